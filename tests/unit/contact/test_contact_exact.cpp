// Unit tests of the exact contact path's speed-ups: the body-space solver reused across free sets
// gives the same answers as a fresh one (its symbolic analysis kept, its last factorisation reused only for
// the same free set) or updated by a few rows, the deferred sparse Delassus matrix equals the eager one, and the splitting passes of
// a resting pyramid (fixed-point residual, Aitken extrapolation, damping after a stall) converge within the
// pass cap in a bounded number of factorisations; the block Cholesky of the body-space matrix equals a dense
// one.
#include "contact/block_cholesky.hpp"
#include "contact/body_space_solve.hpp"
#include "contact/box_lcp.hpp"
#include "contact/delassus.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace suite::contact;
using suite::lcp::Vec;

namespace {
std::vector<Body> pyramid(int base) {
  SceneParams p;
  p.scene = "pyramid";
  p.pyramid_base = base;
  return buildScene(p);
}

DelassusSystem system(const std::vector<Body>& b, const StepperOptions& o, bool sparse, bool defer = false) {
  std::vector<Mat3> inv_i;
  std::vector<Vec3> v;
  for (const Body& x : b) { // the velocities after gravity's impulse (v*)
    inv_i.push_back(x.is_static ? Mat3::Zero() : x.invInertiaWorld());
    v.push_back(x.is_static ? x.v : Vec3(x.v + o.dt * o.gravity));
  }
  const std::vector<Contact> cs = findContacts(b, o.margin, o.gravity, o.dt);
  return buildDelassus(b, inv_i, v, cs, boxRows(cs, true), o, sparse, defer);
}

// Free sets: every row but those with i % k == j.
std::vector<int> freeSet(int n, int k, int j) {
  std::vector<int> F;
  for (int i = 0; i < n; ++i)
    if (i % k != j) F.push_back(i);
  return F;
}
} // namespace

TEST(ContactExactSolve, BodySpaceSolverReusedEqualsFresh) {
  const auto b = pyramid(5);
  const DelassusSystem d = system(b, StepperOptions{}, false), s = system(b, StepperOptions{}, true);
  const int n = (int)s.b.size();
  BodySpaceSolver solver(s.rows, s.mass, s.reg);
  const std::vector<std::vector<int>> sets = {freeSet(n, 5, 2), freeSet(n, 5, 2), freeSet(n, 7, 3),
                                              freeSet(n, 5, 2)};
  for (size_t k = 0; k < sets.size(); ++k) {
    const std::vector<int>& F = sets[k];
    Vec r(F.size()), x, x_fresh;
    for (size_t a = 0; a < F.size(); ++a) r[a] = std::cos(0.5 + a + k); // any right-hand side
    ASSERT_TRUE(solver.solve(F, r, &x));
    ASSERT_TRUE(bodySpaceSolve(s.rows, s.mass, s.reg, F, r, &x_fresh));
    const suite::lcp::Mat AFF = d.A(F, F);
    const double backward = (AFF * x - r).lpNorm<Eigen::Infinity>() /
                            (AFF.lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>());
    std::printf("pyramid 5, free set %zu (%zu rows): max|x - x_fresh| %.1e, backward error %.1e\n", k,
                F.size(), (x - x_fresh).lpNorm<Eigen::Infinity>(), backward);
    // same pattern, ordering and assembly as a fresh solver: the same numbers, bit for bit
    EXPECT_EQ((x - x_fresh).lpNorm<Eigen::Infinity>(), 0.0) << k;
    EXPECT_LE(backward, 1e-15) << k;
  }
  EXPECT_EQ(solver.solves(), 4);
  EXPECT_EQ(solver.factorizations(), 3); // the repeated free set reuses its factorisation
}

// A free set within a few rows (at least 16) of the factorised one is solved by a low-rank update of
// that factorisation (rows added and removed), not a new one: the same answer as a fresh solver to round-off;
// a set further away is factorised anew.
TEST(ContactExactSolve, BodySpaceSolverUpdateEqualsFresh) {
  const auto b = pyramid(5);
  const DelassusSystem d = system(b, StepperOptions{}, false), s = system(b, StepperOptions{}, true);
  const int n = (int)s.b.size();
  BodySpaceSolver solver(s.rows, s.mass, s.reg);
  const std::vector<int> base = freeSet(n, 5, 2);
  std::vector<int> near = base; // 3 rows removed, 4 added (rows i % 5 == 2 with i < 20)
  near.erase(near.begin() + 10), near.erase(near.begin() + 20), near.erase(near.begin() + 30);
  for (int i : {2, 7, 12, 17}) near.push_back(i);
  std::sort(near.begin(), near.end());
  const std::vector<std::vector<int>> sets = {base, near, near, freeSet(n, 7, 3)};
  for (size_t k = 0; k < sets.size(); ++k) {
    const std::vector<int>& F = sets[k];
    Vec r(F.size()), x, x_fresh;
    for (size_t a = 0; a < F.size(); ++a) r[a] = std::sin(0.3 + a + k);
    ASSERT_TRUE(solver.solve(F, r, &x));
    ASSERT_TRUE(bodySpaceSolve(s.rows, s.mass, s.reg, F, r, &x_fresh));
    const double diff = (x - x_fresh).lpNorm<Eigen::Infinity>() / x_fresh.lpNorm<Eigen::Infinity>();
    const double backward = (d.A(F, F) * x - r).lpNorm<Eigen::Infinity>() /
                            (d.A(F, F).lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>());
    std::printf(
        "pyramid 5, set %zu (%zu rows): relative difference to a fresh solve %.1e, backward error %.1e\n", k,
        F.size(), diff, backward);
    EXPECT_LE(diff, 1e-12) << k;
    EXPECT_LE(backward, 1e-15) << k;
  }
  EXPECT_EQ(solver.updates(), 1);        // near: 7 rows from base
  EXPECT_EQ(solver.factorizations(), 2); // base, then the far set
  EXPECT_EQ(solver.solves(), 4);
}

TEST(ContactExactSolve, DeferredSparseMatrixEqualsEager) {
  const auto b = pyramid(5);
  const DelassusSystem eager = system(b, StepperOptions{}, true),
                       deferred = system(b, StepperOptions{}, true, true);
  EXPECT_EQ(deferred.S.nonZeros(), 0);
  const SpMat& S = sparseMatrix(deferred);
  ASSERT_EQ(S.nonZeros(), eager.S.nonZeros());
  EXPECT_EQ(suite::lcp::Mat(S - eager.S).lpNorm<Eigen::Infinity>(), 0.0);
  for (int i = 0; i < (int)eager.b.size(); ++i) { // reg as read off S: A_ii - (J M^-1 J^T)_ii, same rounding
    const JRow& J = eager.rows[i];
    EXPECT_EQ(deferred.reg[i], eager.S.coeff(i, i) - (J.ja.dot(J.ma) + J.jb.dot(J.mb))) << i;
  }
}

TEST(ContactExactSolve, RestingPyramidPassesConvergeWithinTheCap) {
  auto b = pyramid(8); // 36 boxes, 768 rows: the sparse path
  const auto b0 = b;
  StepperOptions o;
  Stepper st(o);
  long long factorizations = 0;
  int max_passes = 0;
  double drift = 0.0;
  for (int k = 0; k < 100; ++k) {
    const StepStats s = st.step(&b);
    ASSERT_FALSE(s.failed) << k;
    ASSERT_EQ(s.solver, "sparse_active_set") << k;
    if (k > 0) factorizations += s.factorizations;
    max_passes = std::max(max_passes, s.splitting_iterations);
  }
  for (size_t i = 0; i < b.size(); ++i) drift = std::max(drift, (b[i].x - b0[i].x).lpNorm<Eigen::Infinity>());
  std::printf("pyramid 8, steps 2-100: %.2f factorisations per step, at most %d passes, drift %.2e\n",
              factorizations / 99.0, max_passes, drift);
  EXPECT_LT(max_passes, o.splitting_max_it); // every step's passes converged, none stopped by the cap
  EXPECT_LE(drift, 1e-6);
  EXPECT_LE(factorizations, 12 * 99); // measured 11.05 (14.19 on main at 06b88ad)
}

// The block Cholesky of the body-space matrix (block_cholesky.hpp) on a random block-sparse SPD matrix whose
// ordering makes fill (a ring of 12 blocks plus chords): its solve equals the dense LL^T solve to round-off, and
// an indefinite matrix is refused.
TEST(ContactExactSolve, BlockCholeskyEqualsDense) {
  const int n = 12;
  std::vector<std::pair<int, int>> edges;
  for (int k = 0; k < n; ++k) edges.push_back({k, (k + 1) % n});
  edges.push_back({0, 6}), edges.push_back({3, 9}), edges.push_back({9, 3}); // a repeat as well
  BlockCholesky chol;
  const std::vector<int> at = chol.analyze(n, edges);
  ASSERT_EQ(at.size(), edges.size());
  EXPECT_EQ(at[edges.size() - 1], at[edges.size() - 2]);
  EXPECT_GT(chol.blocksInL(), n + 14); // the ring's fill
  suite::lcp::Mat K = suite::lcp::Mat::Zero(6 * n, 6 * n);
  std::srand(7);
  for (size_t e = 0; e + 1 < edges.size(); ++e) { // off-diagonal blocks: random, lower storage
    const int i = std::max(edges[e].first, edges[e].second), j = std::min(edges[e].first, edges[e].second);
    const BlockCholesky::M6 B = BlockCholesky::M6::Random();
    chol.lower(at[e]) = B;
    K.block<6, 6>(6 * i, 6 * j) = B;
    K.block<6, 6>(6 * j, 6 * i) = B.transpose();
  }
  for (int k = 0; k < n; ++k) { // diagonally dominant diagonal blocks
    const BlockCholesky::M6 R = BlockCholesky::M6::Random();
    const BlockCholesky::M6 D = R * R.transpose() + 40.0 * BlockCholesky::M6::Identity();
    chol.diag(k) = D;
    K.block<6, 6>(6 * k, 6 * k) = D;
  }
  ASSERT_TRUE(chol.factor());
  Vec x = Vec::LinSpaced(6 * n, -1.0, 2.0), ref = K.llt().solve(x);
  chol.solve(&x);
  const double err = (x - ref).lpNorm<Eigen::Infinity>() / ref.lpNorm<Eigen::Infinity>();
  std::printf("block Cholesky, 12 blocks with fill: relative difference to dense LL^T %.1e\n", err);
  EXPECT_LE(err, 1e-13);
  chol.diag(5) = -chol.diag(5); // indefinite
  EXPECT_FALSE(chol.factor());
}
