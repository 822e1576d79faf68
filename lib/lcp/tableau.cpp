// Dictionary pivoting for complementary pivoting methods; see tableau.hpp.
#include "lcp/tableau.hpp"

#include <algorithm>

namespace suite::lcp {

Tableau::Tableau(const Mat& M, const Vec& q, const Vec* d) : n(static_cast<int>(q.size())) {
  const int nc = d ? n + 1 : n;
  b = q;
  A.resize(n, nc);
  A.leftCols(n) = M;
  if (d) A.col(n) = *d;
  basic.resize(n);
  nonbasic.resize(nc);
  row_of.assign(2 * n + 1, -1);
  col_of.assign(2 * n + 1, -1);
  for (int i = 0; i < n; ++i) {
    basic[i] = i;
    row_of[i] = i;
    nonbasic[i] = n + i;
    col_of[n + i] = i;
  }
  if (d) {
    nonbasic[n] = 2 * n;
    col_of[2 * n] = n;
  }
}

void Tableau::pivot(int r, int c) {
  // y_r = b_r + sum_k A_rk x_k  ->  x_c = (y_r - b_r - sum_{k!=c} A_rk x_k) / A_rc
  const double piv = A(r, c);
  const double inv = 1.0 / piv;
  // new row r
  Eigen::RowVectorXd row = -A.row(r) * inv;
  row[c] = inv;
  const double br = -b[r] * inv;
  // other rows: y_i = b_i + A_ic x_c + ...
  Vec col = A.col(c);
  col[r] = 0.0;
  b += col * br;
  b[r] = br;
  A.noalias() += col * row; // rank-1 update of every column; column c and row r are overwritten below
  A.col(c) = col * inv;
  A.row(r) = row;
  const int yr = basic[r], xc = nonbasic[c];
  basic[r] = xc;
  nonbasic[c] = yr;
  row_of[xc] = r;
  col_of[xc] = -1;
  row_of[yr] = -1;
  col_of[yr] = c;
}

Vec Tableau::zValues() const {
  Vec z = Vec::Zero(n);
  for (int i = 0; i < n; ++i) {
    const int rr = row_of[n + i];
    if (rr >= 0) z[i] = std::max(0.0, b[rr]);
  }
  return z;
}

} // namespace suite::lcp
