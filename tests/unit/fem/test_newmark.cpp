// Newmark (beta = 1/4, gamma = 1/2) on 1-DOF and 2-DOF undamped oscillators: the phase advance per step is
// exactly 2 arctan(omega dt / 2), i.e. period elongation omega dt / (2 arctan(omega dt / 2)) (Hughes 1987,
// sec. 9.1.4), and the energy is conserved to round-off over 1e5 steps.
#include "fem_test_util.hpp"

#include "fem/newmark.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

using namespace suite::fem;

namespace {
SymCsc dense2(double a00, double a01, double a11) {
  SymCsc A;
  A.n = 2;
  A.colptr = {0, 1, 3};
  A.rowind = {0, 0, 1};
  A.val = {a00, a01, a11};
  return A;
}

struct Oscillator {
  LinearSecondOrderSystem sys;
  std::unique_ptr<LinearSolver> solver = makeSkylineSolver();
  Newmark nm;
  NewmarkState s;
  Oscillator(const SymCsc& K, const std::vector<double>& M, std::vector<double> u0) : sys(K) {
    EXPECT_EQ(solver->analyze(PETSC_COMM_SELF, K, K.n == 1 ? std::vector<int>{0} : std::vector<int>{0, 1}),
              0);
    EXPECT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), M, NewmarkParams(),
                       [](double, double* f) { f[0] = 0; }),
              0);
    s.u = std::move(u0);
    s.v.assign(s.u.size(), 0.0);
    EXPECT_EQ(nm.initialize(&s), 0);
  }
};

// Unwrapped phase of (omega q, -qdot) accumulated over steps.
struct Phase {
  double total = 0, last = 0;
  void update(double x, double y) {
    const double a = std::atan2(y, x);
    double d = a - last;
    while (d > M_PI) d -= 2 * M_PI;
    while (d <= -M_PI) d += 2 * M_PI;
    total += d;
    last = a;
  }
};
} // namespace

TEST(FemNewmark, OneDofPeriodElongation) {
  for (double wdt : {0.1, 0.5, 1.0, 2.0}) {
    const double w = 3.0, dt = wdt / w;
    SymCsc K;
    K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {w * w};
    Oscillator o(K, {1.0}, {1.0});
    Phase ph;
    const int nsteps = 1000;
    StepTimings tm;
    for (int k = 0; k < nsteps; ++k) {
      ASSERT_EQ(o.nm.step(&o.s, dt, &tm), 0);
      ph.update(w * o.s.u[0], -o.s.v[0]);
    }
    const double theta = ph.total / nsteps;
    const double elong = wdt / theta, exact = wdt / (2 * std::atan(wdt / 2));
    EXPECT_NEAR(elong, exact, 1e-10 * exact) << "omega dt = " << wdt;
  }
}

TEST(FemNewmark, OneDofEnergyDrift) {
  const double w = 2.0, dt = 0.05;
  SymCsc K;
  K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {w * w};
  Oscillator o(K, {1.0}, {1.0});
  const double e0 = 0.5 * w * w;
  StepTimings tm;
  double drift = 0;
  for (int k = 0; k < 100000; ++k) {
    ASSERT_EQ(o.nm.step(&o.s, dt, &tm), 0);
    const double e = 0.5 * o.s.v[0] * o.s.v[0] + 0.5 * w * w * o.s.u[0] * o.s.u[0];
    drift = std::max(drift, std::abs(e - e0) / e0);
  }
  EXPECT_LT(drift, 1e-12);
}

TEST(FemNewmark, TwoDofModesAndEnergy) {
  const SymCsc K = dense2(3.0, -1.0, 2.0);
  const std::vector<double> M = {1.0, 0.0, 2.0}; // diag(1, 2) on the same pattern
  Eigen::Matrix2d Kd, Md;
  Kd << 3, -1, -1, 2;
  Md << 1, 0, 0, 2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(Kd, Md);
  const Eigen::Matrix2d Phi = eig.eigenvectors(); // M-orthonormal
  const Eigen::Vector2d w = eig.eigenvalues().cwiseSqrt();
  Oscillator o(K, M, {1.0, 0.5});
  const double dt = 0.2;
  Phase ph[2];
  const int nsteps = 2000;
  StepTimings tm;
  const auto energy = [&]() {
    const Eigen::Vector2d u(o.s.u[0], o.s.u[1]), v(o.s.v[0], o.s.v[1]);
    return 0.5 * v.dot(Md * v) + 0.5 * u.dot(Kd * u);
  };
  const double e0 = energy();
  double drift = 0;
  for (int k = 0; k < nsteps; ++k) {
    ASSERT_EQ(o.nm.step(&o.s, dt, &tm), 0);
    const Eigen::Vector2d q = Phi.transpose() * Md * Eigen::Vector2d(o.s.u[0], o.s.u[1]);
    const Eigen::Vector2d qd = Phi.transpose() * Md * Eigen::Vector2d(o.s.v[0], o.s.v[1]);
    for (int i = 0; i < 2; ++i) ph[i].update(w[i] * q[i], -qd[i]);
    drift = std::max(drift, std::abs(energy() - e0) / e0);
  }
  for (int i = 0; i < 2; ++i) {
    const double theta = std::abs(ph[i].total) / nsteps, wdt = w[i] * dt;
    EXPECT_NEAR(wdt / theta, wdt / (2 * std::atan(wdt / 2)), 1e-10) << "mode " << i;
  }
  EXPECT_LT(drift, 1e-12);
}

TEST(FemNewmark, RejectsNonPositiveDt) {
  SymCsc K;
  K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {1.0};
  Oscillator o(K, {1.0}, {1.0});
  femtest::QuietErrors quiet;
  StepTimings tm;
  EXPECT_NE(o.nm.step(&o.s, 0.0, &tm), 0);
  EXPECT_NE(o.nm.step(&o.s, -1e-3, &tm), 0);
}

namespace {
// Unit spring whose states with u > limit are inadmissible (stands in for an inverted element, det F <= 0).
class GuardedSpring final : public SecondOrderSystem {
public:
  explicit GuardedSpring(double limit) : limit_(limit) {
    K_.n = 1, K_.colptr = {0, 1}, K_.rowind = {0}, K_.val = {1.0};
  }
  const SymCsc& pattern() const override { return K_; }
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override {
    f[0] = u[0];
    if (K) *K = {1.0};
    if (energy) *energy = 0.5 * u[0] * u[0];
    return u[0] <= limit_;
  }

private:
  SymCsc K_;
  double limit_;
};
} // namespace

// A step that makes the state inadmissible is rejected and redone with halved dt (substeps), never accepted.
TEST(FemNewmark, InadmissibleStepIsRejectedAndDtHalved) {
  GuardedSpring sys(1.2);
  auto solver = makeSkylineSolver();
  SymCsc K = sys.pattern();
  ASSERT_EQ(solver->analyze(PETSC_COMM_SELF, K, {0}), 0);
  Newmark nm;
  NewmarkParams p;
  ASSERT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0}, p, [](double, double* f) { f[0] = 0; }), 0);
  NewmarkState s;
  s.u = {0.0}, s.v = {1.0};
  ASSERT_EQ(nm.initialize(&s), 0);
  StepTimings tm;
  // u0 = 0, v0 = 1, dt = 2: the Newton start (predictor) u = dt v0 = 2 > 1.2 is inadmissible -> rejected; the
  // two halves start at 1.0 and end below 1 (the trapezoidal rule conserves the energy 1/2).
  ASSERT_EQ(nm.step(&s, 2.0, &tm), 0);
  EXPECT_GE(tm.rejected, 1);
  EXPECT_NEAR(s.t, 2.0, 1e-14);
  EXPECT_LE(s.u[0], 1.0);
  // Admissible only for u <= 0 while moving up: every substep fails; after max_halvings a clear error.
  GuardedSpring tight(0.0);
  Newmark nm2;
  p.max_halvings = 3;
  ASSERT_EQ(nm2.setup(PETSC_COMM_SELF, &tight, solver.get(), {1.0}, p, [](double, double* f) { f[0] = 0; }),
            0);
  NewmarkState s2;
  s2.u = {0.0}, s2.v = {1.0};
  ASSERT_EQ(nm2.initialize(&s2), 0);
  femtest::QuietErrors quiet;
  EXPECT_NE(nm2.step(&s2, 0.1, &tm), 0);
  EXPECT_EQ(s2.t, 0.0); // nothing accepted
}
