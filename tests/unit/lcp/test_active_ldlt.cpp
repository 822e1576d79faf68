// ActiveLdlt (LDL^T up/down-dates of a principal block): after every add / remove of a random sequence the
// solve M_FF x = b agrees with a fresh dense solve; refresh and block resets; an indefinite block; a singular
// block is refused (add returns false, set unchanged). Also: bpp and keller on symmetric (LDL^T path) and
// nonsymmetric (LU / inverse path) problems give verified solutions.
#include "lcp/active_ldlt.hpp"
#include "lcp/generators.hpp"
#include "lcp/rng.hpp"
#include "lcp/solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace suite::lcp;

namespace {

double solveError(const Mat& M, const ActiveLdlt& f, Rng& rng) {
  const auto& F = f.indices();
  const int k = f.size();
  if (k == 0) return 0.0;
  Vec b(k);
  for (int a = 0; a < k; ++a) b[a] = rng.uniform(-1.0, 1.0);
  Vec x;
  f.solve(b, &x);
  const Mat A = M(F, F);
  const Vec ref = A.partialPivLu().solve(b);
  return (x - ref).lpNorm<Eigen::Infinity>() / std::max(1.0, ref.lpNorm<Eigen::Infinity>());
}

TEST(ActiveLdlt, RandomAddRemoveSequenceMatchesDenseSolve) {
  const int n = 30;
  Rng rng(7, 0);
  const Mat M = spdWithCondition(n, 1e4, rng);
  for (int refresh : {5, 64}) {
    ActiveLdlt f(M, refresh);
    double worst = 0.0;
    for (int step = 0; step < 400; ++step) {
      const int j = static_cast<int>(rng.uniform(0.0, n - 1e-9));
      if (f.position(j) >= 0) {
        ASSERT_TRUE(f.remove(j));
        EXPECT_EQ(f.position(j), -1);
      } else {
        ASSERT_TRUE(f.add(j)) << "SPD block refused at step " << step;
        EXPECT_EQ(f.indices()[f.position(j)], j);
      }
      ASSERT_EQ(static_cast<int>(f.indices().size()), f.size());
      for (int a = 0; a < f.size(); ++a) ASSERT_EQ(f.position(f.indices()[a]), a);
      worst = std::max(worst, solveError(M, f, rng));
    }
    EXPECT_LT(worst, 1e-9) << "refresh " << refresh; // cond(M_FF) <= 1e4
  }
}

TEST(ActiveLdlt, ResetAndRemoveFirstMiddleLast) {
  const int n = 12;
  Rng rng(3, 1);
  const Mat M = spdWithCondition(n, 1e2, rng);
  ActiveLdlt f(M);
  ASSERT_TRUE(f.reset({0, 2, 4, 6, 8, 10, 11}));
  EXPECT_LT(solveError(M, f, rng), 1e-12);
  for (int j : {0, 6, 11}) { // first, middle, last position
    ASSERT_TRUE(f.remove(j));
    EXPECT_LT(solveError(M, f, rng), 1e-12) << "after removing " << j;
  }
  EXPECT_EQ(f.indices(), (std::vector<int>{2, 4, 8, 10}));
  ASSERT_TRUE(f.remove(5)); // absent: no-op
  EXPECT_EQ(f.size(), 4);
}

TEST(ActiveLdlt, IndefiniteBlockAndSingularBlockRefused) {
  Mat M(4, 4);
  M << 2, 1, 0, 2, //
      1, -3, 1, 1, //
      0, 1, 4, 0,  //
      2, 1, 0, 2;  // column 3 equals column 0
  ActiveLdlt f(M);
  ASSERT_TRUE(f.reset({0, 1, 2})); // indefinite (d = 2, -3.5, ...): unpivoted LDL^T
  Rng rng(1, 1);
  EXPECT_LT(solveError(M, f, rng), 1e-13);
  EXPECT_FALSE(f.add(3)); // M_{0123} is singular
  EXPECT_EQ(f.size(), 3);
  EXPECT_EQ(f.position(3), -1);
  EXPECT_LT(solveError(M, f, rng), 1e-13);
}

TEST(ActiveLdlt, BppAndKellerSolveSymmetricAndNonsymmetricFamilies) {
  GeneratorParams gp;
  gp.n = 40;
  gp.cond = 1e4;
  gp.qrange = 1e2;
  gp.lower = -1e2;
  gp.upper = 1e2;
  for (const char* fam : {"random_box", "random_spd", "pmatrix"})
    for (const char* s : {"bpp", "keller"})
      for (int k = 0; k < 20; ++k) {
        const Problem p = generate(fam, gp, k);
        EXPECT_EQ(p.symmetric, std::string(fam) == "pmatrix" ? 0 : 1) << fam;
        const Result r = solve(*makeSolver(s), p);
        EXPECT_TRUE(r.ok()) << s << " on " << fam << " #" << k << ": " << statusName(r.status);
        EXPECT_LE(r.residual, 1e-10 * (1.0 + p.q.lpNorm<Eigen::Infinity>()));
      }
}

} // namespace
