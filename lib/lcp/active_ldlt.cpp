// LDL^T up/down-dates of a principal block; see active_ldlt.hpp.
#include "lcp/active_ldlt.hpp"

#include <algorithm>
#include <cmath>

namespace suite::lcp {

ActiveLdlt::ActiveLdlt(const Mat& M, int refresh)
    : M_(M), n_(static_cast<int>(M.rows())), refresh_(refresh), pos_(M.rows(), -1), L_(M.rows(), M.rows()),
      D_(M.rows()), work_(M.rows()) {
  F_.reserve(n_);
}

static inline double pivotScale(double mjj) {
  return 1e-13 * std::max(1.0, std::abs(mjj));
}

bool ActiveLdlt::factor() {
  const int k = k_;
  changes_ = 0;
  if (k == 0) return true;
  {
    // Positive definite block (the common case): Eigen's blocked Cholesky in place, L_c = L D^{1/2}.
    for (int b = 0; b < k; ++b)
      for (int a = b; a < k; ++a) L_(a, b) = M_(F_[a], F_[b]);
    Eigen::Ref<Mat, 0, Eigen::OuterStride<>> A(L_.topLeftCorner(k, k));
    Eigen::LLT<Eigen::Ref<Mat, 0, Eigen::OuterStride<>>> llt(A);
    bool ok = llt.info() == Eigen::Success;
    for (int j = 0; ok && j < k; ++j) {
      const double ljj = L_(j, j);
      const double d = ljj * ljj;
      if (!(d > pivotScale(M_(F_[j], F_[j])))) {
        ok = false;
        break;
      }
      D_[j] = d;
      L_(j, j) = 1.0;
      for (int a = j + 1; a < k; ++a) L_(a, j) /= ljj;
    }
    if (ok) return true;
  }
  return factorIndefinite();
}

bool ActiveLdlt::factorIndefinite() {
  // Unpivoted LDL^T (right-looking, column j of L and d_j from the Schur complement kept in L's lower part).
  const int k = k_;
  for (int b = 0; b < k; ++b)
    for (int a = b; a < k; ++a) L_(a, b) = M_(F_[a], F_[b]);
  for (int j = 0; j < k; ++j) {
    const double d = L_(j, j);
    if (!(std::abs(d) > pivotScale(M_(F_[j], F_[j])))) return false;
    D_[j] = d;
    L_(j, j) = 1.0;
    double* cj = &L_(0, j);
    for (int a = j + 1; a < k; ++a) cj[a] /= d;
    for (int b = j + 1; b < k; ++b) { // trailing update: A_ab -= l_aj d l_bj (lower part)
      const double f = cj[b] * d;
      double* cb = &L_(0, b);
      for (int a = b; a < k; ++a) cb[a] -= cj[a] * f;
    }
  }
  changes_ = 0;
  return true;
}

bool ActiveLdlt::reset(const std::vector<int>& F) {
  for (int j : F_) pos_[j] = -1;
  F_ = F;
  k_ = static_cast<int>(F_.size());
  for (int a = 0; a < k_; ++a) pos_[F_[a]] = a;
  if (factor()) return true;
  for (int j : F_) pos_[j] = -1;
  F_.clear();
  k_ = 0;
  return false;
}

bool ActiveLdlt::add(int j) {
  const int k = k_;
  // y = L^{-1} M_Fj (unit lower forward substitution), l = D^{-1} y, d = M_jj - y.l
  double* y = work_.data();
  for (int a = 0; a < k; ++a) y[a] = M_(F_[a], j);
  for (int b = 0; b < k; ++b) {
    const double yb = y[b];
    const double* cb = &L_(0, b);
    for (int a = b + 1; a < k; ++a) y[a] -= cb[a] * yb;
  }
  double d = M_(j, j);
  for (int a = 0; a < k; ++a) {
    const double la = y[a] / D_[a];
    d -= y[a] * la;
    L_(k, a) = la;
  }
  if (!(std::abs(d) > pivotScale(M_(j, j)))) return false;
  L_(k, k) = 1.0;
  D_[k] = d;
  F_.push_back(j);
  pos_[j] = k;
  ++k_;
  if (++changes_ >= refresh_ && !factor()) {
    // the fresh factorisation disagrees with the updated one (drift): undo the addition
    F_.pop_back();
    pos_[j] = -1;
    --k_;
    return reset(F_) && false;
  }
  return true;
}

bool ActiveLdlt::remove(int j) {
  const int p = pos_[j];
  if (p < 0) return true;
  const int k = k_;
  const int m = k - p - 1; // size of the trailing block
  // z = l32 (rows p+1..k-1 of column p), alpha = d_p: rank-1 update of the trailing block (GGMS method C1)
  double* z = work_.data();
  for (int a = 0; a < m; ++a) z[a] = L_(p + 1 + a, p);
  double alpha = D_[p];
  for (int c = 0; c < m; ++c) {
    const int jc = p + 1 + c;
    const double pz = z[c];
    const double dold = D_[jc];
    const double dnew = dold + alpha * pz * pz;
    const double beta = pz * alpha / dnew;
    alpha = dold * alpha / dnew;
    D_[jc] = dnew;
    double* col = &L_(0, jc);
    for (int a = c + 1; a < m; ++a) {
      z[a] -= pz * col[p + 1 + a];
      col[p + 1 + a] += beta * z[a];
    }
  }
  // delete row p and column p: shift rows p+1.. up in columns < p, and the trailing block up-left by one
  for (int b = 0; b < p; ++b) {
    double* col = &L_(0, b);
    std::copy(col + p + 1, col + k, col + p);
  }
  for (int b = p + 1; b < k; ++b) {
    const double* src = &L_(0, b);
    double* dst = &L_(0, b - 1);
    std::copy(src + b, src + k, dst + b - 1);
    D_[b - 1] = D_[b];
  }
  F_.erase(F_.begin() + p);
  pos_[j] = -1;
  for (int a = p; a < k - 1; ++a) pos_[F_[a]] = a;
  --k_;
  if (++changes_ >= refresh_ && !factor()) return reset({}) && false;
  return true;
}

void ActiveLdlt::solveInPlace(double* v) const {
  const int k = k_;
  for (int b = 0; b < k; ++b) { // L u = v
    const double vb = v[b];
    if (vb == 0.0) continue;
    const double* cb = &L_(0, b);
    for (int a = b + 1; a < k; ++a) v[a] -= cb[a] * vb;
  }
  for (int a = 0; a < k; ++a) v[a] /= D_[a];
  for (int b = k - 1; b >= 0; --b) { // L^T x = u: x_b = u_b - sum_{a>b} l_ab x_a
    const double* cb = &L_(0, b);
    double s = v[b];
    for (int a = b + 1; a < k; ++a) s -= cb[a] * v[a];
    v[b] = s;
  }
}

void ActiveLdlt::solve(const Vec& b, Vec* x) const {
  if (x != &b) *x = b;
  solveInPlace(x->data());
}

double ActiveLdlt::minPivotRatio() const {
  double r = kInf;
  for (int a = 0; a < k_; ++a) r = std::min(r, std::abs(D_[a]) / std::max(1.0, std::abs(M_(F_[a], F_[a]))));
  return r;
}

} // namespace suite::lcp
