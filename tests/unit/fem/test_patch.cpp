// Patch tests (Irons & Razzaque 1972; Zienkiewicz & Taylor vol. 1, ch. 9): a linear displacement field is
// reproduced to round-off by the static solution with the field prescribed on the boundary, and under a
// finite homogeneous deformation F = R(30 deg) diag(1.2, 0.9, 1.1) the StVK interior nodal forces vanish; a
// rigid rotation gives zero internal force and energy; the assembled tangent matches central differences to
// O(h^2).
#include "fem_test_util.hpp"

#include "fem/linear_solver.hpp"
#include "fem/newmark.hpp"
#include "fem/ordering.hpp"

#include <gtest/gtest.h>

using namespace suite::fem;

namespace {
const Lame kLame{576.9230769230769, 384.6153846153846}; // E = 1000, nu = 0.3

Mat3 finiteF() {
  return Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
         Eigen::Vector3d(1.2, 0.9, 1.1).asDiagonal();
}

// Displacement u = (F - I) X + c at every node.
std::vector<double> homogeneousField(const TetMesh& m, const Mat3& F, double shift = 1.0) {
  std::vector<double> u(3 * m.numNodes());
  const Eigen::Vector3d c = shift * Eigen::Vector3d(0.1, -0.2, 0.05);
  for (int v = 0; v < m.numNodes(); ++v) {
    const Eigen::Vector3d X(m.nodes[v][0], m.nodes[v][1], m.nodes[v][2]);
    const Eigen::Vector3d d = (F - Mat3::Identity()) * X + c;
    for (int i = 0; i < 3; ++i) u[3 * v + i] = d[i];
  }
  return u;
}

// Interior forces for the homogeneous field: all DOFs free, look at interior nodes only.
double maxInteriorForce(const TetMesh& m, const Material& mat, const Mat3& F, double* energy) {
  ElasticModel model;
  EXPECT_EQ(model.setup(PETSC_COMM_SELF, m, mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
  const auto u = homogeneousField(m, F);
  std::vector<double> f(model.numFree());
  const auto res = model.assemble(u.data(), f.data(), nullptr);
  EXPECT_LT(res.bad_elem, 0);
  *energy = res.energy;
  const auto bnd = femtest::boundaryNodes(m);
  double mx = 0;
  for (int v = 0; v < m.numNodes(); ++v)
    if (!bnd[v])
      for (int i = 0; i < 3; ++i) mx = std::max(mx, std::abs(f[3 * v + i]));
  return mx;
}
} // namespace

TEST(FemPatch, HomogeneousDeformationInteriorForcesVanish) {
  for (int order : {1, 2}) {
    const TetMesh m = femtest::cube(3, order);
    for (const char* name : {"linear", "stvk", "corotational"}) {
      std::unique_ptr<Material> mat;
      ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &mat), 0);
      double e;
      EXPECT_LT(maxInteriorForce(m, *mat, finiteF(), &e), 1e-12 * kLame.mu) << name << " P" << order;
      // Energy: W(F) times the unit volume.
      Mat3 P;
      double W;
      mat->evaluate(finiteF(), &W, &P, nullptr);
      EXPECT_NEAR(e, W, 1e-12 * W) << name << " P" << order;
    }
  }
}

TEST(FemPatch, RotationGivesZeroStVKForceAndEnergy) {
  const TetMesh m = femtest::cube(2, 2);
  auto mat = makeStVenantKirchhoff(kLame);
  ElasticModel model;
  ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
  const Mat3 R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const auto u = homogeneousField(m, R);
  std::vector<double> f(model.numFree());
  const auto res = model.assemble(u.data(), f.data(), nullptr);
  double mx = 0;
  for (double x : f) mx = std::max(mx, std::abs(x));
  EXPECT_LT(mx, 1e-12 * kLame.mu);
  EXPECT_LT(std::abs(res.energy), 1e-13 * kLame.mu);
}

// Boundary nodes prescribed to the linear field, interior solved: reproduced to 1e-12 (linear: one solve;
// StVK: Newton with load stepping on the prescribed displacement).
TEST(FemPatch, LinearFieldReproducedByStaticSolve) {
  for (int order : {1, 2}) {
    const TetMesh m = femtest::cube(3, order);
    for (const char* name : {"linear", "stvk"}) {
      std::unique_ptr<Material> mat;
      ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &mat), 0);
      // Linear: a small field (the zero initial guess inside must not invert elements next to the boundary).
      const bool lin = std::string(name) == "linear";
      const Mat3 F = lin ? Mat3(Mat3::Identity() + 0.01 * finiteF()) : finiteF();
      const auto bnd = femtest::boundaryNodes(m);
      std::vector<char> fixed(3 * m.numNodes(), 0);
      for (int v = 0; v < m.numNodes(); ++v)
        for (int i = 0; i < 3; ++i) fixed[3 * v + i] = bnd[v];
      ElasticModel model;
      ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, fixed), 0);
      const auto exact = homogeneousField(m, F, lin ? 0.01 : 1.0);
      // Newton on the free DOFs with the prescribed boundary values in the full vector.
      std::vector<double> ufull(exact.size(), 0.0);
      SymCsc K = model.pattern();
      auto solver = makeCholmodSolver();
      ASSERT_EQ(solver->analyze(PETSC_COMM_SELF, K, orderAmd(graphOfMatrix(K))), 0);
      std::vector<double> f(model.numFree()), du(model.numFree());
      const int nsteps = std::string(name) == "linear" ? 1 : 10;
      for (int step = 1; step <= nsteps; ++step) {
        for (size_t d = 0; d < exact.size(); ++d)
          if (fixed[d]) ufull[d] = exact[d] * step / nsteps;
        double rn = 1;
        for (int it = 0; it < 30 && rn > 1e-13 * kLame.mu; ++it) {
          ASSERT_LT(model.assemble(ufull.data(), f.data(), &K.val).bad_elem, 0)
              << name << " P" << order << " step " << step;
          rn = 0;
          for (double x : f) rn = std::max(rn, std::abs(x));
          bool ok;
          ASSERT_EQ(solver->factor(K, &ok), 0);
          ASSERT_TRUE(ok);
          ASSERT_EQ(solver->solve(f.data(), du.data()), 0);
          for (size_t d = 0; d < exact.size(); ++d)
            if (model.eq()[d] >= 0) ufull[d] -= du[model.eq()[d]];
        }
      }
      double err = 0;
      for (size_t d = 0; d < exact.size(); ++d) err = std::max(err, std::abs(ufull[d] - exact[d]));
      EXPECT_LT(err, 1e-12) << name << " P" << order;
    }
  }
}

TEST(FemPatch, AssembledTangentMatchesFiniteDifferences) {
  for (int order : {1, 2}) {
    const TetMesh m = femtest::cube(2, order);
    auto mat = makeStVenantKirchhoff(kLame);
    ElasticModel model;
    ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
    auto u = homogeneousField(m, finiteF());
    for (size_t d = 0; d < u.size(); ++d) u[d] += 0.02 * std::sin(1.7 * d + 0.3); // non-homogeneous
    const int n = model.numFree();
    SymCsc K = model.pattern();
    std::vector<double> f(n), fp(n), fm(n), Kv(n);
    ASSERT_LT(model.assemble(u.data(), f.data(), &K.val).bad_elem, 0);
    std::vector<double> dir(n);
    for (int i = 0; i < n; ++i) dir[i] = std::cos(0.9 * i + 0.1);
    symMultiply(K, K.val, dir.data(), Kv.data());
    auto fdError = [&](double h) {
      std::vector<double> up(u), um(u);
      for (int i = 0; i < n; ++i) up[i] += h * dir[i], um[i] -= h * dir[i];
      model.assemble(up.data(), fp.data(), nullptr);
      model.assemble(um.data(), fm.data(), nullptr);
      double e = 0;
      for (int i = 0; i < n; ++i) e = std::max(e, std::abs((fp[i] - fm[i]) / (2 * h) - Kv[i]));
      return e;
    };
    const double e1 = fdError(1e-3), e2 = fdError(5e-4);
    EXPECT_NEAR(e1 / e2, 4.0, 0.05) << "P" << order << " errors " << e1 << " " << e2;
  }
}
