// Block principal pivoting (Kostreva 1978, "Block pivot methods for solving the complementarity problem")
// with the Judice-Pires safeguard (Judice & Pires 1994, Comput. Oper. Res. 21: infeasibility counter with
// p_bar = 10 tries, then Murty's least-index single pivots until the number of infeasibilities drops), in
// the box form (index at lower bound / upper bound / free). Each block iteration solves
// M_FF z_F = -(q_F + M_FN z_N).
// Symmetric M: the LDL^T factors of M_FF are carried from one iteration to the next (active_ldlt.hpp:
// rank-1 up/down-dates for a few changed indices, a fresh factorisation when many change at once) and
// c = q + M_:N z_N is updated column by column, so an iteration costs O(n |F| + changes |F|^2) instead of
// O(|F|^3 + n^2). Initial sets without a warm start: those of the diagonal (Jacobi) estimate
// z_i = mid(l_i, u_i, -q_i / M_ii) (M_ii > 0; else as initialStates()): on the random box benchmark this
// halves the block iterations compared with starting from z = l (any start terminates with the safeguard).
// Nonsymmetric M, or a principal block whose LDL^T pivot vanishes: a fresh factorisation per
// iteration (Cholesky when symmetric and positive definite, else LU; solver.cpp solveStates). Warm start:
// the initial index sets are read off the given z.
#include "lcp/active_ldlt.hpp"
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
    if (!(opt.warm_start && opt.warm_start->size() == n)) {
      // No warm start: the states of the diagonal (Jacobi) estimate z_i = mid(l_i, u_i, -q_i / M_ii).
      for (int i = 0; i < n; ++i) {
        const double d = p.M(i, i);
        if (!(d > 0.0)) continue;
        const double t = -p.q[i] / d;
        st[i] = t <= p.l[i] ? State::Lower : (t >= p.u[i] ? State::Upper : State::Free);
      }
    }
    int best = n + 1, tries = pbar;
    Vec z(n), w(n), c, x(n);
    std::vector<int> V, F, add, rem;
    V.reserve(n);
    const bool sym = isSymmetric(p);
    // Fast path state: factors of M_FF and c = q + M_:N z_N.
    bool fast = sym;
    ActiveLdlt ldlt(p.M);
    auto bound = [&](int i) { return st[i] == State::Lower ? p.l[i] : p.u[i]; };
    if (fast) {
      Vec zn = Vec::Zero(n);
      F.clear();
      for (int i = 0; i < n; ++i)
        if (st[i] == State::Free)
          F.push_back(i);
        else
          zn[i] = bound(i);
      c = p.M * zn + p.q;
      fast = ldlt.reset(F);
    }
    while (true) {
      if (fast) {
        const auto& FF = ldlt.indices();
        const int k = ldlt.size();
        for (int a = 0; a < k; ++a) x[a] = -c[FF[a]];
        ldlt.solveInPlace(x.data());
        w = c;
        for (int i = 0; i < n; ++i)
          if (st[i] != State::Free) z[i] = bound(i);
        for (int a = 0; a < k; ++a) {
          z[FF[a]] = x[a];
          w.noalias() += x[a] * p.M.col(FF[a]);
        }
        if (!z.allFinite()) fast = false; // numerically singular block: redo this iteration by a fresh solve
      }
      if (!fast) {
        if (!solveStates(p, st, &z, sym)) {
          r.status = Status::Breakdown;
          r.message = "singular principal block M_FF";
          break;
        }
        w.noalias() = p.M * z + p.q;
      }
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
      add.clear();
      rem.clear();
      auto flip = [&](int i) {
        if (st[i] == State::Free) {
          st[i] = z[i] < p.l[i] ? State::Lower : State::Upper;
          rem.push_back(i);
          if (fast) c.noalias() += bound(i) * p.M.col(i);
        } else {
          if (fast) c.noalias() -= bound(i) * p.M.col(i);
          st[i] = State::Free;
          add.push_back(i);
        }
      };
      if (block)
        for (int i : V) flip(i);
      else
        flip(V.front());
      if (fast) {
        const int changes = static_cast<int>(add.size() + rem.size());
        bool ok = true;
        if (changes > 4 + ldlt.size() / 8) { // many changes: one fresh factorisation is cheaper
          F.clear();
          for (int i = 0; i < n; ++i)
            if (st[i] == State::Free) F.push_back(i);
          ok = ldlt.reset(F);
        } else {
          for (int i : rem) ok = ok && ldlt.remove(i);
          for (int i : add) ok = ok && ldlt.add(i);
        }
        fast = ok; // a vanishing LDL^T pivot: continue with fresh factorisations (LU if needed)
      }
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
