// The lagged tangent (-jacobian lagged, lib/fem/newmark.cpp) and the work cap (-newton_max_corrections) on the
// hardening two-mass chain: lagged corrections reach full Newton's trajectory (same stopping test) with a
// fraction of its factorisations; the refresh rule refactorises on the first step, after a dt change, when
// the factorisation held stops contracting the residual (a load jump) and after refresh_iterations
// corrections; the capped step is accepted with the residual of its last iterate, which equals
// |M a + f(u) - f_ext(t)| recomputed from the accepted state, and the step after it refactorises.
#include "newmark_test_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace suite::fem;
using femtest::chainParams;
using femtest::ChainRun;

namespace {
// Newton's test at |r| <= 1e-10 |r_predictor| or |r| <= 1e-10: at dt = 0.01 the residual's round-off floor is
// about |u| eps 4 / (beta dt^2) ~ 1e-11, above 1e-10 times the predictor's residual (~1e-5).
NewmarkParams fullParams() {
  NewmarkParams p = chainParams(false);
  p.newton_atol = 1e-10;
  return p;
}
NewmarkParams laggedParams() {
  NewmarkParams p = fullParams();
  p.lagged = true;
  return p;
}
} // namespace

TEST(FemNewmarkLagged, ReachesFullNewtonTrajectoryWithFewerFactorisations) {
  ChainRun full(fullParams()), lag(laggedParams());
  const double dt = 0.01;
  int fact_full = 0, fact_lag = 0, it_lag = 0;
  double umax = 0, diff = 0;
  for (int k = 0; k < 1000; ++k) {
    StepTimings t1, t2;
    ASSERT_EQ(full.nm.step(&full.s, dt, &t1), 0);
    ASSERT_EQ(lag.nm.step(&lag.s, dt, &t2), 0);
    ASSERT_TRUE(t1.converged && t2.converged) << "step " << k;
    ASSERT_EQ(t2.rejected, 0);
    fact_full += t1.factorizations, fact_lag += t2.factorizations, it_lag += t2.newton_iterations;
    for (int i = 0; i < 2; ++i)
      umax = std::max(umax, std::abs(full.s.u[i])), diff = std::max(diff, std::abs(full.s.u[i] - lag.s.u[i]));
  }
  std::printf("1000 steps: full Newton %d factorisations; lagged %d factorisations, %d corrections; max |du| "
              "%.2e (umax %.2f)\n",
              fact_full, fact_lag, it_lag, diff, umax);
  // Measured: max |du| 1.4e-10 (umax 1.23); 26 factorisations against 1892.
  EXPECT_GT(umax, 0.3);         // nonlinear regime
  EXPECT_LT(diff, 1e-9 * umax); // both stop at the same Newton test
  EXPECT_LT(40 * fact_lag, fact_full);
}

TEST(FemNewmarkLagged, RefreshRuleRefactorisesWhenItMust) {
  ChainRun lag(laggedParams());
  const double dt = 0.01;
  StepTimings tm;
  ASSERT_EQ(lag.nm.step(&lag.s, dt, &tm), 0); // the solver holds the mass matrix after initialize()
  EXPECT_GE(tm.factorizations, 1);
  int quiet = 0;
  for (int k = 0; k < 20; ++k) {
    ASSERT_EQ(lag.nm.step(&lag.s, dt, &tm), 0);
    quiet += tm.factorizations;
  }
  EXPECT_LT(quiet, 20);                             // smooth phase: most steps reuse the factorisation
  ASSERT_EQ(lag.nm.step(&lag.s, 0.5 * dt, &tm), 0); // a new dt: K_eff changed
  EXPECT_GE(tm.factorizations, 1);
  ASSERT_EQ(lag.nm.step(&lag.s, 0.5 * dt, &tm), 0);
  // A load jump (drive x 40) at dt = 0.05: the factorisation of the quiet phase no longer contracts the
  // residual.
  ChainRun off(laggedParams());
  NewmarkParams never = laggedParams();
  never.refresh_contraction = 0.99, never.refresh_iterations = 1000, never.newton_max_it = 200;
  ChainRun stale(never);
  for (ChainRun* r : {&off, &stale})
    for (int k = 0; k < 20; ++k) ASSERT_EQ(r->nm.step(&r->s, 0.05, &tm), 0);
  off.load_scale = stale.load_scale = 40;
  StepTimings jump, jump_stale;
  ASSERT_EQ(off.nm.step(&off.s, 0.05, &jump), 0);
  ASSERT_EQ(stale.nm.step(&stale.s, 0.05, &jump_stale), 0);
  std::printf("load jump: refresh rule %d corrections, %d factorisations; rule off %d corrections, %d\n",
              jump.newton_iterations, jump.factorizations, jump_stale.newton_iterations,
              jump_stale.factorizations);
  EXPECT_GE(jump.factorizations, 1);
  EXPECT_EQ(jump_stale.factorizations, 0);
  EXPECT_LT(jump.newton_iterations, jump_stale.newton_iterations);
  // refresh_iterations = 1: after the first correction with the factorisation held, every correction of the
  // step is preceded by a refactorisation (full Newton from the first lagged correction on).
  NewmarkParams every = laggedParams();
  every.refresh_iterations = 1;
  ChainRun each(every);
  ASSERT_EQ(each.nm.step(&each.s, dt, &tm), 0);
  for (int k = 0; k < 30; ++k) {
    ASSERT_EQ(each.nm.step(&each.s, dt, &tm), 0);
    EXPECT_EQ(tm.factorizations, tm.newton_iterations - 1) << "step " << k;
  }
}

TEST(FemNewmarkLagged, WorkCapAcceptsWithTheLastIteratesResidual) {
  NewmarkParams p = laggedParams();
  p.max_corrections = 1;
  ChainRun cap(p);
  cap.load_scale = 10; // strongly nonlinear: one correction does not reach 1e-10
  const double dt = 0.05;
  int capped = 0;
  bool last_capped = false;
  for (int k = 0; k < 50; ++k) {
    StepTimings tm;
    ASSERT_EQ(cap.nm.step(&cap.s, dt, &tm), 0);
    ASSERT_EQ(tm.rejected, 0);
    EXPECT_LE(tm.newton_iterations, 1);
    EXPECT_EQ(tm.capped, !tm.converged);
    if (last_capped) {
      EXPECT_EQ(tm.factorizations, 1) << "step " << k; // refreshed after a capped step
    }
    last_capped = tm.capped;
    capped += tm.capped ? 1 : 0;
    // The recorded residual against the accepted state: r = M a + f(u) - f_ext(t), M = I.
    double f[2], fe[2];
    cap.sys.internalForce(cap.s.u.data(), f, nullptr, nullptr);
    ChainRun::load(cap.s.t, cap.load_scale, fe);
    const double r0 = cap.s.a[0] + f[0] - fe[0], r1 = cap.s.a[1] + f[1] - fe[1];
    const double rn = std::hypot(r0, r1);
    EXPECT_NEAR(tm.residual, rn, 1e-9 * std::max(rn, 1.0)) << "step " << k;
  }
  std::printf("work cap 1 correction: %d of 50 steps accepted above the tolerance\n", capped);
  EXPECT_GT(capped, 25); // measured: 50 of 50
}
