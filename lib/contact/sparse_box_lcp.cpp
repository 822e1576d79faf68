// PGS and active-set Newton on the sparse contact box LCP (see sparse_box_lcp.hpp).
#include "contact/sparse_box_lcp.hpp"

#include "contact/body_space_solve.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <memory>

namespace suite::contact {

namespace {
double activeNormInf(const SparseBoxLcp& p, const lcp::Vec& v) {
  double m = 0.0;
  for (int i = 0; i < p.size(); ++i)
    if (p.active(i)) m = std::max(m, std::abs(v[i]));
  return m;
}

// The scale of row i: A_ii, or 1 for a row that moves nothing (no body, no compliance).
double rowScale(const SparseBoxLcp& p, int i) {
  return p.diag[i] > 0 ? p.diag[i] : 1.0;
}

enum class RowState : signed char { Lower, Upper, Free };

// A row's impulse moves its own velocity by A_ii per unit, and every other row's in the pile with it, so
// the impulse that cancels w_i once the coupled rows have adjusted is about w_i (A^-1)_ii, several times
// w_i / A_ii. The states are first read off z - kJumpGain w / A_ii (kJumpGain standing for A_ii (A^-1)_ii,
// a box pile's ~4 to 10): a tangent row at one bound whose velocity has the wrong sign goes straight to the
// other bound when that step crosses the box. When the block exchange stalls (its 3 tries spent) the read
// turns to z - w / A_ii (the row's own Newton step) with a fresh exchange rule: with narrow boxes (mu lambda_n
// small against the impulses) the jump read sends rows from bound to bound. Scaled by A_ii, the reads and the
// residual below do not change when every mass is scaled (z with the masses, w not). Pivots per step on
// pile_grid (1,125 boxes, 20 steps) by the first read's gain: 1: 1,092; 2: 311; 4: 304; 8: 185; 16: 151;
// 32: 145; 100: 108; 1,000: 4,000 and splitting passes at their cap. 8 is about the unscaled read z - w
// at 1 kg boxes; gain 8 without the stall switch fails ContactBlockPgs's narrow-box pyramid.

// States read off z - gain w / A_ii (as lcp::statesFromSolution); inactive rows at their (zero) bound.
std::vector<RowState> readStates(const SparseBoxLcp& p, const lcp::Vec& z, const lcp::Vec& w, double gain) {
  std::vector<RowState> s(p.size(), RowState::Lower);
  for (int i = 0; i < p.size(); ++i) {
    if (!p.active(i)) continue;
    const double t = z[i] - gain * w[i] / rowScale(p, i);
    s[i] = t <= p.l[i] ? RowState::Lower : t >= p.u[i] ? RowState::Upper : RowState::Free;
  }
  return s;
}

bool rowSpaceSolve(const SparseBoxLcp& p, const std::vector<int>& F, const std::vector<int>& pos,
                   const lcp::Vec& rhs, lcp::Vec* x);

// z for the states: z_N at its bounds, A_FF z_F = -(b_F + A_FN z_N) in body space, else by sparse LDL^T.
bool solveFree(const SparseBoxLcp& p, const std::vector<RowState>& s, lcp::Vec* z) {
  const int n = p.size();
  std::vector<int> pos(n, -1), F;
  for (int i = 0; i < n; ++i) {
    if (s[i] == RowState::Free) pos[i] = (int)F.size(), F.push_back(i);
    (*z)[i] = s[i] == RowState::Free ? 0.0 : s[i] == RowState::Lower ? p.l[i] : p.u[i];
  }
  if (F.empty()) return true;
  lcp::Vec t, x;
  sparseResidual(p, *z, &t); // t = A z_N + b (z_F = 0)
  lcp::Vec rhs(F.size());
  for (size_t a = 0; a < F.size(); ++a) rhs[a] = -t[F[a]];
  const bool body =
      p.mass && (p.body ? p.body->solve(F, rhs, &x) : bodySpaceSolve(*p.rows, *p.mass, p.reg, F, rhs, &x));
  if (!body && !rowSpaceSolve(p, F, pos, rhs, &x)) return false;
  for (size_t a = 0; a < F.size(); ++a) (*z)[F[a]] = x[a];
  return true;
}

// A_FF x = rhs by a sparse LDL^T of A_FF (+ refinement).
bool rowSpaceSolve(const SparseBoxLcp& p, const std::vector<int>& F, const std::vector<int>& pos,
                   const lcp::Vec& rhs, lcp::Vec* xp) {
  std::vector<Eigen::Triplet<double>> trip;
  for (size_t a = 0; a < F.size(); ++a) {
    for (SpMat::InnerIterator it(sparseMatrix(*p.sys), F[a]); it; ++it)
      if (pos[it.col()] >= 0) trip.emplace_back((int)a, pos[it.col()], it.value());
  }
  for (size_t a = 0; a < F.size(); ++a) // compliance added to the system's (proximalSolve)
    if (p.reg[F[a]] != p.sys->reg[F[a]]) trip.emplace_back((int)a, (int)a, p.reg[F[a]] - p.sys->reg[F[a]]);
  Eigen::SparseMatrix<double> K(F.size(), F.size());
  K.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
  if (ldlt.info() != Eigen::Success) return false;
  lcp::Vec& x = *xp;
  x = ldlt.solve(rhs);
  for (int k = 0; k < 3; ++k) x += ldlt.solve(rhs - K * x);
  return x.allFinite();
}
// Block principal pivoting's exchange rule with its backup (Judice & Pires 1994): every infeasible row
// changes state while the number of infeasible rows keeps falling (3 tries without a new low allowed), else
// only the last infeasible row (Murty's least-index rule, finite for a positive definite A).
struct ExchangeRule {
  long long best = -1;
  int tries = 3;
  // cur <- the next states from the states read off the exact solve; returns the rows changed.
  long long exchange(const std::vector<RowState>& read, std::vector<RowState>* cur) {
    long long infeasible = 0;
    int last = -1;
    for (size_t i = 0; i < read.size(); ++i)
      if (read[i] != (*cur)[i]) ++infeasible, last = (int)i;
    if (infeasible == 0) return 0;
    if (best < 0 || infeasible < best) {
      best = infeasible, tries = 3;
    } else if (tries == 0) {
      (*cur)[last] = read[last];
      return 1;
    } else {
      --tries;
    }
    *cur = read;
    return infeasible;
  }
};
} // namespace

SparseBoxLcp makeSparseBoxLcp(const DelassusSystem& sys, lcp::Vec l, lcp::Vec u) {
  SparseBoxLcp p;
  p.rows = &sys.rows;
  p.sys = &sys;
  p.nbodies = sys.nbodies;
  p.b = sys.b, p.l = std::move(l), p.u = std::move(u);
  p.reg = sys.reg;
  p.diag.resize(p.size());
  for (int i = 0; i < p.size(); ++i) p.diag[i] = delassusDiagonal(sys, i);
  p.mass = &sys.mass;
  p.link.assign(p.size(), -1);
  p.coef.assign(p.size(), 0.0);
  return p;
}

double sparseTolerance(const SparseBoxLcp& p, double rel_tol) {
  return rel_tol * (1.0 + activeNormInf(p, p.b));
}

double sparseResidual(const SparseBoxLcp& p, const lcp::Vec& z, lcp::Vec* w_out) {
  const V6s u = bodyImpulseVelocities(*p.rows, z, p.nbodies);
  lcp::Vec w(p.size());
  double r = 0.0;
  for (int i = 0; i < p.size(); ++i) {
    w[i] = rowVelocity((*p.rows)[i], u) + p.reg[i] * z[i] + p.b[i];
    if (!p.active(i)) continue;
    const double a = rowScale(p, i);
    const double d = a * std::abs(z[i] - std::clamp(z[i] - w[i] / a, p.lower(i, z), p.upper(i, z)));
    r = std::isnan(d) ? lcp::kInf : std::max(r, d);
  }
  if (w_out) *w_out = std::move(w);
  return r;
}

std::vector<int> heightOrder(const std::vector<Contact>& cs, const Vec3& gravity, int per) {
  std::vector<std::pair<double, int>> key(cs.size()); // (height, index): the stable order by height
  for (size_t i = 0; i < cs.size(); ++i) key[i] = {-gravity.dot(cs[i].p), (int)i};
  std::sort(key.begin(), key.end());
  std::vector<int> rows;
  rows.reserve(cs.size() * per);
  for (const auto& [h, i] : key)
    for (int k = 0; k < per; ++k) rows.push_back(i * per + k);
  return rows;
}

int pgsSweeps(const SparseBoxLcp& p, int max_sweeps, double tol, lcp::Vec* zp) {
  lcp::Vec& z = *zp;
  const std::vector<JRow>& rows = *p.rows;
  V6s u = bodyImpulseVelocities(rows, z, p.nbodies);
  const lcp::Vec& diag = p.diag;
  const int n = p.size();
  int sweep = 0;
  for (double change = lcp::kInf; sweep < max_sweeps && !(change <= tol); ++sweep) {
    change = 0.0;
    for (int k = 0; k < n; ++k) {
      const int j = p.symmetric && sweep % 2 ? n - 1 - k : k; // symmetric: every other sweep backwards
      const int i = p.order.empty() ? j : p.order[j];
      if (!p.active(i) || !(diag[i] > 0)) continue;
      const double w = rowVelocity(rows[i], u) + p.reg[i] * z[i] + p.b[i];
      const double zi = std::clamp(z[i] - w / diag[i], p.lower(i, z), p.upper(i, z));
      const double dz = zi - z[i];
      if (dz == 0.0) continue;
      addRowImpulse(rows[i], dz, &u);
      z[i] = zi;
      change = std::max(change, std::abs(dz));
    }
  }
  return sweep;
}

bool freeStart(const SparseBoxLcp& p, lcp::Vec* z, SparseSolveStats* st) {
  std::vector<RowState> s(p.size(), RowState::Lower);
  for (int i = 0; i < p.size(); ++i)
    if (p.active(i)) s[i] = RowState::Free;
  lcp::Vec cand(p.size());
  ++st->factorizations;
  if (!solveFree(p, s, &cand) || !(sparseResidual(p, cand) < sparseResidual(p, *z))) return false;
  *z = cand;
  return true;
}

bool activeSetSolve(const SparseBoxLcp& p, int max_it, double rel_tol, lcp::Vec* z, SparseSolveStats* st,
                    bool solve_once, double gain) {
  st->tolerance = sparseTolerance(p, rel_tol);
  lcp::Vec w, best = *z;
  st->residual = sparseResidual(p, *z, &w);
  std::vector<RowState> cur = readStates(p, *z, w, gain);
  ExchangeRule rule;
  for (int it = 0; it < max_it && (!(st->residual <= st->tolerance) || (solve_once && it == 0)); ++it) {
    lcp::Vec cand(p.size());
    ++st->factorizations;
    if (!solveFree(p, cur, &cand)) break;
    const double r = sparseResidual(p, cand, &w);
    *z = cand;
    if (r < st->residual || (solve_once && it == 0 && r <= st->tolerance)) st->residual = r, best = cand;
    if (rule.tries == 0 && gain != 1.0) gain = 1.0, rule = ExchangeRule(); // stalled: the standard read
    const std::vector<RowState> next = readStates(p, cand, w, gain);
    const long long changed = rule.exchange(next, &cur);
    if (changed == 0) break; // the states of the exact solve are consistent: nothing left to exchange
    st->pivots += changed;
  }
  *z = best;
  return st->residual <= st->tolerance;
}

namespace {
bool proximalRow(const SparseBoxLcp& p, int i) {
  return p.active(i) && p.link[i] < 0 && std::isfinite(p.l[i]) && std::isfinite(p.u[i]);
}

// The subproblem of proximalSolve for rho: q = p with the compliance rho A_ii added on the box rows (reg,
// diag, and a body-space solver for that compliance when p has masses); q.b is set per step.
struct ProximalProblem {
  SparseBoxLcp q;
  std::unique_ptr<BodySpaceSolver> body;
  ProximalProblem(const SparseBoxLcp& p, double rho) : q(p) {
    for (int i = 0; i < p.size(); ++i) {
      const double r = proximalRow(p, i) ? rho * rowScale(p, i) : 0.0;
      q.reg[i] += r, q.diag[i] += r;
    }
    if (p.mass) body = std::make_unique<BodySpaceSolver>(*p.rows, *p.mass, q.reg), q.body = body.get();
  }
  // b - R z_k, R the added compliance.
  void center(const SparseBoxLcp& p, const lcp::Vec& z) {
    for (int i = 0; i < p.size(); ++i) q.b[i] = p.b[i] - (q.reg[i] - p.reg[i]) * z[i];
  }
};
} // namespace

bool proximalSolve(const SparseBoxLcp& p, const ProximalOptions& o, double rel_tol, lcp::Vec* z,
                   SparseSolveStats* st, int* steps) {
  st->tolerance = sparseTolerance(p, rel_tol);
  st->residual = sparseResidual(p, *z);
  lcp::Vec best = *z, center = *z;
  double rho = o.rho, sub_rho = 0.0, shrink = o.shrink;
  bool any_solved = false;
  std::unique_ptr<ProximalProblem> sub;
  for (int k = 0; k < o.max_steps && !(st->residual <= st->tolerance); ++k) {
    if (rho != sub_rho) sub = std::make_unique<ProximalProblem>(p, rho), sub_rho = rho;
    sub->center(p, center);
    SparseSolveStats ss;
    // from a proximal centre most states are right: the rows' own Newton read (gain 1), not the jump read
    const bool solved = activeSetSolve(sub->q, o.max_factorizations, rel_tol, z, &ss, false, 1.0);
    st->factorizations += ss.factorizations, st->pivots += ss.pivots;
    ++*steps;
    const double r = sparseResidual(p, *z);
    if (r < st->residual) st->residual = r, best = *z;
    if (solved) {
      center = *z, any_solved = true;
      rho = std::max(o.rho_min, rho * shrink);
    } else {
      *z = center; // (a failure at a rho solved before, from another centre, happens: rho grows on)
      rho /= o.shrink;
      if (any_solved) shrink = std::sqrt(shrink);
    }
  }
  *z = best;
  return st->residual <= st->tolerance;
}

} // namespace suite::contact
