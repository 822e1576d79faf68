// Sparse symmetric matrices (upper triangle, compressed columns), adjacency graphs, and the ordering metrics:
// bandwidth, profile (envelope), symbolic Cholesky fill nnz(L) and factor flops (elimination tree and row
// subtrees, Liu 1990 "The role of elimination trees in sparse factorization", SIAM J. Matrix Anal. Appl. 11).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace suite::fem {

// Upper triangle incl. diagonal, columns compressed, row indices sorted within a column.
struct SymCsc {
  int n = 0;
  std::vector<int> colptr, rowind;
  std::vector<double> val;
  long long nnzUpper() const { return colptr.empty() ? 0 : colptr.back(); }
};

// Undirected graph in CSR form, no self loops, symmetric (j in adj(i) <=> i in adj(j)).
struct Graph {
  int n = 0;
  std::vector<int> xadj, adj;
  int degree(int v) const { return xadj[v + 1] - xadj[v]; }
};
Graph graphOfMatrix(const SymCsc& A);

// Permutations: perm[new] = old. inverse(perm)[old] = new.
std::vector<int> inversePermutation(const std::vector<int>& perm);
bool isPermutation(const std::vector<int>& perm, int n);
// Node order -> DOF order: the dofs of each node (eq[3*node + c] >= 0 for free dofs) in node order.
std::vector<int> expandToDofs(const std::vector<int>& node_perm, const std::vector<int>& eq, int ndof_free);

// Metrics of the graph's matrix (with diagonal) under perm.
//  bandwidth = max |i - j| over nonzeros a_ij of P A P^T;
//  profile   = sum_i (i - f_i), f_i = min{ j <= i : a_ij != 0 } (lower envelope, diagonal excluded; George &
//  Liu
//              1981, sec. 4.1); the skyline storage is profile + n;
//  nnz_L     = nonzeros of the Cholesky factor L incl. diagonal (no cancellation);
//  flops     = sum_j eta_j (eta_j + 3), eta_j = off-diagonal nonzeros of column j of L (twice George & Liu's
//              multiplicative count); envelope_flops the same for the skyline factorisation (fill =
//              envelope).
struct OrderingMetrics {
  long long bandwidth = 0, profile = 0, nnz_L = 0;
  double flops = 0, envelope_flops = 0;
};
OrderingMetrics computeMetrics(const Graph& g, const std::vector<int>& perm);
long long bandwidthOf(const Graph& g, const std::vector<int>& perm);
long long profileOf(const Graph& g, const std::vector<int>& perm);
// Column counts of L (incl. diagonal) for P A P^T.
std::vector<long long> choleskyColumnCounts(const Graph& g, const std::vector<int>& perm);

// y = A x for the symmetric matrix whose upper triangle is (A pattern, values val).
void symMultiply(const SymCsc& A, const std::vector<double>& val, const double* x, double* y);

} // namespace suite::fem
