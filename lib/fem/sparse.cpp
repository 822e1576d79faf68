// Graph utilities and ordering metrics. Symbolic factorisation: elimination tree by Liu's algorithm with path
// compression, then for each row i the row subtree (union of etree paths from the nonzeros a_ik, k < i) marks
// the nonzeros of row i of L (Liu 1990, sec. 3; Davis, Direct Methods for Sparse Linear Systems 2006,
// sec. 4.2).
#include "fem/sparse.hpp"

#include <algorithm>

namespace suite::fem {

Graph graphOfMatrix(const SymCsc& A) {
  Graph g;
  g.n = A.n;
  std::vector<int> deg(A.n, 0);
  for (int c = 0; c < A.n; ++c)
    for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k)
      if (A.rowind[k] != c) ++deg[c], ++deg[A.rowind[k]];
  g.xadj.assign(A.n + 1, 0);
  for (int i = 0; i < A.n; ++i) g.xadj[i + 1] = g.xadj[i] + deg[i];
  g.adj.resize(g.xadj[A.n]);
  std::vector<int> pos(g.xadj.begin(), g.xadj.end() - 1);
  for (int c = 0; c < A.n; ++c)
    for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
      const int r = A.rowind[k];
      if (r == c) continue;
      g.adj[pos[c]++] = r;
      g.adj[pos[r]++] = c;
    }
  for (int i = 0; i < A.n; ++i) std::sort(g.adj.begin() + g.xadj[i], g.adj.begin() + g.xadj[i + 1]);
  return g;
}

std::vector<int> inversePermutation(const std::vector<int>& perm) {
  std::vector<int> inv(perm.size());
  for (size_t i = 0; i < perm.size(); ++i) inv[perm[i]] = static_cast<int>(i);
  return inv;
}

bool isPermutation(const std::vector<int>& perm, int n) {
  if (static_cast<int>(perm.size()) != n) return false;
  std::vector<char> seen(n, 0);
  for (int p : perm) {
    if (p < 0 || p >= n || seen[p]) return false;
    seen[p] = 1;
  }
  return true;
}

std::vector<int> expandToDofs(const std::vector<int>& node_perm, const std::vector<int>& eq, int ndof_free) {
  std::vector<int> p(ndof_free);
  int k = 0;
  for (int node : node_perm) {
    const int* e = eq.data() + 3 * node;
    for (int c = 0; c < 3; ++c)
      if (e[c] >= 0 && k < ndof_free) p[k++] = e[c];
  }
  p.resize(k);
  return p;
}

long long bandwidthOf(const Graph& g, const std::vector<int>& perm) {
  const auto inv = inversePermutation(perm);
  long long b = 0;
  for (int v = 0; v < g.n; ++v)
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k)
      b = std::max<long long>(b, std::abs(inv[v] - inv[g.adj[k]]));
  return b;
}

long long profileOf(const Graph& g, const std::vector<int>& perm) {
  const auto inv = inversePermutation(perm);
  long long p = 0;
  for (int i = 0; i < g.n; ++i) { // new row i = old vertex perm[i]
    int f = i;
    const int v = perm[i];
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) f = std::min(f, inv[g.adj[k]]);
    p += i - f;
  }
  return p;
}

std::vector<long long> choleskyColumnCounts(const Graph& g, const std::vector<int>& perm) {
  const int n = g.n;
  const auto inv = inversePermutation(perm);
  // Lower pattern by rows in the new order: for new row i, the columns k < i.
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int i = 0; i < n; ++i) {
    const int v = perm[i];
    for (int q = g.xadj[v]; q < g.xadj[v + 1]; ++q) {
      int k = inv[g.adj[q]];
      if (k >= i) continue;
      while (k != -1 && k != i) { // climb with path compression
        const int next = ancestor[k];
        ancestor[k] = i;
        if (next == -1) parent[k] = i;
        k = next;
      }
    }
  }
  std::vector<long long> count(n, 1);
  std::vector<int> mark(n, -1);
  for (int i = 0; i < n; ++i) {
    mark[i] = i;
    const int v = perm[i];
    for (int q = g.xadj[v]; q < g.xadj[v + 1]; ++q) {
      int j = inv[g.adj[q]];
      if (j >= i) continue;
      while (mark[j] != i) {
        ++count[j];
        mark[j] = i;
        j = parent[j];
      }
    }
  }
  return count;
}

OrderingMetrics computeMetrics(const Graph& g, const std::vector<int>& perm) {
  OrderingMetrics m;
  m.bandwidth = bandwidthOf(g, perm);
  m.profile = profileOf(g, perm);
  for (long long c : choleskyColumnCounts(g, perm)) {
    m.nnz_L += c;
    const double eta = static_cast<double>(c - 1);
    m.flops += eta * (eta + 3);
  }
  // Skyline: column j of the envelope holds the rows i > j with f_i <= j.
  const auto inv = inversePermutation(perm);
  std::vector<long long> colh(g.n + 1, 0); // difference array of envelope column heights
  for (int i = 0; i < g.n; ++i) {
    int f = i;
    const int v = perm[i];
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) f = std::min(f, inv[g.adj[k]]);
    colh[f] += 1, colh[i] -= 1; // rows i cover columns f..i-1
  }
  long long run = 0;
  for (int j = 0; j < g.n; ++j) {
    run += colh[j];
    const double eta = static_cast<double>(run);
    m.envelope_flops += eta * (eta + 3);
  }
  return m;
}

void symMultiply(const SymCsc& A, const std::vector<double>& val, const double* x, double* y) {
  for (int i = 0; i < A.n; ++i) y[i] = 0;
  for (int c = 0; c < A.n; ++c) {
    double s = 0;
    const double xc = x[c];
    for (int k = A.colptr[c]; k < A.colptr[c + 1]; ++k) {
      const int r = A.rowind[k];
      const double a = val[k];
      s += a * x[r];
      if (r != c) y[r] += a * xc;
    }
    y[c] += s;
  }
}
} // namespace suite::fem
