// Rank-1 (bordering) updates of the inverse of a principal block; see active_inverse.hpp.
#include "lcp/active_inverse.hpp"

#include <cmath>

namespace suite::lcp {

ActiveInverse::ActiveInverse(const Mat& M, int refresh)
    : M_(M), pos_(M.rows(), -1), inv_(M.rows(), M.rows()), refresh_(refresh) {}

bool ActiveInverse::refactor() {
  const int k = size();
  if (k == 0) return true;
  Mat A(k, k);
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) A(a, b) = M_(F_[a], F_[b]);
  Eigen::PartialPivLU<Mat> lu(A);
  if (!(lu.rcond() > 1e-14)) return false;
  inv_.topLeftCorner(k, k) = lu.inverse();
  changes_ = 0;
  return true;
}

bool ActiveInverse::add(int j) {
  const int k = size();
  const double scale = std::max(1.0, std::abs(M_(j, j)));
  if (k == 0) {
    last_schur_ = M_(j, j);
    if (!(std::abs(last_schur_) > 1e-13 * scale)) return false;
    inv_(0, 0) = 1.0 / last_schur_;
  } else {
    Vec b(k), c(k);
    for (int a = 0; a < k; ++a) {
      b[a] = M_(F_[a], j);
      c[a] = M_(j, F_[a]);
    }
    const auto Ai = inv_.topLeftCorner(k, k);
    Vec u = Ai * b;             // A^{-1} b
    Vec v = Ai.transpose() * c; // (c^T A^{-1})^T
    const double s = M_(j, j) - c.dot(u);
    last_schur_ = s;
    if (!(std::abs(s) > 1e-13 * std::max(scale, b.lpNorm<Eigen::Infinity>() * u.lpNorm<Eigen::Infinity>())))
      return false;
    inv_.topLeftCorner(k, k).noalias() += (u / s) * v.transpose();
    inv_.block(0, k, k, 1) = -u / s;
    inv_.block(k, 0, 1, k) = -v.transpose() / s;
    inv_(k, k) = 1.0 / s;
  }
  pos_[j] = k;
  F_.push_back(j);
  if (++changes_ >= refresh_) return refactor() || true;
  return true;
}

bool ActiveInverse::remove(int j) {
  const int k = size();
  const int p = pos_[j];
  if (p < 0) return false;
  const int last = k - 1;
  if (p != last) { // move j to the last position
    inv_.row(p).head(k).swap(inv_.row(last).head(k));
    inv_.col(p).head(k).swap(inv_.col(last).head(k));
    std::swap(F_[p], F_[last]);
    pos_[F_[p]] = p;
  }
  const double h = inv_(last, last);
  if (!(std::abs(h) > 1e-300)) return false;
  if (last > 0) {
    Vec f = inv_.block(0, last, last, 1);
    Vec g = inv_.block(last, 0, 1, last).transpose();
    inv_.topLeftCorner(last, last).noalias() -= (f / h) * g.transpose();
  }
  F_.pop_back();
  pos_[j] = -1;
  if (++changes_ >= refresh_) refactor();
  return true;
}

void ActiveInverse::solve(const Vec& b, Vec* x) const {
  const int k = size();
  *x = inv_.topLeftCorner(k, k) * b;
}

} // namespace suite::lcp
