// The sparse Delassus matrix and the matrix-free operator (see delassus_sparse.hpp).
#include "contact/delassus_sparse.hpp"

namespace suite::contact {

double rowCoupling(const JRow& R, const JRow& Q) {
  double v = 0.0;
  if (R.ba >= 0 && R.ba == Q.ba) v += R.ja.dot(Q.ma);
  if (R.ba >= 0 && R.ba == Q.bb) v += R.ja.dot(Q.mb);
  if (R.bb >= 0 && R.bb == Q.ba) v += R.jb.dot(Q.ma);
  if (R.bb >= 0 && R.bb == Q.bb) v += R.jb.dot(Q.mb);
  return v;
}

namespace {

// The rows at each body (each row at most once per body), in increasing row order.
std::vector<std::vector<int>> rowsAtBodies(const std::vector<JRow>& rows, int nbodies) {
  std::vector<std::vector<int>> at(nbodies);
  for (int r = 0; r < (int)rows.size(); ++r) {
    if (rows[r].ba >= 0) at[rows[r].ba].push_back(r);
    if (rows[r].bb >= 0 && rows[r].bb != rows[r].ba) at[rows[r].bb].push_back(r);
  }
  return at;
}
} // namespace

std::vector<Eigen::Triplet<double>> delassusTriplets(const std::vector<JRow>& rows, int nbodies,
                                                     const std::vector<double>& diag_scale, bool lower) {
  const int n = (int)rows.size();
  const std::vector<std::vector<int>> at = rowsAtBodies(rows, nbodies);
  std::vector<int> mark(n, -1), cols; // mark[q] == r: q already a column of row r
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < n; ++r) {
    cols.clear();
    for (int b : {rows[r].ba, rows[r].bb})
      if (b >= 0)
        for (int q : at[b])
          if (mark[q] != r && (!lower || q >= r)) mark[q] = r, cols.push_back(q);
    for (int q : cols) {
      const int i = lower ? q : r, j = lower ? r : q; // lower: the entry (q, r), q >= r
      double v = rowCoupling(rows[i], rows[j]);
      if (q == r) v *= 1.0 + diag_scale[r];
      t.emplace_back(i, j, v);
    }
  }
  return t;
}

SpMat sparseDelassus(const std::vector<JRow>& rows, int nbodies, const std::vector<double>& diag_scale) {
  const std::vector<Eigen::Triplet<double>> t = delassusTriplets(rows, nbodies, diag_scale, false);
  SpMat A((Eigen::Index)rows.size(), (Eigen::Index)rows.size());
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

V6s bodyImpulseVelocities(const std::vector<JRow>& rows, const lcp::Vec& z, int nbodies) {
  V6s u(nbodies, V6::Zero());
  for (size_t r = 0; r < rows.size(); ++r) addRowImpulse(rows[r], z[r], &u);
  return u;
}

} // namespace suite::contact
