// Inverse of the principal block M_FF of an ordered index set F, kept up to date under insertion and
// deletion of one index by bordering / Schur-complement rank-1 formulas (O(|F|^2) per change instead of a
// refactorisation; Cottle, Pang & Stone 2009, sec. 4.1 on principal pivoting and the Schur complement).
// Refactorises from scratch every `refresh` changes to bound the drift.
#pragma once

#include "lcp/problem.hpp"

#include <vector>

namespace suite::lcp {

class ActiveInverse {
public:
  explicit ActiveInverse(const Mat& M, int refresh = 64);
  // Adds index j; returns false (and leaves F unchanged) if the Schur complement is ~0.
  bool add(int j);
  // Removes index j (must be in F); returns false if the pivot of the deletion formula is ~0.
  bool remove(int j);
  int size() const { return static_cast<int>(F_.size()); }
  const std::vector<int>& indices() const { return F_; }
  int position(int j) const { return pos_[j]; }
  // x = M_FF^{-1} b (b ordered like indices()).
  void solve(const Vec& b, Vec* x) const;
  // Last Schur complement of add() (M_jj - M_jF M_FF^{-1} M_Fj).
  double lastSchur() const { return last_schur_; }

private:
  bool refactor();
  const Mat& M_;
  std::vector<int> F_, pos_;
  Mat inv_; // top-left k x k block used
  int changes_ = 0, refresh_;
  double last_schur_ = 0.0;
};

} // namespace suite::lcp
