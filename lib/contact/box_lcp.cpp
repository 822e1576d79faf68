// The box LCP of the contact rows (see box_lcp.hpp).
#include "contact/box_lcp.hpp"

#include "contact/sparse_box_lcp.hpp"

#include <algorithm>
#include <cmath>

namespace suite::contact {

std::vector<ConstraintRow> boxRows(const std::vector<Contact>& cs, bool friction) {
  std::vector<ConstraintRow> rows;
  rows.reserve(cs.size() * (friction ? 3 : 1));
  for (int i = 0; i < (int)cs.size(); ++i) {
    rows.push_back({i, cs[i].n, true});
    if (friction) {
      rows.push_back({i, cs[i].t1, false});
      rows.push_back({i, cs[i].t2, false});
    }
  }
  return rows;
}

std::vector<std::string> boxChain(const StepperOptions& o) {
  std::vector<std::string> names{o.lcp_solver};
  for (const auto& f : o.fallback_solvers)
    if (f != o.lcp_solver) names.push_back(f);
  return names;
}

BoxRows initialBoxRows(const ContactStep& step, int per) {
  BoxRows s;
  s.nc = (int)step.contacts.size();
  s.per = per;
  s.nu.assign(s.nc, 0.0);
  s.full = lcp::Vec::Zero(s.nc * per);
  for (int i = 0; i < s.nc; ++i)
    for (int k = 0; k < per; ++k) s.full[i * per + k] = step.prev[i][k];
  return s;
}

std::vector<double> weightEstimates(const ContactStep& step, const StepperOptions& o) {
  std::vector<int> count(step.bodies.size(), 0);
  for (const Contact& c : step.contacts) ++count[c.a], ++count[c.b];
  std::vector<double> nu;
  for (const Contact& c : step.contacts) {
    double e = 0.0;
    int k = 0;
    for (int id : {c.a, c.b})
      if (!step.bodies[id].is_static) e += step.bodies[id].mass / count[id], ++k;
    nu.push_back(k ? o.gravity.norm() * o.dt * e / k : 0.0);
  }
  return nu;
}

namespace {
// The problem of the active rows (normals, and the tangents with a non-zero bound); warm: their impulses.
lcp::Problem activeProblem(const lcp::Mat& A, const DelassusSystem& sys, double mu, const BoxRows& s,
                           std::vector<int>* active, lcp::Vec* warm) {
  bool any_t = false;
  for (int i = 0; i < s.nc; ++i) {
    active->push_back(i * s.per);
    if (s.per == 3 && mu * s.nu[i] > 0) {
      active->push_back(i * s.per + 1), active->push_back(i * s.per + 2);
      any_t = true;
    }
  }
  const int n = (int)active->size();
  lcp::Mat M(n, n);
  lcp::Vec q(n), l(n), u(n);
  warm->resize(n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) M(r, c) = A((*active)[r], (*active)[c]);
    q[r] = sys.b[(*active)[r]];
    (*warm)[r] = s.full[(*active)[r]];
    const bool normal = (*active)[r] % s.per == 0;
    const double bound = normal ? lcp::kInf : mu * s.nu[(*active)[r] / s.per];
    l[r] = normal ? 0.0 : -bound;
    u[r] = bound;
  }
  return any_t ? lcp::makeBox(M, q, l, u, "contact") : lcp::makeLcp(M, q, "contact");
}
// Sweeps before the sparse active-set solve of an exact pass, and its factorisation cap.
constexpr int kExactSweeps = 20, kRetrySweeps = 500, kExactFactorizations = 20, kRetryFactorizations = 40;

// The pass on the sparse Delassus matrix: PGS sweeps from the warm start, then active-set Newton, the proximal
// active set when that stalls (narrow friction boxes), then more sweeps and active-set Newton again, accepted
// by the chain's rule (residual <= lcp_tol (1 + |b|_inf)); false: not accepted (the dense chain follows).
bool sparsePass(const DelassusSystem& sys, double mu, BoxRows* sp, double rel_tol, lcp::Vec* next,
                StepStats* st) {
  BoxRows& s = *sp; // s.body: created by the step's first pass, kept by the next ones
  const int n = s.nc * s.per;
  lcp::Vec l(n), u(n);
  for (int r = 0; r < n; ++r) {
    const double bound = r % s.per == 0 ? lcp::kInf : mu * s.nu[r / s.per];
    l[r] = r % s.per == 0 ? 0.0 : -bound, u[r] = bound;
  }
  SparseBoxLcp p = makeSparseBoxLcp(sys, l, u);
  if (!s.body) s.body = std::make_shared<BodySpaceSolver>(sys.rows, sys.mass, p.reg); // same reg every pass
  p.body = s.body.get();
  lcp::Vec z = s.full.cwiseMax(l).cwiseMin(u);
  SparseSolveStats ss;
  // the sweeps only from a poor start (scaled residual above 1e-2 (1 + |b|): about 1e-3 on the
  // unscaled residual at 1 kg boxes, A_ii 4 to 8 kg^-1); the answer always from at least one exact solve
  const double poor = 1e-2 * (1.0 + p.b.lpNorm<Eigen::Infinity>());
  if (!(sparseResidual(p, z) <= poor)) freeStart(p, &z, &ss);
  if (!(sparseResidual(p, z) <= poor)) ss.sweeps = pgsSweeps(p, kExactSweeps, 0.0, &z);
  bool ok = activeSetSolve(p, kExactFactorizations, rel_tol, &z, &ss, true);
  if (!ok) ok = proximalSolve(p, ProximalOptions{}, rel_tol, &z, &ss, &st->proximal_steps); // narrow boxes
  if (!ok) { // a second try from a closer start: many more (cheap) sweeps
    ss.sweeps += pgsSweeps(p, kRetrySweeps, 0.0, &z);
    ok = activeSetSolve(p, kRetryFactorizations, rel_tol, &z, &ss, true);
  }
  st->iterations += ss.sweeps + ss.factorizations;
  st->pivots += ss.pivots;
  st->factorizations += ss.factorizations;
  st->fallbacks += !ok;
  if (!ok) return false;
  st->solver = "sparse_active_set";
  st->residual = std::max(st->residual, ss.residual);
  int rows = 0;
  for (int r = 0; r < n; ++r) rows += p.active(r);
  st->rows = rows;
  *next = z;
  return true;
}

// The pass on the dense Delassus matrix through the solver chain.
bool densePass(const DelassusSystem& sys, double mu, const std::vector<std::string>& chain, const BoxRows& s,
               ChainSolve& solver, lcp::Vec* next, StepStats* st) {
  std::vector<int> active;
  lcp::Vec warm, z;
  const lcp::Problem p = sys.sparse ? activeProblem(denseDelassus(sys), sys, mu, s, &active, &warm)
                                    : activeProblem(sys.A, sys, mu, s, &active, &warm);
  if (!solver.solve(p, chain, nullptr, &warm, &z, ChainSolve::Units::Impulses)) return false;
  st->rows = (int)active.size();
  *next = lcp::Vec::Zero(s.nc * s.per);
  for (size_t r = 0; r < active.size(); ++r) (*next)[active[r]] = z[r];
  return true;
}
} // namespace

bool solveBoxPass(const DelassusSystem& sys, double mu, const std::vector<std::string>& chain, bool first,
                  ChainSolve& solver, BoxRows* s, double* err, double* nmax, StepStats* st) {
  lcp::Vec next;
  const bool sparse_ok = sys.sparse && sparsePass(sys, mu, s, solver.options().lcp_tol, &next, st);
  if (!sparse_ok && !densePass(sys, mu, chain, *s, solver, &next, st)) return false;
  *err = 0.0, *nmax = 0.0;
  if (s->an.empty()) // the diagonals do not change from pass to pass
    for (int i = 0; i < s->nc; ++i) s->an.push_back(delassusDiagonal(sys, i * s->per));
  const std::vector<double>& an = s->an;
  for (int i = 0; i < s->nc; ++i) {
    *err = std::max(*err, an[i] * std::abs(next[i * s->per] - (first ? 0.0 : s->full[i * s->per])));
    *nmax = std::max(*nmax, an[i] * std::abs(next[i * s->per]));
  }
  s->full = next;
  return true;
}

std::vector<double> stickingEstimates(const DelassusSystem& sys, int nc, int per) {
  const int n = nc * per;
  const lcp::Vec l = lcp::Vec::Constant(n, -lcp::kInf), u = lcp::Vec::Constant(n, lcp::kInf);
  const SparseBoxLcp q = makeSparseBoxLcp(sys, l, u);
  lcp::Vec z = lcp::Vec::Zero(n);
  SparseSolveStats st;
  std::vector<double> nu(nc, 0.0);
  if (!freeStart(q, &z, &st)) return nu;
  for (int i = 0; i < nc; ++i) nu[i] = std::max(0.0, z[i * per]);
  return nu;
}

void boxImpulses(const BoxRows& s, Impulses* out) {
  out->z = s.full;
  out->lambda.assign(s.nc, Vec3::Zero());
  for (int i = 0; i < s.nc; ++i)
    for (int k = 0; k < s.per; ++k) out->lambda[i][k] = s.full[i * s.per + k];
}

bool solveSingleBoxPass(const ContactStep& step, const DelassusSystem& sys, int per, std::vector<double> nu,
                        double mu, const std::vector<std::string>& chain, ChainSolve& solver, Impulses* out,
                        StepStats* st) {
  BoxRows s = initialBoxRows(step, per);
  s.nu = std::move(nu);
  double err = 0.0, nmax = 0.0;
  if (!solveBoxPass(sys, mu, chain, true, solver, &s, &err, &nmax, st)) return false;
  st->splitting_iterations = 1;
  st->splitting_error = err;
  boxImpulses(s, out);
  return true;
}

} // namespace suite::contact
