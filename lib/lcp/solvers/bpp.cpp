// Block principal pivoting (Kostreva 1978, "Block pivot methods for solving the complementarity problem")
// with the Judice-Pires safeguard (Judice & Pires 1994, Comput. Oper. Res. 21: infeasibility counter with
// p_bar = 10 tries, then Murty's least-index single pivots until the number of infeasibilities drops), in
// the box form (index at lower bound / upper bound / free). Each block iteration solves
// M_FF z_F = -(q_F + M_FN z_N).
// Damped exchanges: a block exchange that did not lower the number of infeasibilities below the best so far
// (one of the counter's p_bar tries) flips only the most violated half of the infeasible indices (violation:
// |w_i| at a bound, the distance to the box when free). Termination is the safeguard's: every improvement
// lowers the best count, and after p_bar tries without one the single pivots (finite for P-matrices) run
// until the next. On ill-conditioned SPD matrices full exchanges oscillate (random_spd n = 100, cond 1e8:
// 11 to 201 iterations, median 175 / 253 us on two seeds of 6 problems; damped: 9 to 23 iterations, 100 to
// 120 us; Lemke ~200 us); where full exchanges improve (box LCPs, better-conditioned SPD) nothing changes
// (the same iteration counts on random_box n = 100, the contact dumps and random_spd n = 100 at cond 1e4).
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

#include <algorithm>
#include <cmath>
#include <utility>

namespace suite::lcp {
namespace {

// One run: the index sets (states), z, w and, on the fast path, the factors of M_FF and c = q + M_:N z_N.
class BppRun {
public:
  BppRun(const Problem& p, const SolverOptions& opt)
      : p_(p), n_(p.size()), cap_(opt.max_iterations > 0 ? opt.max_iterations : 10 * n_ + 100),
        tol_(signTolerance(p)), st_(initialStates(p, opt.warm_start)), z_(n_), w_(n_), x_(n_),
        sym_(isSymmetric(p)), fast_(sym_), ldlt_(p.M) {
    if (!(opt.warm_start && opt.warm_start->size() == n_)) jacobiStates();
    V_.reserve(n_);
    if (fast_) startFast();
  }

  Result solve() {
    while (true) {
      if (!solveBlock()) {
        r_.status = Status::Breakdown;
        r_.message = "singular principal block M_FF";
        break;
      }
      findInfeasible();
      if (V_.empty()) {
        r_.status = Status::Solved;
        break;
      }
      if (r_.iterations >= cap_) {
        r_.status = Status::MaxIterations;
        break;
      }
      const int ninf = static_cast<int>(V_.size());
      const bool improved = ninf < best_;
      const bool block = blockPivot(ninf);
      add_.clear();
      rem_.clear();
      if (!block)
        flip(V_.front());
      else if (improved || ninf == 1)
        for (int i : V_) flip(i);
      else
        flipMostViolatedHalf();
      if (fast_) updateFactors();
      r_.pivots += static_cast<long long>(add_.size() + rem_.size()); // the indices flipped
      ++r_.iterations;
    }
    r_.z = z_;
    return r_;
  }

private:
  static constexpr int kPbar = 10;
  double bound(int i) const { return st_[i] == State::Lower ? p_.l[i] : p_.u[i]; }

  // No warm start: the states of the diagonal (Jacobi) estimate z_i = mid(l_i, u_i, -q_i / M_ii).
  void jacobiStates() {
    for (int i = 0; i < n_; ++i) {
      const double d = p_.M(i, i);
      if (!(d > 0.0)) continue;
      const double t = -p_.q[i] / d;
      st_[i] = t <= p_.l[i] ? State::Lower : (t >= p_.u[i] ? State::Upper : State::Free);
    }
  }

  // Fast path: c = q + M_:N z_N and the factors of M_FF.
  void startFast() {
    Vec zn = Vec::Zero(n_);
    F_.clear();
    for (int i = 0; i < n_; ++i)
      if (st_[i] == State::Free)
        F_.push_back(i);
      else
        zn[i] = bound(i);
    c_ = p_.M * zn + p_.q;
    fast_ = ldlt_.reset(F_);
  }

  // z and w of the current index sets; false if M_FF is singular.
  bool solveBlock() {
    if (fast_) {
      const auto& FF = ldlt_.indices();
      const int k = ldlt_.size();
      for (int a = 0; a < k; ++a) x_[a] = -c_[FF[a]];
      ldlt_.solveInPlace(x_.data());
      w_ = c_;
      for (int i = 0; i < n_; ++i)
        if (st_[i] != State::Free) z_[i] = bound(i);
      for (int a = 0; a < k; ++a) {
        z_[FF[a]] = x_[a];
        w_.noalias() += x_[a] * p_.M.col(FF[a]);
      }
      if (!z_.allFinite()) fast_ = false; // numerically singular block: redo this iteration by a fresh solve
    }
    if (!fast_) {
      if (!solveStates(p_, st_, &z_, sym_)) return false;
      w_.noalias() = p_.M * z_ + p_.q;
    }
    return true;
  }

  // V = the infeasible indices (wrong sign of w at a bound, z outside the box when free).
  void findInfeasible() {
    V_.clear();
    for (int i = 0; i < n_; ++i) {
      const double zt = 1e-13 * (1.0 + std::abs(z_[i]));
      if ((st_[i] == State::Lower && w_[i] < -tol_) || (st_[i] == State::Upper && w_[i] > tol_) ||
          (st_[i] == State::Free && (z_[i] < p_.l[i] - zt || z_[i] > p_.u[i] + zt)))
        V_.push_back(i);
    }
  }

  // The Judice-Pires counter: a block pivot, or (false) Murty's least-index single principal pivot.
  bool blockPivot(int ninf) {
    if (ninf < best_) {
      best_ = ninf;
      tries_ = kPbar;
    } else if (tries_ > 0) {
      --tries_;
    } else {
      return false;
    }
    return true;
  }

  // The damped exchange: the ceil(|V| / 2) most violated infeasible indices (ties: the lower index) flipped.
  void flipMostViolatedHalf() {
    order_.clear();
    for (int i : V_) {
      const double v = st_[i] == State::Free ? std::max(p_.l[i] - z_[i], z_[i] - p_.u[i]) : std::abs(w_[i]);
      order_.emplace_back(-v, i);
    }
    const auto half = order_.begin() + (order_.size() + 1) / 2;
    std::nth_element(order_.begin(), half - 1, order_.end());
    for (auto it = order_.begin(); it != half; ++it) flip(it->second);
  }

  void flip(int i) {
    if (st_[i] == State::Free) {
      st_[i] = z_[i] < p_.l[i] ? State::Lower : State::Upper;
      rem_.push_back(i);
      if (fast_) c_.noalias() += bound(i) * p_.M.col(i);
    } else {
      if (fast_) c_.noalias() -= bound(i) * p_.M.col(i);
      st_[i] = State::Free;
      add_.push_back(i);
    }
  }

  void updateFactors() {
    const int changes = static_cast<int>(add_.size() + rem_.size());
    bool ok = true;
    if (changes > 4 + ldlt_.size() / 8) { // many changes: one fresh factorisation is cheaper
      F_.clear();
      for (int i = 0; i < n_; ++i)
        if (st_[i] == State::Free) F_.push_back(i);
      ok = ldlt_.reset(F_);
    } else {
      for (int i : rem_) ok = ok && ldlt_.remove(i);
      for (int i : add_) ok = ok && ldlt_.add(i);
    }
    fast_ = ok; // a vanishing LDL^T pivot: continue with fresh factorisations (LU if needed)
  }

  const Problem& p_;
  const int n_, cap_;
  const double tol_;
  Result r_;
  std::vector<State> st_;
  int best_ = n_ + 1, tries_ = kPbar;
  Vec z_, w_, c_, x_;
  std::vector<int> V_, F_, add_, rem_;
  std::vector<std::pair<double, int>> order_; // (-violation, index) of the damped exchange
  const bool sym_;
  bool fast_;
  ActiveLdlt ldlt_;
};

class Bpp : public Solver {
public:
  std::string name() const override { return "bpp"; }
  Result run(const Problem& p, const SolverOptions& opt) const override { return BppRun(p, opt).solve(); }
};

} // namespace

std::unique_ptr<Solver> makeBpp() {
  return std::make_unique<Bpp>();
}

} // namespace suite::lcp
