// The solver chain the friction formulations solve through (lcp::solveWithChain with the contact library's
// solvers): a failed attempt falls back to the next solver, every answer is verified on the original problem
// (also when the chain solves a scaled form first), unknown names are reported and skipped, and a chain that
// fails everywhere is never reported as solved and names every attempt.
#include "contact/friction_formulation.hpp"
#include "contact/lemke_rf.hpp"
#include "lcp/solver.hpp"

#include <gtest/gtest.h>

using namespace suite::contact;
namespace lcp = suite::lcp;

namespace {
// A small SPD LCP with two active and one inactive unknown.
lcp::Problem spdLcp() {
  lcp::Mat M(3, 3);
  M << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  lcp::Vec q(3);
  q << -1, -2, 3;
  return lcp::makeLcp(M, q, "spd3");
}

lcp::ChainOptions contactChain(int first_cap) {
  lcp::ChainOptions o;
  o.rel_tol = 1e-8;
  o.first_max_iterations = first_cap;
  o.make = makeContactSolver;
  return o;
}
} // namespace

TEST(ContactSolverChain, FallsBackAndVerifies) {
  const lcp::Problem p = spdLcp();
  std::vector<lcp::Attempt> att;
  const lcp::Result r = lcp::solveWithChain(p, {"pgs", "lemke_rf"}, contactChain(1), &att);
  ASSERT_EQ(att.size(), 2u);
  EXPECT_FALSE(att[0].accepted);
  EXPECT_TRUE(att[1].accepted);
  EXPECT_EQ(att[1].solver, "lemke_rf");
  EXPECT_EQ(r.status, lcp::Status::Solved);
  EXPECT_LE(lcp::naturalResidual(p, r.z, p.M * r.z + p.q), lcp::acceptanceTolerance(p, 1e-8));
  EXPECT_EQ(lcp::describeAttempts(att).rfind("pgs: max_iterations (residual ", 0), 0u)
      << lcp::describeAttempts(att);
}

TEST(ContactSolverChain, ScaledFirstAnswerOnTheOriginal) {
  const lcp::Problem p = spdLcp();
  const lcp::Vec s = lcp::Vec::Constant(3, 0.5);
  lcp::ChainOptions o = contactChain(0);
  o.scale = &s;
  std::vector<lcp::Attempt> att;
  const lcp::Result r = lcp::solveWithChain(p, {"lemke"}, o, &att);
  ASSERT_EQ(att.size(), 1u);
  EXPECT_EQ(att[0].form, lcp::Form::Scaled);
  EXPECT_EQ(r.status, lcp::Status::Solved);
  EXPECT_EQ(r.z.size(), 3);
  EXPECT_NEAR(r.residual, lcp::naturalResidual(p, r.z, p.M * r.z + p.q), 1e-300);
}

TEST(ContactSolverChain, UnknownAndFailedNeverSolved) {
  const lcp::Problem p = spdLcp();
  std::vector<lcp::Attempt> att;
  const lcp::Result r = lcp::solveWithChain(p, {"nosuch", "pgs"}, contactChain(0), &att);
  ASSERT_EQ(att.size(), 2u);
  EXPECT_FALSE(att[0].known);
  EXPECT_EQ(r.status == lcp::Status::Solved, att[1].accepted);
  lcp::ChainOptions capped = contactChain(1);
  const lcp::Result f = lcp::solveWithChain(p, {"pgs", "nosuch"}, capped, &att); // the cap is pgs's
  ASSERT_EQ(att.size(), 2u);
  EXPECT_NE(f.status, lcp::Status::Solved);
  const std::string why = lcp::describeAttempts(att);
  EXPECT_NE(why.find("nosuch: unknown solver; "), std::string::npos) << why;
  EXPECT_NE(why.find("pgs: max_iterations"), std::string::npos) << why;
}

// The solver choices of -lcp_solver / -fallback_solvers / -polyhedral_solvers: lib/lcp's registry in its order,
// then lemke_rf, each with a description and each made by makeContactSolver.
TEST(ContactSolverChain, ChoicesAreTheRegistryPlusLemkeRf) {
  const std::vector<suite::Choice> choices = contactSolverChoices();
  const std::vector<lcp::SolverInfo> registry = lcp::solverRegistry();
  ASSERT_EQ(choices.size(), registry.size() + 1);
  for (size_t i = 0; i < registry.size(); ++i) EXPECT_EQ(choices[i].name, registry[i].name);
  EXPECT_EQ(choices.back().name, "lemke_rf");
  for (const suite::Choice& c : choices) {
    EXPECT_FALSE(c.help.empty()) << c.name;
    EXPECT_NE(makeContactSolver(c.name), nullptr) << c.name;
  }
}
