// Material laws: rotation invariance of StVK and corotational, the tangent against central differences of P
// (error O(h^2)), and the single-tet uniaxial-strain StVK compression with its singular tangent at s =
// 1/sqrt(3).
#include "fem_test_util.hpp"

#include "fem/linear_solver.hpp"

#include <gtest/gtest.h>

using namespace suite::fem;

namespace {
Mat3 rotation(double deg, Eigen::Vector3d axis) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, axis.normalized()).toRotationMatrix();
}
const Lame kLame{1.3, 0.7};

// Max |A h - (P(F+hE) - P(F-hE))/2| over unit directions E, relative.
double tangentError(const Material& m, const Mat3& F, double h) {
  Tangent A;
  Mat3 P;
  double W;
  m.evaluate(F, &W, &P, &A);
  double err = 0;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      Mat3 dF = Mat3::Zero();
      dF(k, L) = 1;
      Mat3 Pp, Pm;
      m.evaluate(F + h * dF, &W, &Pp, nullptr);
      m.evaluate(F - h * dF, &W, &Pm, nullptr);
      const Mat3 fd = (Pp - Pm) / (2 * h);
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) err = std::max(err, std::abs(fd(i, J) - A(3 * i + J, 3 * k + L)));
    }
  return err;
}
} // namespace

TEST(FemMaterial, RotationGivesZeroStVKStressAndEnergy) {
  for (const char* name : {"stvk", "corotational"}) {
    std::unique_ptr<Material> m;
    ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &m), 0);
    const Mat3 R = rotation(73.0, {1, 2, 3});
    Mat3 P;
    double W;
    m->evaluate(R, &W, &P, nullptr);
    EXPECT_LT(P.norm(), 1e-14) << name;
    EXPECT_LT(std::abs(W), 1e-15) << name;
  }
}

TEST(FemMaterial, TangentMatchesCentralDifferencesSecondOrder) {
  const Mat3 F = rotation(30.0, {0, 0, 1}) * Eigen::Vector3d(1.2, 0.9, 1.1).asDiagonal();
  for (const char* name : {"linear", "stvk"}) {
    std::unique_ptr<Material> m;
    ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &m), 0);
    const double e1 = tangentError(*m, F, 1e-3), e2 = tangentError(*m, F, 5e-4);
    if (std::string(name) == "linear") {
      EXPECT_LT(e1, 1e-10); // exact (P linear in F)
    } else {
      // StVK's P is cubic in F: the central difference error is exactly h^2 * (third derivative)/6, ratio 4.
      EXPECT_NEAR(e1 / e2, 4.0, 0.01) << "errors " << e1 << " " << e2;
      EXPECT_LT(e1, 1e-5);
    }
  }
}

TEST(FemMaterial, EnergyDerivativeIsStress) {
  const Mat3 F = rotation(30.0, {0, 0, 1}) * Eigen::Vector3d(1.2, 0.9, 1.1).asDiagonal();
  for (const char* name : {"linear", "stvk", "corotational"}) {
    std::unique_ptr<Material> m;
    ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &m), 0);
    Mat3 P, dummy;
    double W, Wp, Wm;
    m->evaluate(F, &W, &P, nullptr);
    const double h = 1e-5;
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) {
        Mat3 dF = Mat3::Zero();
        dF(i, J) = h;
        m->evaluate(F + dF, &Wp, &dummy, nullptr);
        m->evaluate(F - dF, &Wm, &dummy, nullptr);
        EXPECT_NEAR((Wp - Wm) / (2 * h), P(i, J), 1e-8) << name << " " << i << J;
      }
  }
}

TEST(FemMaterial, BadParametersRejected) {
  femtest::QuietErrors quiet;
  Lame l;
  EXPECT_NE(lameFromYoung(PETSC_COMM_SELF, 1000, 0.5, &l), 0);
  EXPECT_NE(lameFromYoung(PETSC_COMM_SELF, 1000, 0.7, &l), 0);
  EXPECT_NE(lameFromYoung(PETSC_COMM_SELF, 0, 0.3, &l), 0);
  EXPECT_NE(lameFromYoung(PETSC_COMM_SELF, -5, 0.3, &l), 0);
  EXPECT_EQ(lameFromYoung(PETSC_COMM_SELF, 1000, 0.3, &l), 0);
  std::unique_ptr<Material> m;
  EXPECT_NE(createMaterial(PETSC_COMM_SELF, "neo-hookean-typo", l, &m), 0);
}

// Single unit tet, x -> s x for all nodes (uniaxial strain F = diag(s,1,1)): P_11 = (lambda+2mu)(s^3 - s)/2
// and the stiffness of the one free DOF (x of node 1) is V (lambda+2mu)(3s^2-1)/2, zero at s = 1/sqrt(3).
TEST(FemMaterial, UniaxialStrainSingleTetStVK) {
  TetMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.elems = {0, 1, 2, 3};
  auto mat = makeStVenantKirchhoff(kLame);
  std::vector<char> fixed(12, 1);
  fixed[3] = 0; // x of node 1
  ElasticModel model;
  ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, fixed), 0);
  const double c = kLame.lambda + 2 * kLame.mu;
  for (double s : {0.3, 0.5, 1.0 / std::sqrt(3.0), 0.8, 1.0, 1.2, 1.5}) {
    std::vector<double> u(12, 0.0);
    u[3] = s - 1.0; // node 1 at x = s; nodes 0,2,3 have x = 0
    double f;
    std::vector<double> K(model.pattern().val.size());
    const auto res = model.assemble(u.data(), &f, &K);
    ASSERT_LT(res.bad_elem, 0);
    const double P11 = 6.0 * f; // f = V P_11 dN_1/dX_1, V = 1/6
    EXPECT_NEAR(P11, c * (s * s * s - s) / 2, 1e-13 * c) << "s = " << s;
    EXPECT_NEAR(K[0], c * (3 * s * s - 1) / 12, 1e-13 * c) << "s = " << s;
  }
  // At s = 1/sqrt(3) the tangent is singular: a Cholesky factorisation must report it.
  std::vector<double> u(12, 0.0);
  u[3] = 1.0 / std::sqrt(3.0) - 1.0;
  double f;
  SymCsc K = model.pattern();
  model.assemble(u.data(), &f, &K.val);
  EXPECT_LT(std::abs(K.val[0]), 1e-15);
  auto solver = makeSkylineSolver();
  ASSERT_EQ(solver->analyze(PETSC_COMM_SELF, K, {0}), 0);
  K.val[0] = -1e-3 * c; // just beyond the limit point: not positive definite
  bool ok = true;
  ASSERT_EQ(solver->factor(K, &ok), 0);
  EXPECT_FALSE(ok);
}

// The closed-form element tangents (linear, StVK) equal the generic sum over the 9x9 material tangent.
TEST(FemMaterial, ClosedFormElementTangentMatchesGeneric) {
  const Mat3 F = rotation(30.0, {0, 0, 1}) * Eigen::Vector3d(1.2, 0.9, 1.1).asDiagonal();
  double g[30];
  for (int k = 0; k < 30; ++k) g[k] = std::sin(1.3 * k + 0.2);
  for (const char* name : {"linear", "stvk"}) {
    std::unique_ptr<Material> m;
    ASSERT_EQ(createMaterial(PETSC_COMM_SELF, name, kLame, &m), 0);
    for (int nen : {4, 10}) {
      std::vector<double> k1(900, 0.0), k2(900, 0.0);
      m->addElementTangent(F, g, nen, 0.7, k1.data());
      m->Material::addElementTangent(F, g, nen, 0.7, k2.data());
      double d = 0, mx = 0;
      for (int p = 0; p < 3 * nen; ++p)
        for (int q = p; q < 3 * nen; ++q)
          d = std::max(d, std::abs(k1[p * 3 * nen + q] - k2[p * 3 * nen + q])),
          mx = std::max(mx, std::abs(k2[p * 3 * nen + q]));
      EXPECT_LT(d, 1e-13 * mx) << name << " nen " << nen;
    }
  }
}

// Corotational: the polar rotation of the scaled Newton iteration against the SVD's (P from R = U V^T, eps =
// V S V^T - I computed here), over stretches from 1e-7 to 2 and repeated singular values; the closed-form
// element tangent against sum_JL g_aJ A_iJkL g_bL of the 9x9 tangent A = (R x I) C (R x I)^T.
TEST(FemMaterial, CorotationalPolarIterationMatchesSvd) {
  std::unique_ptr<Material> m;
  ASSERT_EQ(createMaterial(PETSC_COMM_SELF, "corotational", kLame, &m), 0);
  const std::vector<Eigen::Vector3d> stretches = {{1 + 1e-7, 1 - 2e-7, 1}, {1.01, 0.99, 1.02},
                                                  {1.2, 0.9, 1.1},         {2.0, 0.5, 1.0},
                                                  {1.1, 1.1, 1.1},         {0.3, 0.3, 1.5}};
  double worst_p = 0, worst_k = 0;
  for (const auto& s : stretches)
    for (double deg : {0.0, 17.0, 90.0, 170.0}) {
      const Mat3 Q = rotation(deg, {1, 2, 3}), V = rotation(33.0, {-1, 0.5, 2});
      const Mat3 F =
          Q * V * s.asDiagonal() * V.transpose() + 1e-3 * rotation(5.0, {0, 1, 0}) - 1e-3 * Mat3::Identity();
      Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Mat3 R = svd.matrixU() * svd.matrixV().transpose();
      ASSERT_GT(R.determinant(), 0);
      const Mat3 eps =
          svd.matrixV() * svd.singularValues().asDiagonal() * svd.matrixV().transpose() - Mat3::Identity();
      const Mat3 Pref = R * (kLame.lambda * eps.trace() * Mat3::Identity() + 2 * kLame.mu * eps);
      Mat3 P;
      double W;
      Tangent A;
      m->evaluate(F, &W, &P, &A);
      worst_p = std::max(worst_p, (P - Pref).norm() / std::max(Pref.norm(), kLame.lambda + 2 * kLame.mu));
      const double g[12] = {-1, -1, -1, 1, 0, 0, 0, 1, 0, 0.2, 0.1, 1.3};
      double ke[144] = {0}, kref[144] = {0};
      m->addElementTangent(F, g, 4, 0.7, ke);
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i)
          for (int b = 0; b < 4; ++b)
            for (int k = 0; k < 3; ++k) {
              const int p = 3 * a + i, q = 3 * b + k;
              if (q < p) continue;
              for (int J = 0; J < 3; ++J)
                for (int L = 0; L < 3; ++L)
                  kref[p * 12 + q] += 0.7 * g[3 * a + J] * A(3 * i + J, 3 * k + L) * g[3 * b + L];
            }
      double kn = 0, kd = 0;
      for (int e = 0; e < 144; ++e)
        kn = std::max(kn, std::abs(kref[e])), kd = std::max(kd, std::abs(ke[e] - kref[e]));
      worst_k = std::max(worst_k, kd / kn);
    }
  std::printf("corotational: max relative |P - P_svd| %.2e, |K - K_generic| %.2e\n", worst_p, worst_k);
  EXPECT_LT(worst_p, 1e-13);
  EXPECT_LT(worst_k, 1e-14);
}
