// Block principal pivoting (Kostreva 1978, "Block pivot methods for solving the complementarity problem")
// with the Judice-Pires safeguard (Judice & Pires 1994, Comput. Oper. Res. 21: infeasibility counter with
// p_bar = 10 tries, then Murty's least-index single pivots until the number of infeasibilities drops), in
// the box form (index at lower bound / upper bound / free). Each block iteration solves M_FF z_F = -(q_F +
// M_FN z_N) by a fresh factorisation (Cholesky when M is symmetric and M_FF positive definite, else LU). Warm
// start: the initial index sets are read off the given z.
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

class Bpp : public Solver {
public:
  std::string name() const override { return "bpp"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const int cap = opt.max_iterations > 0 ? opt.max_iterations : 10 * n + 100;
    const int pbar = 10;
    const double tol = signTolerance(p);
    Result r;
    std::vector<State> st = initialStates(p, opt.warm_start);
    int best = n + 1, tries = pbar;
    Vec z;
    std::vector<int> V;
    const bool sym = isSymmetric(p.M);
    while (true) {
      if (!solveStates(p, st, &z, sym)) {
        r.status = Status::Breakdown;
        r.message = "singular principal block M_FF";
        break;
      }
      const Vec w = p.M * z + p.q;
      V.clear();
      for (int i = 0; i < n; ++i) {
        const double zt = 1e-13 * (1.0 + std::abs(z[i]));
        if ((st[i] == State::Lower && w[i] < -tol) || (st[i] == State::Upper && w[i] > tol) ||
            (st[i] == State::Free && (z[i] < p.l[i] - zt || z[i] > p.u[i] + zt)))
          V.push_back(i);
      }
      if (V.empty()) {
        r.status = Status::Solved;
        break;
      }
      if (r.iterations >= cap) {
        r.status = Status::MaxIterations;
        break;
      }
      const int ninf = static_cast<int>(V.size());
      bool block = true;
      if (ninf < best) {
        best = ninf;
        tries = pbar;
      } else if (tries > 0) {
        --tries;
      } else {
        block = false; // Murty fallback: least-index single principal pivot
      }
      auto flip = [&](int i) {
        if (st[i] == State::Free)
          st[i] = z[i] < p.l[i] ? State::Lower : State::Upper;
        else
          st[i] = State::Free;
      };
      if (block)
        for (int i : V) flip(i);
      else
        flip(V.front());
      r.pivots += block ? ninf : 1;
      ++r.iterations;
    }
    r.z = z;
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeBpp() {
  return std::make_unique<Bpp>();
}

} // namespace suite::lcp
