// Sparse Cholesky factorisation K = L L^T of a symmetric positive definite matrix made of 6 x 6 blocks (one
// block row per body: the body-space matrix of body_space_solve.hpp), left-looking over the block columns with
// dense fixed-size 6 x 6 kernels. Each body's 6 unknowns always share their sparsity, so the bodies are the
// supernodes of K: the scalar up-looking factorisation (Eigen's SimplicialLLT) spends its time on index work
// that here is done once per block instead of once per entry.
// Symbolic: the block elimination tree and the column structures of L, struct(L_k) = adj_>k(k) united with
// struct(L_c) \ {k} over the children c of k (Davis, "Direct methods for sparse linear systems", SIAM 2006,
// ch. 4.1-4.2), computed once per pattern; numeric: column k gathers L_kj-scaled updates from the columns j of
// its row structure (left-looking; Ng & Peyton, SIAM J. Sci. Comput. 14 (1993), supernodal left-looking
// Cholesky), then L_kk = chol(W_kk), L_ik = W_ik L_kk^-T; L_kk^-1 is kept, so that every later step is a
// fixed-size 6 x 6 product.
// The block order is the caller's (it orders the bodies, e.g. by AMD on the body graph).
#pragma once

#include <Eigen/Dense>

#include <utility>
#include <vector>

namespace suite::contact {

class BlockCholesky {
public:
  using M6 = Eigen::Matrix<double, 6, 6>;

  // n block rows and columns; edges: the off-diagonal blocks (i, j), i != j, of K's pattern (either triangle,
  // repeats allowed). Returns per edge the index of its block in the lower storage (row max(i, j), column
  // min(i, j)); lower(index) is that block of K, to be filled before factor().
  std::vector<int> analyze(int n, const std::vector<std::pair<int, int>>& edges);
  // K's blocks: diagonal k, and the lower blocks (fill blocks stay zero); setZero() clears them all.
  M6& diag(int k) { return kd_[k]; }
  M6& lower(int index) { return ko_[index]; }
  void setZero();
  // L from K's blocks; false if K is not (numerically) positive definite.
  bool factor();
  // x <- K^-1 x (x of size 6 n, block k at 6 k).
  void solve(Eigen::VectorXd* x) const;
  long long blocksInL() const { return n_ + (long long)rowidx_.size(); }

private:
  int n_ = 0;
  std::vector<int> colptr_, rowidx_; // block column k of L: entries colptr_[k] .. colptr_[k+1]-1, rows > k
  std::vector<int> rowptr_, rowcol_, rowent_; // row structure: row k holds (column rowcol_, entry rowent_)
  std::vector<M6> kd_, ko_;                   // K's blocks in L's layout
  std::vector<M6> ld_, lo_;                   // L's blocks (ld_: lower triangular)
  std::vector<int> pos_;                      // scratch: the entry of row i in the column being factored
};

} // namespace suite::contact
