// The solver chain of the friction formulations (see friction_formulation.hpp): lcp::solveWithChain with the
// contact library's solvers, the attempts added to the step's statistics.
#include "contact/friction_formulation.hpp"

#include "contact/lemke_rf.hpp"
#include "lcp/solver.hpp"

#include <algorithm>

namespace suite::contact {

bool ChainSolve::solve(const lcp::Problem& p, const std::vector<std::string>& chain, const lcp::Vec* scale,
                       const lcp::Vec* warm, lcp::Vec* z) {
  if (keep_all_ || problems_->empty())
    problems_->push_back(p);
  else
    problems_->back() = p; // always keep the last one (dumped on failure)
  lcp::ChainOptions co;
  co.rel_tol = o_.lcp_tol;
  co.first_max_iterations = o_.lcp_max_iterations; // the cap is for the primary solver only
  co.warm_start = o_.warm_start ? warm : nullptr;
  co.scale = scale;
  co.make = makeContactSolver;
  std::vector<lcp::Attempt> attempts;
  const lcp::Result r = lcp::solveWithChain(p, chain, co, &attempts);
  for (const lcp::Attempt& a : attempts) {
    st_->iterations += a.iterations;
    st_->pivots += a.pivots;
    st_->refinements += a.refinements;
    st_->fallbacks += a.known && !a.accepted;
  }
  if (!r.ok()) {
    st_->failed = true;
    st_->message = "contact problem of size " + std::to_string(p.size()) +
                   " not solved: " + lcp::describeAttempts(attempts);
    return false;
  }
  *solution_ = r.z;
  *z = r.z;
  st_->solver = attempts.back().solver;
  st_->residual = std::max(st_->residual, r.residual);
  return true;
}

} // namespace suite::contact
