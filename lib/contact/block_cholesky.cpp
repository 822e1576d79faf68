// Block sparse Cholesky with 6 x 6 blocks (see block_cholesky.hpp).
#include "contact/block_cholesky.hpp"

#include <algorithm>

namespace suite::contact {

namespace {
using V6d = Eigen::Matrix<double, 6, 1>;

// Column structures of L (rows > k, sorted) from the lower adjacency: struct(L_k) = adj_>k(k) united with
// struct(L_c) \ {k} over the children c of k in the elimination tree (parent(c) = min struct(L_c)).
std::vector<std::vector<int>> columnStructures(int n, const std::vector<std::vector<int>>& adj) {
  std::vector<std::vector<int>> cols(n), children(n);
  std::vector<int> mark(n, -1);
  for (int k = 0; k < n; ++k) {
    std::vector<int>& s = cols[k];
    auto add = [&](int i) {
      if (i > k && mark[i] != k) mark[i] = k, s.push_back(i);
    };
    for (int i : adj[k]) add(i);
    for (int c : children[k])
      for (int i : cols[c]) add(i);
    std::sort(s.begin(), s.end());
    if (!s.empty()) children[s.front()].push_back(k);
  }
  return cols;
}
} // namespace

std::vector<int> BlockCholesky::analyze(int n, const std::vector<std::pair<int, int>>& edges) {
  n_ = n;
  std::vector<std::vector<int>> adj(n);
  for (const auto& [i, j] : edges)
    if (i != j) adj[std::min(i, j)].push_back(std::max(i, j));
  const std::vector<std::vector<int>> cols = columnStructures(n, adj);
  colptr_.assign(n + 1, 0);
  rowidx_.clear();
  for (int k = 0; k < n; ++k) {
    rowidx_.insert(rowidx_.end(), cols[k].begin(), cols[k].end());
    colptr_[k + 1] = (int)rowidx_.size();
  }
  rowptr_.assign(n + 1, 0); // row structure, columns increasing within a row (counting sort by row)
  for (int i : rowidx_) ++rowptr_[i + 1];
  for (int k = 0; k < n; ++k) rowptr_[k + 1] += rowptr_[k];
  rowcol_.resize(rowidx_.size());
  rowent_.resize(rowidx_.size());
  std::vector<int> next(rowptr_.begin(), rowptr_.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int e = colptr_[j]; e < colptr_[j + 1]; ++e)
      rowcol_[next[rowidx_[e]]] = j, rowent_[next[rowidx_[e]]++] = e;
  kd_.assign(n, M6::Zero());
  ko_.assign(rowidx_.size(), M6::Zero());
  ld_.resize(n);
  lo_.resize(rowidx_.size());
  pos_.assign(n, -1);
  std::vector<int> index(edges.size(), -1);
  for (size_t k = 0; k < edges.size(); ++k) {
    const int j = std::min(edges[k].first, edges[k].second), i = std::max(edges[k].first, edges[k].second);
    if (i == j) continue;
    index[k] = (int)(std::lower_bound(rowidx_.begin() + colptr_[j], rowidx_.begin() + colptr_[j + 1], i) -
                     rowidx_.begin());
  }
  return index;
}

void BlockCholesky::setZero() {
  std::fill(kd_.begin(), kd_.end(), M6::Zero());
  std::fill(ko_.begin(), ko_.end(), M6::Zero());
}

bool BlockCholesky::factor() {
  lo_ = ko_;
  for (int k = 0; k < n_; ++k) {
    for (int e = colptr_[k]; e < colptr_[k + 1]; ++e) pos_[rowidx_[e]] = e;
    M6 w = kd_[k];
    for (int r = rowptr_[k]; r < rowptr_[k + 1]; ++r) { // the columns j < k with L_kj != 0
      const int j = rowcol_[r], ekj = rowent_[r];
      const M6 lkjt = lo_[ekj].transpose();
      w.noalias() -= lo_[ekj] * lkjt;
      for (int e = ekj + 1; e < colptr_[j + 1]; ++e) lo_[pos_[rowidx_[e]]].noalias() -= lo_[e] * lkjt;
    }
    const Eigen::LLT<M6> llt(w);
    if (llt.info() != Eigen::Success || !llt.matrixLLT().allFinite()) return false;
    ld_[k] = llt.matrixL().solve(M6::Identity()); // L_kk^-1: fixed-size products from here on
    const M6 inv_t = ld_[k].transpose();
    for (int e = colptr_[k]; e < colptr_[k + 1]; ++e) lo_[e] = lo_[e] * inv_t; // L_ik = W_ik L_kk^-T
  }
  return true;
}

void BlockCholesky::solve(Eigen::VectorXd* xp) const {
  Eigen::VectorXd& x = *xp;
  for (int k = 0; k < n_; ++k) { // L y = x, column by column
    const V6d y = ld_[k] * x.segment<6>(6 * k);
    x.segment<6>(6 * k) = y;
    for (int e = colptr_[k]; e < colptr_[k + 1]; ++e) x.segment<6>(6 * rowidx_[e]).noalias() -= lo_[e] * y;
  }
  for (int k = n_ - 1; k >= 0; --k) { // L^T x = y
    V6d t = x.segment<6>(6 * k);
    for (int e = colptr_[k]; e < colptr_[k + 1]; ++e)
      t.noalias() -= lo_[e].transpose() * x.segment<6>(6 * rowidx_[e]);
    x.segment<6>(6 * k) = ld_[k].transpose() * t;
  }
}

} // namespace suite::contact
