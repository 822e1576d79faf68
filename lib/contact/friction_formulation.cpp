// The solver chain of the friction formulations (see friction_formulation.hpp): lcp::solveWithChain with the
// contact library's solvers, the attempts added to the step's statistics.
#include "contact/friction_formulation.hpp"

#include "contact/lemke_rf.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>

namespace suite::contact {

namespace {
// The power of two nearest 1 / max_i M_ii (1 when the diagonal is not positive): an impulse scale of p.
double impulseScale(const lcp::Problem& p) {
  const double d = p.size() > 0 ? p.M.diagonal().maxCoeff() : 0.0;
  if (!(d > 0) || !std::isfinite(d)) return 1.0;
  return std::exp2(std::round(-std::log2(d)));
}

// p with z = s z': M' = s M, the same q, bounds / s.
lcp::Problem inVelocityUnits(const lcp::Problem& p, double s) {
  lcp::Problem q = p;
  q.M *= s;
  q.l /= s;
  q.u /= s;
  return q;
}
} // namespace

bool ChainSolve::solve(const lcp::Problem& p, const std::vector<std::string>& chain, const lcp::Vec* scale,
                       const lcp::Vec* warm, lcp::Vec* z, Units units) {
  if (keep_all_ || problems_->empty())
    problems_->push_back(p);
  else
    problems_->back() = p; // always keep the last one (dumped on failure)
  const double s = units == Units::Impulses ? impulseScale(p) : 1.0;
  if (s != 1.0) {
    const lcp::Vec warm_s = warm ? lcp::Vec(*warm / s) : lcp::Vec();
    if (!solveAsGiven(inVelocityUnits(p, s), chain, scale, warm ? &warm_s : nullptr, z)) return false;
    *z *= s;
    *solution_ = *z;
    return true;
  }
  return solveAsGiven(p, chain, scale, warm, z);
}

bool ChainSolve::solveAsGiven(const lcp::Problem& p, const std::vector<std::string>& chain,
                              const lcp::Vec* scale, const lcp::Vec* warm, lcp::Vec* z) {
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
