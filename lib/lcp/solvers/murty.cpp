// Murty's least-index principal pivoting method (Murty 1974, "Note on a Bard-type scheme for solving the
// complementarity problem"; Cottle, Pang & Stone 2009, sec. 4.2), here in its box form: each index is at its
// lower bound, at its upper bound or free; the least index violating its sign condition is flipped (one
// principal pivot). Finite for P-matrices. M_FF^{-1} is updated by rank-1 bordering formulas
// (active_inverse.hpp). Warm start: the initial index sets are read off the given z.
#include "lcp/active_inverse.hpp"
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

class Murty : public Solver {
public:
  std::string name() const override { return "murty"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const long long cap = opt.max_iterations > 0 ? opt.max_iterations : 100LL * n + 1000;
    const double tol = signTolerance(p);
    Result r;
    std::vector<State> st = initialStates(p, opt.warm_start);
    ActiveInverse inv(p.M);
    for (int i = 0; i < n; ++i)
      if (st[i] == State::Free && !inv.add(i)) st[i] = std::isfinite(p.l[i]) ? State::Lower : State::Upper;
    Vec z(n), w, x;
    while (true) {
      const auto& F = inv.indices();
      const int k = static_cast<int>(F.size());
      for (int i = 0; i < n; ++i)
        if (st[i] != State::Free) z[i] = st[i] == State::Lower ? p.l[i] : p.u[i];
      Vec rhs(k);
      for (int a = 0; a < k; ++a) {
        double s = p.q[F[a]];
        for (int j = 0; j < n; ++j)
          if (st[j] != State::Free) s += p.M(F[a], j) * z[j];
        rhs[a] = -s;
      }
      inv.solve(rhs, &x);
      for (int a = 0; a < k; ++a) z[F[a]] = x[a];
      w = p.M * z + p.q;
      int viol = -1;
      for (int i = 0; i < n && viol < 0; ++i) {
        const double zt = 1e-13 * (1.0 + std::abs(z[i]));
        if ((st[i] == State::Lower && w[i] < -tol) || (st[i] == State::Upper && w[i] > tol) ||
            (st[i] == State::Free && (z[i] < p.l[i] - zt || z[i] > p.u[i] + zt)))
          viol = i;
      }
      if (viol < 0) {
        r.status = Status::Solved;
        break;
      }
      if (r.pivots >= cap) {
        r.status = Status::MaxIterations;
        break;
      }
      bool ok;
      if (st[viol] == State::Free) {
        st[viol] = z[viol] < p.l[viol] ? State::Lower : State::Upper;
        ok = inv.remove(viol);
      } else {
        st[viol] = State::Free;
        ok = inv.add(viol);
      }
      ++r.pivots;
      if (!ok) {
        r.status = Status::Breakdown;
        r.message = "zero principal pivot (matrix not P)";
        break;
      }
      if (!z.allFinite()) {
        r.status = Status::NumericalError;
        break;
      }
    }
    r.z = z;
    r.iterations = static_cast<int>(r.pivots);
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeMurty() {
  return std::make_unique<Murty>();
}

} // namespace suite::lcp
