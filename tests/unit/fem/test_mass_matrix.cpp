// The consistent and HRZ-lumped mass matrices (fem/assembly) against closed forms, computed here without the
// suite's shape functions or quadrature:
// - the element matrix of a one-element mesh (P1 and P2) against exact integrals of the products of its shape
//   functions written in barycentric coordinates, integral of l1^a l2^b l3^c l4^d over a tetrahedron
//   = 6V a! b! c! d! / (a+b+c+d+3)! (Eisenberg & Malvern 1973); P1 gives rho V (1 + delta_ij) / 20;
// - on a box mesh, the mass's action on rigid motions: translations give the total mass rho V, translations
//   against rotations the first moments, rotations the inertia tensor of the box about the origin (exact for
//   P1 and P2: the consistent mass integrates the product of two linear fields exactly);
// - the lumped mass: P1 equals the row sums of the consistent mass; P2 (HRZ: Hinton, Rock & Zienkiewicz 1976)
//   is the consistent diagonal scaled per element to the element's mass, positive, with the total mass.
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <map>
#include <memory>

using namespace suite::fem;

namespace {
const Lame kLame{576.9230769230769, 384.6153846153846}; // any material: the mass does not depend on it
constexpr double kRho = 2.5;

// The model of mesh m with every DOF free (DOF 3 node + component).
std::unique_ptr<ElasticModel> freeModel(const TetMesh& m, std::unique_ptr<Material>* mat) {
  EXPECT_EQ(createMaterial(PETSC_COMM_SELF, "linear", kLame, mat), 0);
  auto model = std::make_unique<ElasticModel>();
  EXPECT_EQ(model->setup(PETSC_COMM_SELF, m, **mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
  return model;
}

// The full symmetric matrix of values on the model's pattern (upper triangle, CSC).
Eigen::MatrixXd dense(const ElasticModel& model, const std::vector<double>& val) {
  const SymCsc& p = model.pattern();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p.n, p.n);
  for (int j = 0; j < p.n; ++j)
    for (int k = p.colptr[j]; k < p.colptr[j + 1]; ++k) {
      A(p.rowind[k], j) = val[k];
      A(j, p.rowind[k]) = val[k];
    }
  return A;
}

// A polynomial in the barycentric coordinates l0..l3: exponents -> coefficient.
using Poly = std::map<std::array<int, 4>, double>;

Poly times(const Poly& a, const Poly& b) {
  Poly r;
  for (const auto& [ea, ca] : a)
    for (const auto& [eb, cb] : b) {
      std::array<int, 4> e;
      for (int i = 0; i < 4; ++i) e[i] = ea[i] + eb[i];
      r[e] += ca * cb;
    }
  return r;
}

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// Integral over a tetrahedron of volume V (Eisenberg & Malvern 1973).
double integrate(const Poly& p, double V) {
  double s = 0;
  for (const auto& [e, c] : p)
    s += c * 6 * V * factorial(e[0]) * factorial(e[1]) * factorial(e[2]) * factorial(e[3]) /
         factorial(e[0] + e[1] + e[2] + e[3] + 3);
  return s;
}

// The shape function of a node at barycentric position lam (a vertex: one 1; a P2 edge node: two halves).
Poly shapeFunction(const std::array<double, 4>& lam, int order) {
  std::array<int, 4> unit{};
  std::vector<int> half;
  for (int i = 0; i < 4; ++i) {
    if (std::abs(lam[i] - 1) < 1e-12) unit[i] = 1;
    if (std::abs(lam[i] - 0.5) < 1e-12) half.push_back(i);
  }
  Poly p;
  if (half.size() == 2) { // 4 l_a l_b
    std::array<int, 4> e{};
    e[half[0]] = e[half[1]] = 1;
    p[e] = 4;
    return p;
  }
  if (order == 1) { // l_k
    p[unit] = 1;
    return p;
  }
  std::array<int, 4> sq{}; // l_k (2 l_k - 1)
  for (int i = 0; i < 4; ++i) sq[i] = 2 * unit[i];
  p[sq] = 2;
  p[unit] = -1;
  return p;
}

// Barycentric coordinates of x in the tetrahedron v[0..3].
std::array<double, 4> barycentric(const std::array<std::array<double, 3>, 4>& v,
                                  const std::array<double, 3>& x) {
  Eigen::Matrix3d T;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 3; ++i) T(i, c) = v[c + 1][i] - v[0][i];
  const Eigen::Vector3d mu = T.lu().solve(Eigen::Vector3d(x[0] - v[0][0], x[1] - v[0][1], x[2] - v[0][2]));
  return {1 - mu.sum(), mu[0], mu[1], mu[2]};
}

// The element mass (3 nen x 3 nen, DOF 3 a + c) of the one-element mesh m from the exact integrals.
Eigen::MatrixXd exactElementMass(const TetMesh& m) {
  const std::array<std::array<double, 3>, 4> v = {m.nodes[m.elems[0]], m.nodes[m.elems[1]],
                                                  m.nodes[m.elems[2]], m.nodes[m.elems[3]]};
  const double V = tetSignedVolume(v[0], v[1], v[2], v[3]);
  const int n = m.numNodes();
  std::vector<Poly> N(n);
  for (int a = 0; a < n; ++a) N[a] = shapeFunction(barycentric(v, m.nodes[a]), m.order());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < 3; ++c) M(3 * a + c, 3 * b + c) = kRho * integrate(times(N[a], N[b]), V);
  return M;
}

TetMesh oneTet() {
  TetMesh m;
  m.nodes = {{{0.1, -0.2, 0.3}}, {{1.3, 0.1, 0.2}}, {{0.2, 0.9, -0.1}}, {{0.4, 0.3, 1.1}}};
  m.elems = {0, 1, 2, 3};
  m.nodes_per_elem = 4;
  return m;
}

// Rigid motions at every node of m: translation along axis c (c < 3) or rotation about axis c - 3 through the
// origin (omega x x).
Eigen::VectorXd rigid(const TetMesh& m, int c) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(3 * m.numNodes());
  for (int a = 0; a < m.numNodes(); ++a) {
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    if (c < 3)
      u[c] = 1;
    else
      u = Eigen::Vector3d::Unit(c - 3).cross(Eigen::Vector3d(m.nodes[a][0], m.nodes[a][1], m.nodes[a][2]));
    v.segment<3>(3 * a) = u;
  }
  return v;
}

// The 6 x 6 rigid-body mass of the box [0,L]x[0,a]x[0,b] about the origin: rho V I3, the first moments, the
// inertia tensor rho int (|x|^2 I - x x^T) dV.
Eigen::Matrix<double, 6, 6> boxRigidMass(double L, double a, double b) {
  const double m = kRho * L * a * b;
  const Eigen::Vector3d c(L / 2, a / 2, b / 2);              // centre of mass
  const Eigen::Vector3d sq(L * L / 3, a * a / 3, b * b / 3); // <x^2>, <y^2>, <z^2>
  Eigen::Matrix3d second;                                    // <x_i x_j>
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) second(i, j) = i == j ? sq[i] : c[i] * c[j];
  const Eigen::Matrix3d I = m * (second.trace() * Eigen::Matrix3d::Identity() - second);
  Eigen::Matrix<double, 6, 6> R;
  R.topLeftCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  // translation c' against rotation about axis r: rho int (e_r x x)_c' dV = m (e_r x c)_c'
  for (int r = 0; r < 3; ++r) R.block<3, 1>(0, 3 + r) = m * Eigen::Vector3d::Unit(r).cross(c);
  R.bottomLeftCorner<3, 3>() = R.topRightCorner<3, 3>().transpose();
  R.bottomRightCorner<3, 3>() = I;
  return R;
}
} // namespace

TEST(FemMass, ElementMatricesEqualExactIntegralsOfTheShapeFunctions) {
  for (int order : {1, 2}) {
    const TetMesh m = order == 2 ? promoteToP2(oneTet()) : oneTet();
    std::unique_ptr<Material> mat;
    const auto model = freeModel(m, &mat);
    const Eigen::MatrixXd M = dense(*model, model->consistentMass(kRho));
    const Eigen::MatrixXd E = exactElementMass(m);
    const double err = (M - E).cwiseAbs().maxCoeff() / E.cwiseAbs().maxCoeff();
    // measured 7.9e-16 (P1) and 1.6e-15 (P2): round-off of the quadrature sums
    EXPECT_LE(err, 1e-14) << "P" << order << " element mass, max relative difference " << err;
    if (order == 1) { // the textbook form rho V (1 + delta_ij) / 20 per component
      const double V = tetSignedVolume(m.nodes[0], m.nodes[1], m.nodes[2], m.nodes[3]);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          EXPECT_NEAR(M(3 * a, 3 * b), kRho * V * (1 + (a == b)) / 20, 1e-15 * kRho * V);
    }
  }
}

TEST(FemMass, RigidMotionsGiveTotalMassMomentsAndInertiaOfTheBox) {
  BeamSpec s;
  s.length = 2.0;
  s.size = {1.0, 0.5};
  s.cells = {4, 2, 2};
  const Eigen::Matrix<double, 6, 6> exact = boxRigidMass(2.0, 1.0, 0.5);
  for (int order : {1, 2}) {
    const TetMesh m = order == 2 ? promoteToP2(makeBeam(s)) : makeBeam(s);
    std::unique_ptr<Material> mat;
    const auto model = freeModel(m, &mat);
    const Eigen::MatrixXd M = dense(*model, model->consistentMass(kRho));
    Eigen::MatrixXd B(M.rows(), 6);
    for (int c = 0; c < 6; ++c) B.col(c) = rigid(m, c);
    const Eigen::MatrixXd R = B.transpose() * M * B;
    const double err = (R - exact).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
    // measured 3.2e-16 (P1) and 4.3e-16 (P2)
    EXPECT_LE(err, 4e-15) << "P" << order << ": rigid-body mass\n" << R << "\nexact\n" << exact;
  }
}

TEST(FemMass, LumpedIsRowSumsForP1AndScaledDiagonalForP2) {
  BeamSpec s;
  s.length = 2.0;
  s.size = {1.0, 0.5};
  s.cells = {3, 2, 2};
  const double total = kRho * 2.0 * 1.0 * 0.5;
  for (int order : {1, 2}) {
    const TetMesh m = order == 2 ? promoteToP2(makeBeam(s)) : makeBeam(s);
    std::unique_ptr<Material> mat;
    const auto model = freeModel(m, &mat);
    const Eigen::MatrixXd M = dense(*model, model->consistentMass(kRho));
    const Eigen::MatrixXd D = dense(*model, model->lumpedMass(kRho));
    const Eigen::VectorXd d = D.diagonal();
    EXPECT_LE((D - Eigen::MatrixXd(d.asDiagonal())).cwiseAbs().maxCoeff(), 0.0) << "lumped mass is diagonal";
    EXPECT_GT(d.minCoeff(), 0.0) << "P" << order << ": every lumped mass positive";
    for (int c = 0; c < 3; ++c) { // the total mass in each direction
      double sum = 0;
      for (int a = 0; a < m.numNodes(); ++a) sum += d[3 * a + c];
      EXPECT_NEAR(sum, total, 1e-14 * total) << "P" << order << " component " << c;
    }
    if (order == 1) {
      const Eigen::VectorXd rows = M.rowwise().sum();
      // measured 2.2e-17 of the total mass
      EXPECT_LE((d - rows).cwiseAbs().maxCoeff(), 3e-16 * total) << "P1: lumped = row sums";
    } else { // HRZ, element by element: the one-element mesh
      const TetMesh one = promoteToP2(oneTet());
      std::unique_ptr<Material> mat1;
      const auto m1 = freeModel(one, &mat1);
      const Eigen::MatrixXd E = exactElementMass(one);
      const Eigen::VectorXd got = dense(*m1, m1->lumpedMass(kRho)).diagonal();
      const double scale = E.sum() / E.trace(); // element mass (all components) / consistent diagonal
      const Eigen::VectorXd want = scale * E.diagonal();
      // measured 1.1e-15 of the largest entry
      EXPECT_LE((got - want).cwiseAbs().maxCoeff(), 1e-14 * want.maxCoeff()) << "P2: HRZ lumping";
    }
  }
}
