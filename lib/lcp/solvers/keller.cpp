// Keller's principal pivoting for box LCPs (Keller 1973, "The general quadratic optimization problem";
// bounded Dantzig / van de Panne-Whinston type as in Cottle, Pang & Stone 2009, sec. 4.2 and Baraff 1994):
// indices are processed in order; the driving variable z_r moves toward w_r = 0 while the free set keeps
// w_F = 0, and every blocking event (a free z hitting a bound, a bound's w reaching 0, r reaching w_r = 0 or
// its bound) is one principal pivot. Symmetric M: the LDL^T factors of M_FF are updated by rank-1 formulas
// at every pivot (active_ldlt.hpp: bordering for an added index, a Gill-Golub-Murray-Saunders rank-1 update
// for a removed one; O(|F|^2) per pivot, refactorised every 64 changes). Nonsymmetric M (LDL^T does not
// apply): the inverse of M_FF by rank-1 bordering / Schur-complement formulas (active_inverse.hpp).
// Warm start: unprocessed variables start from the given z (clamped to the box).
#include "lcp/active_inverse.hpp"
#include "lcp/active_ldlt.hpp"
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

// One pivoting run: the state (z, w, the free set in the factor, the states of processed indices) and its
// steps. Index rr is driven until it settles (at a bound with the right sign of w_r, or free with w_r = 0).
template <class Factor> class KellerRun {
public:
  KellerRun(const Problem& p, const SolverOptions& opt, Factor& inv)
      : p_(p), inv_(inv), n_(p.size()), cap_(opt.max_iterations > 0 ? opt.max_iterations : 100LL * n_ + 1000),
        tol_(signTolerance(p)), z_(n_), dw_(n_), st_(n_, State::Free), done_(n_, 0) {
    for (int i = 0; i < n_; ++i) {
      if (opt.warm_start && opt.warm_start->size() == n_)
        z_[i] = std::min(p.u[i], std::max(p.l[i], (*opt.warm_start)[i]));
      else
        z_[i] = std::isfinite(p.l[i]) ? p.l[i] : (std::isfinite(p.u[i]) ? p.u[i] : 0.0);
    }
    r_.status = Status::Solved;
  }

  Result solve() {
    for (int rr = 0; rr < n_ && r_.status == Status::Solved; ++rr) {
      if (rr % kRefresh == 0) { // recompute z_F and w from scratch against the drift of the updates below
        refreshZF();
        w_.noalias() = p_.M * z_ + p_.q;
      }
      drive(rr);
      done_[rr] = 1;
    }
    refreshZF();
    r_.z = z_;
    r_.iterations = static_cast<int>(r_.pivots);
    return r_;
  }

private:
  static constexpr int kRefresh = 16; // driving variables between fresh z_F, w (O(n |F| + n^2) each)
  static constexpr double kEps = 1e-14;
  struct Step {
    double t = kInf;
    int event = -1, who = -1; // 0: w_r -> 0, 1: z_r -> bound, 2: free hits bound, 3: bound's w -> 0
  };

  // z_F = -M_FF^{-1}(q_F + M_FN z_N), N = every index outside the free set.
  void refreshZF() {
    const auto& F = inv_.indices();
    const int k = static_cast<int>(F.size());
    if (k == 0) return;
    Vec rhs(k);
    for (int a = 0; a < k; ++a) {
      double s = p_.q[F[a]];
      for (int j = 0; j < n_; ++j)
        if (inv_.position(j) < 0) s += p_.M(F[a], j) * z_[j];
      rhs[a] = -s;
    }
    inv_.solve(rhs, &x_);
    for (int a = 0; a < k; ++a) z_[F[a]] = x_[a];
  }

  // Pivots until rr settles or the run stops (cap, breakdown).
  void drive(int rr) {
    while (!settled(rr)) {
      if (r_.pivots >= cap_) {
        r_.status = Status::MaxIterations;
        return;
      }
      const double dir = w_[rr] < 0 ? 1.0 : -1.0;
      direction(rr, dir);
      Step s;
      limitDriving(rr, dir, &s);
      limitFree(&s);
      limitBound(&s);
      if (s.event < 0 || !std::isfinite(s.t)) {
        r_.status = Status::Breakdown;
        r_.message = "unbounded driving direction (matrix not P / problem without solution)";
        return;
      }
      if (take(rr, dir, s)) return;
    }
  }

  // rr at a bound with the right sign of w_r, or inside with w_r = 0 (then added to the free set).
  bool settled(int rr) {
    const double wr = w_[rr];
    if (z_[rr] <= p_.l[rr] && wr >= -tol_) {
      st_[rr] = State::Lower;
      return true;
    }
    if (z_[rr] >= p_.u[rr] && wr <= tol_) {
      st_[rr] = State::Upper;
      return true;
    }
    if (std::abs(wr) <= tol_ && z_[rr] > p_.l[rr] && z_[rr] < p_.u[rr]) {
      if (!inv_.add(rr)) {
        r_.status = Status::Breakdown;
        r_.message = "singular principal block";
      }
      st_[rr] = State::Free;
      return true;
    }
    return false;
  }

  // dz_F and dw per unit step of z_r in direction dir (w_F stays 0).
  void direction(int rr, double dir) {
    const auto& F = inv_.indices();
    const int k = static_cast<int>(F.size());
    Vec b(k);
    for (int a = 0; a < k; ++a) b[a] = p_.M(F[a], rr);
    inv_.solve(b, &x_);
    dzF_ = -dir * x_;
    dw_ = dir * p_.M.col(rr);
    for (int a = 0; a < k; ++a) dw_ += dzF_[a] * p_.M.col(F[a]);
  }

  // Step limits, in this order: w_r reaching 0, z_r reaching its bound; then the free and bound sets.
  void limitDriving(int rr, double dir, Step* s) const {
    const double wr = w_[rr];
    if (dw_[rr] * wr < 0.0) *s = Step{-wr / dw_[rr], 0, rr};
    const double tb = dir > 0 ? p_.u[rr] - z_[rr] : z_[rr] - p_.l[rr];
    if (tb < s->t) *s = Step{tb, 1, rr};
  }

  void limitFree(Step* s) const {
    const auto& F = inv_.indices();
    for (int a = 0; a < static_cast<int>(F.size()); ++a) {
      const int i = F[a];
      double t = kInf;
      if (dzF_[a] < -kEps && std::isfinite(p_.l[i]))
        t = std::max(0.0, z_[i] - p_.l[i]) / -dzF_[a];
      else if (dzF_[a] > kEps && std::isfinite(p_.u[i]))
        t = std::max(0.0, p_.u[i] - z_[i]) / dzF_[a];
      if (t < s->t) *s = Step{t, 2, i};
    }
  }

  void limitBound(Step* s) const {
    for (int i = 0; i < n_; ++i) {
      if (!done_[i] || st_[i] == State::Free) continue;
      double t = kInf;
      if (st_[i] == State::Lower && dw_[i] < -kEps)
        t = std::max(0.0, w_[i]) / -dw_[i];
      else if (st_[i] == State::Upper && dw_[i] > kEps)
        t = std::max(0.0, -w_[i]) / dw_[i];
      if (t < s->t) *s = Step{t, 3, i};
    }
  }

  // Takes step s and makes its principal pivot; true when rr is settled or the run stops.
  bool take(int rr, double dir, const Step& s) {
    const auto& F = inv_.indices();
    const int k = static_cast<int>(F.size());
    z_[rr] += dir * s.t;
    for (int a = 0; a < k; ++a) z_[F[a]] += s.t * dzF_[a];
    w_ += s.t * dw_;
    ++r_.pivots;
    bool ok = true;
    if (s.event == 0) {
      w_[rr] = 0.0;
      ok = inv_.add(rr);
      st_[rr] = State::Free;
      if (ok) return true;
    } else if (s.event == 1) {
      z_[rr] = dir > 0 ? p_.u[rr] : p_.l[rr];
      st_[rr] = dir > 0 ? State::Upper : State::Lower;
      return true;
    } else if (s.event == 2) {
      const bool low = dzF_[inv_.position(s.who)] < 0;
      z_[s.who] = low ? p_.l[s.who] : p_.u[s.who];
      st_[s.who] = low ? State::Lower : State::Upper;
      ok = inv_.remove(s.who);
    } else {
      w_[s.who] = 0.0;
      st_[s.who] = State::Free;
      ok = inv_.add(s.who);
    }
    if (ok) return false;
    r_.status = Status::Breakdown;
    r_.message = "singular principal block during pivoting";
    return true;
  }

  const Problem& p_;
  Factor& inv_;
  const int n_;
  const long long cap_;
  const double tol_;
  Result r_;
  Vec z_, w_, x_, dzF_, dw_;
  std::vector<State> st_;
  std::vector<char> done_;
};

class Keller : public Solver {
public:
  std::string name() const override { return "keller"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    if (isSymmetric(p)) {
      ActiveLdlt f(p.M);
      return KellerRun<ActiveLdlt>(p, opt, f).solve();
    }
    ActiveInverse f(p.M);
    return KellerRun<ActiveInverse>(p, opt, f).solve();
  }
};

} // namespace

std::unique_ptr<Solver> makeKeller() {
  return std::make_unique<Keller>();
}

} // namespace suite::lcp
