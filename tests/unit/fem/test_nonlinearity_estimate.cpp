// Geometric-nonlinearity estimate (fem/nonlinearity_estimate.hpp) against closed forms, and the law switch
// policy's hysteresis (fem/law_switch.hpp).
//   rigid rotation by theta about z, u = (R - I) X: H = R - I, ||H||_F^2 = 4 (1 - cos theta),
//     1/2 H^T H = (1 - cos theta) on the x-y block, so eta = sqrt((1 - cos theta) / 2) = sin(theta / 2);
//   uniaxial stretch u = (e X, 0, 0): H = e e_x e_x, eta = e / 2.
// Both fields are linear in X, so P1 and P2 interpolate them exactly and eta is exact on any mesh.
#include "fem/law_switch.hpp"
#include "fem/nonlinearity_estimate.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::fem;

namespace {
const Lame kLame{576.9230769230769, 384.6153846153846}; // E = 1000, nu = 0.3

// eta of the displacement u(X) = A X on the 2x2x2 cube (P1 or P2), nothing fixed.
double etaOf(const Eigen::Matrix3d& A, int order) {
  const TetMesh m = femtest::cube(2, order);
  auto mat = makeLinearMaterial(kLame);
  ElasticModel model;
  EXPECT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
  std::vector<double> u(3 * m.numNodes());
  for (int v = 0; v < m.numNodes(); ++v) {
    const Eigen::Vector3d X(m.nodes[v][0], m.nodes[v][1], m.nodes[v][2]);
    const Eigen::Vector3d d = A * X;
    for (int i = 0; i < 3; ++i) u[3 * v + i] = d[i];
  }
  NonlinearityEstimate est;
  EXPECT_EQ(estimateNonlinearity(PETSC_COMM_SELF, model, u.data(), &est), 0);
  return est.ratio();
}
} // namespace

TEST(FemNonlinearityEstimate, RigidRotationGivesSinHalfTheta) {
  for (int order : {1, 2})
    for (double theta : {1e-3, 0.1, 0.5, 1.5}) {
      const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      EXPECT_NEAR(etaOf(R - Eigen::Matrix3d::Identity(), order), std::sin(theta / 2), 1e-12 * theta)
          << "P" << order << " theta " << theta;
    }
}

TEST(FemNonlinearityEstimate, StretchGivesHalfStrainAndZeroAtRest) {
  for (int order : {1, 2}) {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    A(0, 0) = 0.02;
    EXPECT_NEAR(etaOf(A, order), 0.01, 1e-14);
    EXPECT_EQ(etaOf(Eigen::Matrix3d::Zero(), order), 0.0);
  }
  EXPECT_NEAR(linearLawError(0.1), 0.07 * 0.1 + 1.5 * 0.01, 1e-15); // the calibrated model
}

TEST(FemLawSwitch, HysteresisBand) {
  LawSwitchPolicy p;
  p.target = 1e-2, p.up = 0.3, p.down = 0.1; // up at 3e-3, down below 1e-3
  EXPECT_EQ(p.next(Fidelity::cheap, 2.9e-3), Fidelity::cheap);
  EXPECT_FALSE(p.cheapRejected(3e-3));
  EXPECT_TRUE(p.cheapRejected(3.1e-3));
  EXPECT_EQ(p.next(Fidelity::cheap, 3.1e-3), Fidelity::accurate);
  EXPECT_EQ(p.next(Fidelity::accurate, 2e-3), Fidelity::accurate); // inside the band: stays
  EXPECT_EQ(p.next(Fidelity::accurate, 0.9e-3), Fidelity::cheap);
  femtest::QuietErrors quiet;
  EXPECT_EQ(checkLawSwitchPolicy(PETSC_COMM_SELF, p), 0);
  for (double bad : {0.0, -1.0, std::nan(""), static_cast<double>(INFINITY)}) {
    LawSwitchPolicy q = p;
    q.target = bad;
    EXPECT_NE(checkLawSwitchPolicy(PETSC_COMM_SELF, q), 0) << bad;
  }
  LawSwitchPolicy q = p;
  q.down = 0.5;
  EXPECT_NE(checkLawSwitchPolicy(PETSC_COMM_SELF, q), 0);
}
