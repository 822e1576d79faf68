// LDL^T factorisation of the principal block M_FF (M symmetric) of an ordered index set F, kept up to date
// when one index is added or removed, O(|F|^2) per change instead of an O(|F|^3) refactorisation:
//   - add j (appended last): bordering, L y = M_Fj, l = D^{-1} y, d = M_jj - y.l (one triangular solve);
//   - remove the index at position p: with L = [L11 0 0; l21 1 0; L31 l32 L33], D = diag(D1, d2, D3), the
//     trailing block of the reduced factor is L33 D3 L33^T + d2 l32 l32^T, a rank-1 update done by
//     Gill, Golub, Murray & Saunders 1974 ("Methods for modifying matrix factorizations", Math. Comp. 28,
//     method C1), no square roots;
//   - refactorisation from scratch (unpivoted LDL^T of the gathered block) after `refresh` changes, or on
//     demand (many changes at once, e.g. a block pivot).
// Unit lower L and D are stored column-major in n x n / n arrays (top-left |F| x |F| used); no allocation per
// change. A pivot |d| <= 1e-13 max(1, |M_jj|) (singular or numerically indefinite block) makes add / refactor
// return false and leaves the set unchanged (refactor: empty).
#pragma once

#include "lcp/problem.hpp"

#include <vector>

namespace suite::lcp {

class ActiveLdlt {
public:
  explicit ActiveLdlt(const Mat& M, int refresh = 64);
  bool add(int j);
  // Removes index j (no-op if absent); false only if the periodic refactorisation failed (set emptied).
  bool remove(int j);
  // Replaces the set by F and factorises M_FF from scratch; false (set emptied) if a pivot is ~0.
  bool reset(const std::vector<int>& F);
  int size() const { return k_; }
  const std::vector<int>& indices() const { return F_; }
  int position(int j) const { return pos_[j]; }
  // x = M_FF^{-1} b (b ordered like indices(); x may alias b).
  void solve(const Vec& b, Vec* x) const;
  // In place on the first size() entries of v.
  void solveInPlace(double* v) const;
  // Smallest |d_i| / max(1, |M_ii|) (a cheap singularity indicator).
  double minPivotRatio() const;

private:
  bool factor();           // from scratch on F_: Cholesky (blocked), else factorIndefinite()
  bool factorIndefinite(); // unpivoted LDL^T (symmetric indefinite blocks with nonzero pivots)
  const Mat& M_;
  int n_, k_ = 0, changes_ = 0, refresh_;
  std::vector<int> F_, pos_;
  Mat L_;
  Vec D_, work_;
};

} // namespace suite::lcp
