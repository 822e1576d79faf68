// The time-step control of femdyn -dt_adapt (fem/step_control.hpp) on the undamped 1-DOF oscillator
// u'' + omega^2 u = 0, u = cos(omega t): the Zienkiewicz-Xie estimate dt^2 (beta - 1/6) (a_{n+1} - a_n) against
// the exact local error of one Newmark step from the exact state (both dt^3 / 12 a' + O(dt^4)), the low-pass
// factor 1 / (1 + (omega / wc)^2) of Newmark::lowPass, an adaptive run whose global error stays below the
// target (per unit time: the sum of the local estimates is the phase error), and the controller's
// accept / reject / growth logic and option checks.
#include "fem_test_util.hpp"

#include "fem/newmark.hpp"
#include "fem/step_control.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::fem;

namespace {
struct OneDof {
  LinearSecondOrderSystem sys;
  std::unique_ptr<LinearSolver> solver = makeSkylineSolver(), filter = makeSkylineSolver();
  Newmark nm;
  NewmarkState s;
  explicit OneDof(double w) : sys(stiffness(w)) {
    EXPECT_EQ(solver->analyze(PETSC_COMM_SELF, stiffness(w), {0}), 0);
    EXPECT_EQ(filter->analyze(PETSC_COMM_SELF, stiffness(w), {0}), 0);
    EXPECT_EQ(nm.setup(PETSC_COMM_SELF, &sys, solver.get(), {1.0}, NewmarkParams(),
                       [](double, double* f) { f[0] = 0; }),
              0);
    s.u = {1.0}, s.v = {0.0};
    EXPECT_EQ(nm.initialize(&s), 0);
  }
  static SymCsc stiffness(double w) {
    SymCsc K;
    K.n = 1, K.colptr = {0, 1}, K.rowind = {0}, K.val = {w * w};
    return K;
  }
};
} // namespace

// One step from the exact state at omega t = 0.7: estimate / exact local error -> 1 as O(omega dt).
TEST(FemStepControl, EstimateMatchesExactLocalError) {
  const double w = 2.0, t0 = 0.7 / w;
  double last_dev = 1;
  for (double wdt : {0.04, 0.02, 0.01}) {
    const double dt = wdt / w;
    OneDof o(w);
    o.s.t = t0, o.s.u = {std::cos(w * t0)}, o.s.v = {-w * std::sin(w * t0)},
    o.s.a = {-w * w * std::cos(w * t0)};
    const double a0 = o.s.a[0];
    StepTimings tm;
    ASSERT_EQ(o.nm.step(&o.s, dt, &tm), 0);
    double e;
    zienkiewiczXieError(0.25, dt, &a0, o.s.a.data(), 1, &e);
    const double exact = o.s.u[0] - std::cos(w * (t0 + dt));
    const double dev = std::abs(e / exact - 1);
    EXPECT_LT(dev, 1.5 * wdt) << "omega dt " << wdt << ": estimate " << e << ", exact local error " << exact;
    EXPECT_LT(dev, 0.6 * last_dev) << "the estimate converges to the error (first order in dt)";
    last_dev = dev;
  }
}

// The low-pass filter (M + K0 / wc^2)^{-1} M: 1 / (1 + (omega / wc)^2) per mode; refactorised when wc changes.
TEST(FemStepControl, LowPassIsTheModalFactor) {
  const double w = 3.0;
  OneDof o(w);
  for (double ratio : {0.1, 1.0, 10.0, 1.0}) {
    const double e = 1.0, wc = w / ratio;
    double x;
    ASSERT_EQ(o.nm.lowPass(o.filter.get(), wc, &e, &x), 0);
    EXPECT_NEAR(x, 1 / (1 + ratio * ratio), 1e-13) << "omega / wc " << ratio;
    EXPECT_NEAR(o.nm.massNorm(&x), std::abs(x), 1e-15);
  }
  EXPECT_NEAR(cutoffFrequency(0.1, 1.2), 10.0, 1e-12); // (12 / (1.2 * 0.01))^(1/3): phase error 1 rad at wc
}

// The adaptive loop (as femdyn runs it) over 5 periods: max_n |u_n - cos(omega t_n)| <= target (amplitude 1),
// and not below target / 4 (the per-unit-time bound is the phase error here, not a loose bound).
TEST(FemStepControl, AdaptiveRunMeetsTarget) {
  const double w = 2.0, T = 5 * 2 * M_PI / w;
  for (double target : {1e-2, 1e-3}) {
    OneDof o(w);
    StepControlParams p;
    p.target = target, p.t_final = T, p.dt_min = 1e-6 * T;
    StepController c(p);
    double dt = 0.5, err = 0, scale = 1.0;
    int accepted = 0, rejected = 0;
    while (o.s.t < T - 1e-12) {
      const double h = std::min(dt, T - o.s.t);
      const NewmarkState saved = o.s;
      StepTimings tm;
      ASSERT_EQ(o.nm.step(&o.s, h, &tm), 0);
      double e, ef;
      zienkiewiczXieError(0.25, h, saved.a.data(), o.s.a.data(), 1, &e);
      ASSERT_EQ(o.nm.lowPass(o.filter.get(), cutoffFrequency(h, T), &e, &ef), 0);
      bool below;
      const StepDecision d = c.decide(h, std::abs(ef), std::max(scale, std::abs(o.s.u[0])), &below);
      ASSERT_FALSE(below);
      dt = d.dt_next;
      if (!d.accept) {
        o.s = saved, ++rejected;
        continue;
      }
      ++accepted;
      err = std::max(err, std::abs(o.s.u[0] - std::cos(w * o.s.t)));
    }
    printf("target %g: error %.3g, %d steps, %d rejected\n", target, err, accepted, rejected);
    EXPECT_LE(err, target) << accepted << " steps, " << rejected << " rejected";
    EXPECT_GE(err, 0.25 * target) << accepted << " steps";
    EXPECT_GE(rejected, 1) << "the first try dt = 0.5 (omega dt = 1) is too large";
  }
}

TEST(FemStepControl, AcceptRejectAndFactors) {
  StepControlParams p;
  p.target = 1e-2, p.t_final = 10, p.dt_min = 1e-3, p.dt_max = 1.0;
  const double dt = 0.1, tol = kPhaseFactor * p.target * 1.0 * dt / p.t_final; // scale 1
  StepController c(p);
  bool below;
  StepDecision d = c.decide(dt, 0.01 * tol, 1.0, &below); // r = 0.01: growth capped at grow = 2
  EXPECT_TRUE(d.accept);
  EXPECT_DOUBLE_EQ(d.dt_next, 2 * dt);
  d = c.decide(dt, 0.5 * tol, 1.0, &below); // factor 0.8 / sqrt(0.5) = 1.13 < hold: keeps dt
  EXPECT_TRUE(d.accept);
  EXPECT_DOUBLE_EQ(d.dt_next, dt);
  d = c.decide(dt, 4 * tol, 1.0, &below); // r = 4: rejected, dt * 0.8 / 2
  EXPECT_FALSE(d.accept);
  EXPECT_FALSE(below);
  EXPECT_NEAR(d.ratio, 4, 1e-12);
  EXPECT_DOUBLE_EQ(d.dt_next, 0.04);
  d = c.decide(0.04, 0.0, 1.0, &below); // accepted right after a rejection: no growth
  EXPECT_TRUE(d.accept);
  EXPECT_DOUBLE_EQ(d.dt_next, 0.04);
  d = c.decide(0.5, 0.0, 1.0, &below); // growth to 1.0 = dt_max
  EXPECT_DOUBLE_EQ(d.dt_next, 1.0);
  d = c.decide(0.002, 1e6 * tol, 1.0, &below); // shrink bounded at 0.2: 4e-4 < dt_min
  EXPECT_FALSE(d.accept);
  EXPECT_TRUE(below);
}

TEST(FemStepControl, BadSettingsAreErrors) {
  femtest::QuietErrors quiet;
  StepControlParams ok;
  ok.target = 1e-2, ok.t_final = 1, ok.dt_min = 1e-6;
  EXPECT_EQ(checkStepControl(PETSC_COMM_SELF, ok, 0.25), 0);
  for (double t : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    StepControlParams p = ok;
    p.target = t;
    EXPECT_NE(checkStepControl(PETSC_COMM_SELF, p, 0.25), 0) << "target " << t;
  }
  StepControlParams p = ok;
  p.dt_min = 2, p.dt_max = 1;
  EXPECT_NE(checkStepControl(PETSC_COMM_SELF, p, 0.25), 0);
  EXPECT_NE(checkStepControl(PETSC_COMM_SELF, ok, 1.0 / 6.0), 0) << "the estimate vanishes at beta = 1/6";
}
