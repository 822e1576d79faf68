// The blocked banded Cholesky (lib/fem/solver_banded.cpp: blocks of 32 columns, rows limited to the envelope)
// on SPD matrices with a varying envelope wider than the unblocked limit (kd > 96), in natural and shuffled
// order: residual of the solve <= 1e-12 relative, equal to the skyline solver to 1e-12, a matrix that is not
// positive definite reported as such; and the Newmark tangent predictor (lib/fem/newmark.cpp): every Newton
// iteration refactorises, the steps converge to the same trajectory as with the constant-acceleration
// predictor (to the Newton tolerance), with fewer iterations, and restoreTangent() after a "restart"
// continues bitwise like the uninterrupted run.
#include "fem_test_util.hpp"
#include "newmark_test_chain.hpp"

#include "fem/linear_solver.hpp"
#include "fem/newmark.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace suite::fem;
using namespace femtest;

namespace {
// Upper triangle: column c has rows f_c..c with f_c = c - w_c, w_c in [wmin, wmax] (a ragged envelope),
// off-diagonal entries in [-1, 1], diagonal 1 + sum of the row's |entries| (diagonally dominant, SPD).
SymCsc raggedSpd(int n, int wmin, int wmax, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(wmin, wmax);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  SymCsc A;
  A.n = n;
  A.colptr.assign(n + 1, 0);
  std::vector<double> rowsum(n, 0.0);
  std::vector<int> diag(n);
  for (int c = 0; c < n; ++c) {
    const int f = std::max(0, c - w(rng));
    for (int r = f; r <= c; ++r) {
      A.rowind.push_back(r);
      const double x = r == c ? 0.0 : v(rng);
      A.val.push_back(x);
      rowsum[r] += std::abs(x), rowsum[c] += std::abs(x);
      if (r == c) diag[c] = static_cast<int>(A.val.size()) - 1;
    }
    A.colptr[c + 1] = static_cast<int>(A.rowind.size());
  }
  for (int c = 0; c < n; ++c) A.val[diag[c]] = 1.0 + rowsum[c];
  return A;
}
} // namespace

TEST(FemBanded, BlockedMatchesSkylineOnRaggedEnvelope) {
  const SymCsc A = raggedSpd(700, 20, 160, 7);
  std::vector<int> natural(A.n), shuffled(A.n);
  std::iota(natural.begin(), natural.end(), 0);
  shuffled = natural;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
  std::vector<double> b(A.n), x(A.n), y(A.n), r(A.n);
  for (int i = 0; i < A.n; ++i) b[i] = std::cos(0.1 * i);
  for (const auto* perm : {&natural, &shuffled}) {
    auto band = makeBandedSolver(), sky = makeSkylineSolver();
    ASSERT_EQ(band->analyze(PETSC_COMM_SELF, A, *perm), 0);
    ASSERT_EQ(sky->analyze(PETSC_COMM_SELF, A, *perm), 0);
    bool ok1 = false, ok2 = false;
    for (int rep = 0; rep < 2; ++rep) { // refactorisation of the same pattern reuses the storage
      ASSERT_EQ(band->factor(A, &ok1), 0);
      ASSERT_TRUE(ok1);
      ASSERT_EQ(band->solve(b.data(), x.data()), 0);
    }
    ASSERT_EQ(sky->factor(A, &ok2), 0);
    ASSERT_TRUE(ok2);
    ASSERT_EQ(sky->solve(b.data(), y.data()), 0);
    symMultiply(A, A.val, x.data(), r.data());
    double res = 0, bn = 0, diff = 0, xn = 0;
    for (int i = 0; i < A.n; ++i) {
      res = std::max(res, std::abs(r[i] - b[i])), bn = std::max(bn, std::abs(b[i]));
      diff = std::max(diff, std::abs(x[i] - y[i])), xn = std::max(xn, std::abs(y[i]));
    }
    EXPECT_LT(res, 1e-12 * bn);
    EXPECT_LT(diff, 1e-12 * xn);
    // x may alias b.
    std::vector<double> z = b;
    ASSERT_EQ(band->solve(z.data(), z.data()), 0);
    for (int i = 0; i < A.n; ++i) ASSERT_EQ(z[i], x[i]);
  }
}

TEST(FemBanded, BlockedReportsNotPositiveDefinite) {
  SymCsc A = raggedSpd(500, 100, 140, 11);
  // A negative pivot late in the matrix (inside a later block): the factorisation must say so.
  for (int k = A.colptr[400]; k < A.colptr[401]; ++k)
    if (A.rowind[k] == 400) A.val[k] = -1.0;
  std::vector<int> perm(A.n);
  std::iota(perm.begin(), perm.end(), 0);
  auto band = makeBandedSolver();
  ASSERT_EQ(band->analyze(PETSC_COMM_SELF, A, perm), 0);
  bool ok = true;
  ASSERT_EQ(band->factor(A, &ok), 0);
  EXPECT_FALSE(ok);
}

TEST(FemNewmark, TangentPredictorIsFullNewtonWithFewerIterations) {
  ChainRun ca(chainParams(false)), tp(chainParams(true));
  const double dt = 0.05;
  int it_ca = 0, it_tp = 0;
  double umax = 0, diff = 0;
  for (int k = 0; k < 200; ++k) {
    StepTimings t1, t2;
    ASSERT_EQ(ca.nm.step(&ca.s, dt, &t1), 0);
    ASSERT_EQ(tp.nm.step(&tp.s, dt, &t2), 0);
    ASSERT_TRUE(t1.converged && t2.converged);
    ASSERT_EQ(t2.rejected, 0);
    EXPECT_GE(t2.newton_iterations, 1);                 // at least one Newton iteration per step
    EXPECT_EQ(t2.factorizations, t2.newton_iterations); // each refactorises the consistent tangent
    it_ca += t1.newton_iterations, it_tp += t2.newton_iterations;
    for (int i = 0; i < 2; ++i)
      umax = std::max(umax, std::abs(ca.s.u[i])), diff = std::max(diff, std::abs(ca.s.u[i] - tp.s.u[i]));
  }
  EXPECT_GT(umax, 0.3); // nonlinear regime: c u^2 ~ 2
  EXPECT_LT(diff, 1e-8 * umax);
  EXPECT_LT(it_tp, it_ca);
  std::printf(
      "Newton iterations over 200 steps: constant predictor %d, tangent predictor %d; max |du| %.2e\n", it_ca,
      it_tp, diff);
}

TEST(FemNewmark, TangentPredictorRestoredAfterRestartIsBitwise) {
  ChainRun full(chainParams(true)), first(chainParams(true));
  const double dt = 0.05;
  StepTimings tm;
  for (int k = 0; k < 60; ++k) ASSERT_EQ(full.nm.step(&full.s, dt, &tm), 0);
  for (int k = 0; k < 25; ++k) ASSERT_EQ(first.nm.step(&first.s, dt, &tm), 0);
  ASSERT_EQ(first.s.u_tangent.size(), 2u);
  EXPECT_EQ(first.s.dt_tangent, dt);
  // "Restart": a new integrator and solver from the saved state only.
  ChainRun second(chainParams(true));
  second.s = first.s;
  ASSERT_EQ(second.nm.restoreTangent(second.s), 0);
  for (int k = 25; k < 60; ++k) ASSERT_EQ(second.nm.step(&second.s, dt, &tm), 0);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(second.s.u[i], full.s.u[i]);
    EXPECT_EQ(second.s.v[i], full.s.v[i]);
    EXPECT_EQ(second.s.a[i], full.s.a[i]);
  }
  // Without the restore the first step after the restart starts from the plain predictor: not bitwise.
  ChainRun third(chainParams(true));
  third.s = first.s;
  for (int k = 25; k < 60; ++k) ASSERT_EQ(third.nm.step(&third.s, dt, &tm), 0);
  EXPECT_NE(third.s.u[0], full.s.u[0]);
}
