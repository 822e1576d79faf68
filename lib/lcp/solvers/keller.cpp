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

class Keller : public Solver {
public:
  std::string name() const override { return "keller"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    if (isSymmetric(p)) {
      ActiveLdlt f(p.M);
      return pivot(p, opt, f);
    }
    ActiveInverse f(p.M);
    return pivot(p, opt, f);
  }

private:
  static constexpr int kRefresh = 16; // driving variables between fresh z_F, w (O(n |F| + n^2) each)
  template <class Factor> static Result pivot(const Problem& p, const SolverOptions& opt, Factor& inv) {
    const int n = p.size();
    const long long cap = opt.max_iterations > 0 ? opt.max_iterations : 100LL * n + 1000;
    const double tol = signTolerance(p);
    Result r;
    Vec z(n);
    for (int i = 0; i < n; ++i) {
      if (opt.warm_start && opt.warm_start->size() == n)
        z[i] = std::min(p.u[i], std::max(p.l[i], (*opt.warm_start)[i]));
      else
        z[i] = std::isfinite(p.l[i]) ? p.l[i] : (std::isfinite(p.u[i]) ? p.u[i] : 0.0);
    }
    std::vector<State> st(n, State::Free);
    std::vector<char> done(n, 0);
    Vec w, x, dzF, dw(n);
    r.status = Status::Solved;
    auto refreshZF = [&]() { // z_F = -M_FF^{-1}(q_F + M_FN z_N), N = every index outside the free set
      const auto& F = inv.indices();
      const int k = static_cast<int>(F.size());
      if (k == 0) return;
      Vec rhs(k);
      for (int a = 0; a < k; ++a) {
        double s = p.q[F[a]];
        for (int j = 0; j < n; ++j)
          if (inv.position(j) < 0) s += p.M(F[a], j) * z[j];
        rhs[a] = -s;
      }
      inv.solve(rhs, &x);
      for (int a = 0; a < k; ++a) z[F[a]] = x[a];
    };
    for (int rr = 0; rr < n && r.status == Status::Solved; ++rr) {
      if (rr % kRefresh == 0) { // recompute z_F and w from scratch against the drift of the updates below
        refreshZF();
        w.noalias() = p.M * z + p.q;
      }
      while (true) {
        const double wr = w[rr];
        if (z[rr] <= p.l[rr] && wr >= -tol) {
          st[rr] = State::Lower;
          break;
        }
        if (z[rr] >= p.u[rr] && wr <= tol) {
          st[rr] = State::Upper;
          break;
        }
        if (std::abs(wr) <= tol && z[rr] > p.l[rr] && z[rr] < p.u[rr]) {
          if (!inv.add(rr)) {
            r.status = Status::Breakdown;
            r.message = "singular principal block";
          }
          st[rr] = State::Free;
          break;
        }
        if (r.pivots >= cap) {
          r.status = Status::MaxIterations;
          break;
        }
        const double dir = wr < 0 ? 1.0 : -1.0;
        const auto& F = inv.indices();
        const int k = static_cast<int>(F.size());
        Vec b(k);
        for (int a = 0; a < k; ++a) b[a] = p.M(F[a], rr);
        inv.solve(b, &x);
        dzF = -dir * x;
        dw = dir * p.M.col(rr);
        for (int a = 0; a < k; ++a) dw += dzF[a] * p.M.col(F[a]);
        // step limits
        double tbest = kInf;
        int event = -1, who = -1; // 0: w_r -> 0, 1: z_r -> bound, 2: free hits bound, 3: bound's w -> 0
        if (dw[rr] * wr < 0.0) {
          tbest = -wr / dw[rr];
          event = 0;
          who = rr;
        }
        const double tb = dir > 0 ? p.u[rr] - z[rr] : z[rr] - p.l[rr];
        if (tb < tbest) {
          tbest = tb;
          event = 1;
          who = rr;
        }
        const double eps = 1e-14;
        for (int a = 0; a < k; ++a) {
          const int i = F[a];
          double t = kInf;
          if (dzF[a] < -eps && std::isfinite(p.l[i]))
            t = std::max(0.0, z[i] - p.l[i]) / -dzF[a];
          else if (dzF[a] > eps && std::isfinite(p.u[i]))
            t = std::max(0.0, p.u[i] - z[i]) / dzF[a];
          if (t < tbest) {
            tbest = t;
            event = 2;
            who = i;
          }
        }
        for (int i = 0; i < n; ++i) {
          if (!done[i] || st[i] == State::Free) continue;
          double t = kInf;
          if (st[i] == State::Lower && dw[i] < -eps)
            t = std::max(0.0, w[i]) / -dw[i];
          else if (st[i] == State::Upper && dw[i] > eps)
            t = std::max(0.0, -w[i]) / dw[i];
          if (t < tbest) {
            tbest = t;
            event = 3;
            who = i;
          }
        }
        if (event < 0 || !std::isfinite(tbest)) {
          r.status = Status::Breakdown;
          r.message = "unbounded driving direction (matrix not P / problem without solution)";
          break;
        }
        z[rr] += dir * tbest;
        for (int a = 0; a < k; ++a) z[F[a]] += tbest * dzF[a];
        w += tbest * dw;
        ++r.pivots;
        bool ok = true;
        if (event == 0) {
          w[rr] = 0.0;
          ok = inv.add(rr);
          st[rr] = State::Free;
          if (ok) break;
        } else if (event == 1) {
          z[rr] = dir > 0 ? p.u[rr] : p.l[rr];
          st[rr] = dir > 0 ? State::Upper : State::Lower;
          break;
        } else if (event == 2) {
          const bool low = dzF[inv.position(who)] < 0;
          z[who] = low ? p.l[who] : p.u[who];
          st[who] = low ? State::Lower : State::Upper;
          ok = inv.remove(who);
        } else {
          w[who] = 0.0;
          st[who] = State::Free;
          ok = inv.add(who);
        }
        if (!ok) {
          r.status = Status::Breakdown;
          r.message = "singular principal block during pivoting";
          break;
        }
      }
      done[rr] = 1;
    }
    refreshZF();
    r.z = z;
    r.iterations = static_cast<int>(r.pivots);
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeKeller() {
  return std::make_unique<Keller>();
}

} // namespace suite::lcp
