// Newmark (beta = 1/4, gamma = 1/2) on 1-DOF and 2-DOF undamped oscillators: the phase advance per step is
// exactly 2 arctan(omega dt / 2), i.e. period elongation omega dt / (2 arctan(omega dt / 2)) (Hughes 1987,
// sec. 9.1.4), and the energy is conserved to round-off over 1e5 steps.
#include "fem_test_util.hpp"

#include "fem/newmark.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cstdio>

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

namespace {
// Hardening spring f(u) = u + c u^3: Newton needs more iterations the larger the step.
class CubicSpring final : public SecondOrderSystem {
public:
  explicit CubicSpring(double c) : c_(c) { K_.n = 1, K_.colptr = {0, 1}, K_.rowind = {0}, K_.val = {1.0}; }
  const SymCsc& pattern() const override { return K_; }
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override {
    f[0] = u[0] + c_ * u[0] * u[0] * u[0];
    if (K) *K = {1.0 + 3 * c_ * u[0] * u[0]};
    if (energy) *energy = 0.5 * u[0] * u[0] + 0.25 * c_ * u[0] * u[0] * u[0] * u[0];
    return true;
  }

private:
  SymCsc K_;
  double c_;
};

struct CubicRun {
  CubicSpring sys{50.0};
  std::unique_ptr<LinearSolver> solver = makeSkylineSolver();
  Newmark nm;
  NewmarkState s;
  explicit CubicRun(NewmarkParams p) {
    SymCsc K = sys.pattern();
    EXPECT_EQ(solver->analyze(PETSC_COMM_SELF, K, {0}), 0);
    EXPECT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0}, p, [](double, double* f) { f[0] = 0; }),
              0);
    s.u = {0.0}, s.v = {3.0};
    EXPECT_EQ(nm.initialize(&s), 0);
  }
};
} // namespace

// A step whose Newton iteration does not converge within newton_max_it is rejected and redone as two halves
// (bitwise the same as stepping with dt/2 directly); with no halvings left it is a clear error, never accepted.
TEST(FemNewmark, NonConvergedNewtonIsRejectedAndDtHalved) {
  NewmarkParams p;
  p.newton_max_it = 3;
  p.newton_rtol = 1e-12;
  p.newton_atol = 0;
  // From u = 0, v = 3 Newton needs 4 iterations at dt = 0.2 (rejected with newton_max_it = 3) and <= 3 at
  // dt = 0.1: exactly one rejection, then two accepted halves.
  const double dt = 0.2;
  CubicRun big(p);
  StepTimings tm;
  ASSERT_EQ(big.nm.step(&big.s, dt, &tm), 0);
  EXPECT_EQ(tm.rejected, 1);
  EXPECT_TRUE(tm.converged);
  // Reference: the two halves taken directly.
  CubicRun ref(p);
  StepTimings tr;
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(ref.nm.step(&ref.s, dt / 2, &tr), 0);
    EXPECT_EQ(tr.rejected, 0);
  }
  EXPECT_EQ(big.s.u[0], ref.s.u[0]);
  EXPECT_EQ(big.s.v[0], ref.s.v[0]);
  EXPECT_NEAR(big.s.t, dt, 1e-15);
  // No halvings allowed: the non-converged step is an error and the state is unchanged.
  p.max_halvings = 0;
  CubicRun none(p);
  femtest::QuietErrors quiet;
  EXPECT_NE(none.nm.step(&none.s, dt, &tm), 0);
  EXPECT_EQ(none.s.t, 0.0);
  EXPECT_EQ(none.s.u[0], 0.0);
}

// Generalized-alpha (Chung & Hulbert 1993): second order on the undamped 1-DOF oscillator for several
// rho_inf, and the spectral radius of the one-step amplification matrix at omega dt = 1e6 equals rho_inf
// (the analytic limit; the O((omega dt)^-2) remainder is ~1e-12).
TEST(FemGeneralizedAlpha, SecondOrderOnOscillator) {
  const double w = 2.0, T = 5.0;
  for (double rho : {0.0, 0.5, 0.8, 1.0}) {
    double err[3];
    for (int r = 0; r < 3; ++r) {
      const int nsteps = 200 << r;
      const double dt = T / nsteps;
      SymCsc K;
      K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {w * w};
      LinearSecondOrderSystem sys(K);
      auto solver = makeSkylineSolver();
      ASSERT_EQ(solver->analyze(PETSC_COMM_SELF, K, {0}), 0);
      Newmark nm;
      ASSERT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0}, generalizedAlpha(NewmarkParams(), rho),
                         [](double, double* f) { f[0] = 0; }),
                0);
      NewmarkState s;
      s.u = {1.0}, s.v = {0.0};
      ASSERT_EQ(nm.initialize(&s), 0);
      StepTimings tm;
      for (int k = 0; k < nsteps; ++k) ASSERT_EQ(nm.step(&s, dt, &tm), 0);
      err[r] = std::hypot(s.u[0] - std::cos(w * T), (s.v[0] + w * std::sin(w * T)) / w);
    }
    const double p1 = std::log2(err[0] / err[1]), p2 = std::log2(err[1] / err[2]);
    EXPECT_GE(p1, 1.95) << "rho_inf " << rho << " errors " << err[0] << " " << err[1];
    EXPECT_GE(p2, 1.95) << "rho_inf " << rho << " errors " << err[1] << " " << err[2];
    std::printf("generalized-alpha rho_inf %.1f: errors %.3e %.3e %.3e, observed order %.4f %.4f\n", rho,
                err[0], err[1], err[2], p1, p2);
  }
}

namespace {
// Amplification matrix of generalized-alpha for u'' + w^2 u = 0 on the scaled state (u, dt v, dt^2 a), written
// out from the scheme's three equations (Chung & Hulbert 1993, eqs. 3-5) independently of the Newmark class.
Eigen::Matrix3d analyticAmplification(const NewmarkParams& p, double W) {
  const double am = p.alpha_m, af = p.alpha_f, b = p.beta, g = p.gamma;
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    const double x0 = j == 0, x1 = j == 1, x2 = j == 2;
    const double a1 = -(am * x2 + W * W * x0 + W * W * (1 - af) * (x1 + (0.5 - b) * x2)) /
                      ((1 - am) + W * W * (1 - af) * b);
    A(0, j) = x0 + x1 + (0.5 - b) * x2 + b * a1;
    A(1, j) = x1 + (1 - g) * x2 + g * a1;
    A(2, j) = a1;
  }
  return A;
}
} // namespace

// The one-step amplification matrix measured from Newmark::step (three unit states) equals the analytic one,
// and its spectral radius (the numerical dissipation per step) matches the analytic spectral radius to 1e-6 at
// large omega dt; the analytic radius tends to rho_inf (checked at omega dt = 1e6, to 5e-4: the approach is
// O((omega dt)^-1), slower for rho_inf = 0 where the roots coalesce at 0).
TEST(FemGeneralizedAlpha, SpectralRadiusAtLargeOmegaDt) {
  for (double rho : {0.0, 0.3, 0.5, 0.8, 1.0}) {
    const NewmarkParams p = generalizedAlpha(NewmarkParams(), rho);
    for (double W : {10.0, 100.0, 1000.0}) {
      const double dt = 1.0, w = W / dt;
      SymCsc K;
      K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {w * w};
      LinearSecondOrderSystem sys(K);
      auto solver = makeSkylineSolver();
      ASSERT_EQ(solver->analyze(PETSC_COMM_SELF, K, {0}), 0);
      Newmark nm;
      ASSERT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0}, p, [](double, double* f) { f[0] = 0; }),
                0);
      Eigen::Matrix3d A;
      for (int j = 0; j < 3; ++j) {
        NewmarkState s;
        s.u = {0.0}, s.v = {0.0}, s.a = {0.0};
        ASSERT_EQ(nm.initialize(&s), 0);
        s.u[0] = j == 0 ? 1.0 : 0.0;
        s.v[0] = j == 1 ? 1.0 / dt : 0.0;
        s.a[0] = j == 2 ? 1.0 / (dt * dt) : 0.0;
        StepTimings tm;
        ASSERT_EQ(nm.step(&s, dt, &tm), 0);
        A(0, j) = s.u[0], A(1, j) = dt * s.v[0], A(2, j) = dt * dt * s.a[0];
      }
      const Eigen::Matrix3d Aa = analyticAmplification(p, W);
      EXPECT_LT((A - Aa).cwiseAbs().maxCoeff(), 1e-12) << "rho_inf " << rho << " omega dt " << W;
      const double radius = A.eigenvalues().cwiseAbs().maxCoeff();
      const double analytic = Aa.eigenvalues().cwiseAbs().maxCoeff();
      EXPECT_NEAR(radius, analytic, 1e-6) << "rho_inf " << rho << " omega dt " << W;
      std::printf("generalized-alpha rho_inf %.1f, omega dt %g: spectral radius %.9f (analytic %.9f)\n", rho,
                  W, radius, analytic);
    }
    const double limit = analyticAmplification(p, 1e6).eigenvalues().cwiseAbs().maxCoeff();
    EXPECT_NEAR(limit, rho, 5e-4) << "rho_inf " << rho;
    std::printf("generalized-alpha rho_inf %.1f: analytic spectral radius at omega dt = 1e6: %.6f\n", rho,
                limit);
  }
}
