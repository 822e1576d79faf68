// Polyhedral friction (Stewart & Trinkle 1996; Anitescu & Potra 1997; Lacoursiere SIGRAD 2003, Eq. 6):
// every step's LCP of a small log heap is solved by Lemke itself (no fallback) and verified here on the
// unscaled problem; the friction of each contact stays inside the polygon; on the incline the force ratio
// reproduces min(tan th, mu) within the polygon's approximation error mu (1 - cos(pi / d)).
#include "contact/friction_formulation.hpp"
#include "contact/lemke_rf.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"
#include "lcp/solver.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::contact;
namespace lcp = suite::lcp;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// The LCP matrix: structure of Eq. 6 and the gamma compliance making it strictly copositive.
TEST(ContactPolyhedral, LcpStructure) {
  const int nc = 2, d = 4;
  lcp::Mat A = lcp::Mat::Identity(nc * (1 + d), nc * (1 + d));
  lcp::Vec b = lcp::Vec::Constant(nc * (1 + d), -1.0);
  lcp::Problem p = polyhedralLcp(A, b, nc, d, 0.3);
  ASSERT_EQ(p.size(), nc * (2 + d));
  const int k = nc * (1 + d);
  EXPECT_EQ(p.M(k + 1, 1), 0.3);                  // mu lambda_n
  EXPECT_EQ(p.M(k + 1, nc + d + 2), -1.0);        // - e^T beta
  EXPECT_EQ(p.M(nc + d + 2, k + 1), 1.0);         // D^T v + e gamma
  EXPECT_EQ(p.M(nc + 2, k + 1), 0.0);             // other contact
  EXPECT_EQ(p.q[k], 0.0);                         // cone rows have q = 0
  const lcp::Vec s = polyhedralScaling(p, nc, d); // A = I: all ones
  for (int i = 0; i < p.size(); ++i) EXPECT_DOUBLE_EQ(s[i], 1.0);
}

TEST(ContactPolyhedral, SmallLogHeapEveryStepVerified) {
  SceneParams sp;
  sp.scene = "log_heap";
  sp.n_logs = 15;
  auto bodies = buildScene(sp);
  StepperOptions o;
  o.friction = FrictionModel::Polyhedral;
  o.mu = 0.4;
  o.polyhedral_directions = 4;
  Stepper stepper(o);
  stepper.keepProblems(true);
  int max_rows = 0, lemke_steps = 0, with_contacts = 0, fallbacks = 0;
  double worst = 0.0, worst_cone = 0.0;
  for (int s = 0; s < 150; ++s) {
    StepStats st = stepper.step(&bodies);
    ASSERT_FALSE(st.failed) << "step " << s + 1 << ": " << st.message;
    if (st.contacts == 0) continue;
    ++with_contacts;
    ASSERT_EQ(stepper.lastProblems().size(), 1u);
    const lcp::Problem& p = stepper.lastProblems().back();
    const lcp::Vec& z = stepper.lastSolution();
    ASSERT_EQ(z.size(), p.size());
    const lcp::Vec w = lcp::slack(p, z);
    const double r = lcp::naturalResidual(p, z, w);
    EXPECT_LE(r, o.lcp_tol * (1 + p.q.lpNorm<Eigen::Infinity>())) << "step " << s + 1;
    worst = std::max(worst, r / (1 + p.q.lpNorm<Eigen::Infinity>()));
    EXPECT_GE(z.minCoeff(), -o.lcp_tol * (1 + p.q.lpNorm<Eigen::Infinity>()));
    lemke_steps += st.solver == "lemke" || st.solver == "lemke_rf";
    fallbacks += st.fallbacks;
    max_rows = std::max(max_rows, p.size());
    // friction inside the (slightly compliant) polygon: sum_j beta_ij <= mu lambda_n,i
    const int nc = st.contacts, d = o.polyhedral_directions;
    for (int i = 0; i < nc; ++i) {
      double sb = 0.0;
      for (int j = 0; j < d; ++j) sb += z[nc + i * d + j];
      worst_cone = std::max(worst_cone, sb - o.mu * z[i]);
    }
  }
  std::printf(
      "polyhedral heap: %d steps with contacts, %d solved by Lemke (%d failed attempts before), largest "
      "LCP %d, worst relative residual %.2e, worst cone excess %.2e N s\n",
      with_contacts, lemke_steps, fallbacks, max_rows, worst, worst_cone);
  EXPECT_GT(with_contacts, 100);
  EXPECT_GT(max_rows, 100);              // a real heap, not a few isolated contacts
  EXPECT_EQ(lemke_steps, with_contacts); // a pivoting method (the reference) solved every step
  EXPECT_LE(worst_cone, 1e-6);
}

// Force ratio on the incline against min(tan th, mu), to 1e-6, sticking and sliding (along a generator of the
// cone, d = 4 and 8).
TEST(ContactPolyhedral, InclineForceRatio) {
  const double mu = 0.5;
  for (int d : {4, 8}) {
    for (double th : {10.0, 20.0, 25.0, 30.0, 40.0}) {
      SceneParams sp;
      sp.scene = "incline";
      sp.theta_deg = th;
      auto b = buildScene(sp);
      StepperOptions o;
      o.friction = FrictionModel::Polyhedral;
      o.mu = mu;
      o.polyhedral_directions = d;
      Stepper stepper(o);
      StepStats st;
      for (int k = 0; k < 50; ++k) {
        st = stepper.step(&b);
        ASSERT_FALSE(st.failed) << st.message;
      }
      const double exact = std::min(std::tan(th * kPi / 180), mu);
      std::printf("polyhedral d=%d theta %4.1f: ratio %.8f exact %.8f\n", d, th, st.force_ratio, exact);
      // The box slides along x, one of the cone's generators for d = 4 and 8, where the polyhedral cone meets the
      // circular one: the sliding force ratio is mu itself, not mu cos(pi/d). Measured: at most 1.7e-7 from
      // min(tan th, mu) (sliding at 40 deg), 4e-8 at 30 deg, below 1e-8 sticking.
      EXPECT_NEAR(st.force_ratio, exact, 1e-6) << "d " << d << " theta " << th;
    }
  }
}

// Lemke with refactorisation (lemke_rf.hpp) ends, one way or the other, within a few n pivots on the first
// step of a pyramid of base 5 (100 contacts, d = 8: a 1,000-row, highly degenerate polyhedral LCP). There the
// pivots lose the feasibility of the basis (a basic value of -1.5e-6 after a refactorisation); unchecked, Lemke
// cycles from that point to the cap of 100,000 pivots (minutes a step). The feasibility check after each
// refactorisation stops it so that the chain's next solver is tried. Invariant checked: solved and verified,
// or a failure that is not the cap, within 5 n pivots.
TEST(ContactPolyhedral, LemkeRefactoredEndsOnTheDegeneratePyramid) {
  SceneParams sp;
  sp.scene = "pyramid";
  sp.pyramid_base = 5;
  auto bodies = buildScene(sp);
  StepperOptions o;
  o.friction = FrictionModel::Polyhedral;
  o.mu = 0.5;
  o.polyhedral_solvers = {"lemke"}; // fails in ~0.5 s here; the step's problem is kept all the same
  Stepper stepper(o);
  stepper.keepProblems(true);
  stepper.step(&bodies);
  ASSERT_FALSE(stepper.lastProblems().empty());
  const lcp::Problem& p = stepper.lastProblems().back();
  const lcp::Result r = lcp::solve(*makeLemkeRefactored(), p);
  std::printf("pyramid 5, polyhedral d = 8: %d rows, lemke_rf %s after %lld pivots (residual %.2e%s%s)\n",
              p.size(), lcp::statusName(r.status), r.pivots, r.residual, r.message.empty() ? "" : ", ",
              r.message.c_str());
  EXPECT_NE(r.status, lcp::Status::MaxIterations);
  EXPECT_LE(r.pivots, 5LL * p.size());
  if (r.ok()) {
    EXPECT_LE(r.residual, 1e-10 * (1.0 + p.q.lpNorm<Eigen::Infinity>()));
  }
}
