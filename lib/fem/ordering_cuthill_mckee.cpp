// Cuthill-McKee (Cuthill & McKee 1969) and reverse Cuthill-McKee (George 1971) orderings exactly as SPARSEPAK's
// GENRCM, FNROOT, ROOTLS, RCM and DEGREE compute them (George & Liu 1981, "Computer Solution of Large Sparse
// Positive Definite Systems", ch. 4):
//  - GENRCM: nodes 0..n-1 in input order; each node not yet numbered starts its component: FNROOT from it,
//    then RCM from the root found, the component numbered after the earlier ones (and reversed on its own).
//  - FNROOT: level structure (ROOTLS: breadth first, each level in discovery order, neighbours in adjacency
//    order) of the root; unless it has one level or is a chain, the first node of minimum degree in its last
//    level becomes the candidate; if the candidate's structure is deeper, repeat from it, else stop. The
//    candidate is the root returned in both cases (SPARSEPAK overwrites ROOT before the test).
//  - RCM: breadth first from the root, the unnumbered neighbours of each node appended in adjacency order,
//    then sorted by increasing degree (linear insertion: stable, ties keep the adjacency order, which is by
//    increasing node number since Graph's lists are sorted); the component's order reversed (CM: not).
//  Degrees are within the component (DEGREE; diagonal excluded).
// No guard: rcm and cm are these orderings exactly, also where the input order has a smaller bandwidth or
// profile (of the Harwell-Boeing matrices in ../shared/data/matrices: rcm on bcsstk04, bcsstk06 and bcsstk09);
// choosing between them and the input order is the `auto` ordering's job (ordering_auto.cpp).
// tests/reorder/test_reorder_sparsepak.py checks every matrix against an independent transcription of SPARSEPAK.
// Cost: FNROOT's searches are plain breadth-first searches (a typical mesh: two or three), then one
// Cuthill-McKee traversal from the root found. No allocation inside the searches.
#include "fem/ordering.hpp"

#include <algorithm>
#include <climits>

namespace suite::fem {
namespace {

constexpr int kMasked = INT_MAX; // outside the subgraph (pseudoPeripheralNode's mask)

struct Work {
  // mark[v] >= base: visited by the current search (by the CM traversal: at position mark[v] - base);
  // kMasked: outside the subgraph, never visited.
  std::vector<int> mark, deg, bfs, fresh;
  int base = 0;
  explicit Work(const Graph& g) : mark(g.n, 0), deg(g.n), bfs(g.n) {
    int maxdeg = 0;
    for (int v = 0; v < g.n; ++v) deg[v] = g.degree(v), maxdeg = std::max(maxdeg, deg[v]);
    fresh.resize(maxdeg + 1);
  }
  // A new search: the marks of all earlier searches are below the new base.
  void newSearch() {
    const int n = static_cast<int>(mark.size());
    if (base > INT_MAX - 2 * (n + 1)) { // rare: restart the numbering
      for (int& m : mark)
        if (m != kMasked) m = 0;
      base = 0;
    }
    base += n + 1;
  }
};

// SPARSEPAK RCM before its reversal: Cuthill-McKee traversal of the unvisited vertices reachable from root
// into out[0..size): breadth first, the new neighbours of a vertex appended by increasing degree (stable
// insertion sort). Returns size.
int cmTraversal(const Graph& g, int root, Work& w, int* out) {
  w.newSearch();
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  const int* deg = w.deg.data();
  int* mark = w.mark.data();
  int* nb = w.fresh.data();
  const int base = w.base;
  int head = 0, tail = 0;
  out[tail++] = root;
  mark[root] = base;
  for (; head < tail; ++head) {
    const int v = out[head];
    int cnt = 0;
    for (int k = xadj[v], k1 = xadj[v + 1]; k < k1; ++k) {
      const int u = adj[k];
      if (mark[u] < base) mark[u] = base, nb[cnt++] = u; // kMasked is never < base
    }
    for (int i = 1; i < cnt; ++i) { // stable insertion sort of the few new neighbours by degree
      const int u = nb[i], du = deg[u];
      int j = i;
      for (; j > 0 && deg[nb[j - 1]] > du; --j) nb[j] = nb[j - 1];
      nb[j] = u;
    }
    for (int i = 0; i < cnt; ++i) out[tail++] = nb[i];
  }
  return tail;
}

struct Levels {
  int nlev = 0, size = 0, last_level = 0; // levels, vertices, start of the last level in w.bfs
};

// SPARSEPAK ROOTLS: breadth-first search from root over the unvisited (unmasked) vertices into w.bfs, each
// level in discovery order (adjacency order, no sorting).
Levels rootedLevels(const Graph& g, int root, Work& w) {
  w.newSearch();
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  int* mark = w.mark.data();
  int* q = w.bfs.data();
  const int base = w.base;
  Levels ls;
  int head = 0, tail = 0;
  q[tail++] = root;
  mark[root] = base;
  while (head < tail) {
    ls.last_level = head;
    ++ls.nlev;
    for (const int end = tail; head < end; ++head) {
      const int v = q[head];
      for (int k = xadj[v], k1 = xadj[v + 1]; k < k1; ++k) {
        const int u = adj[k];
        if (mark[u] < base) mark[u] = base, q[tail++] = u; // kMasked is never < base
      }
    }
  }
  ls.size = tail;
  return ls;
}

// Degree of v within the subgraph (masked vertices excluded when a mask is in use).
int subDegree(const Graph& g, const Work& w, int v, bool masked) {
  if (!masked) return w.deg[v];
  int d = 0;
  for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) d += w.mark[g.adj[k]] != kMasked ? 1 : 0;
  return d;
}

// SPARSEPAK FNROOT: from root, the first vertex of minimum degree in the last level of the level structure is
// the candidate; repeat from it while its structure is deeper. Returns the last candidate (or root, when its
// structure has one level or is a chain).
int findRoot(const Graph& g, int root, Work& w, bool masked) {
  Levels ls = rootedLevels(g, root, w);
  if (ls.nlev == 1 || ls.nlev == ls.size) return root;
  for (;;) {
    int bestdeg = INT_MAX;
    for (int q = ls.last_level; q < ls.size; ++q) {
      const int d = subDegree(g, w, w.bfs[q], masked);
      if (d < bestdeg) bestdeg = d, root = w.bfs[q];
    }
    const Levels c = rootedLevels(g, root, w);
    if (c.nlev <= ls.nlev || c.nlev >= c.size) return root;
    ls = c;
  }
}

// SPARSEPAK GENRCM (reverse) or its Cuthill-McKee order: components one after the other, each reversed on its
// own if reverse.
std::vector<int> cuthillMcKee(const Graph& g, bool reverse) {
  std::vector<int> order(g.n);
  if (g.n == 0) return order;
  Work w(g);
  std::vector<char> numbered; // only for graphs of several components
  int pos = 0;
  for (int v = 0; v < g.n && pos < g.n; ++v) {
    if (pos > 0 && numbered[v]) continue;
    int* seg = order.data() + pos;
    const int size = cmTraversal(g, findRoot(g, v, w, false), w, seg);
    if (reverse) std::reverse(seg, seg + size);
    pos += size;
    if (pos < g.n) {
      if (numbered.empty()) numbered.assign(g.n, 0);
      for (int i = 0; i < size; ++i) numbered[seg[i]] = 1;
    }
  }
  return order;
}

} // namespace

int pseudoPeripheralNode(const Graph& g, int root, const std::vector<char>& mask) {
  Work w(g);
  for (int v = 0; v < g.n; ++v)
    if (!mask[v]) w.mark[v] = kMasked;
  return findRoot(g, root, w, true);
}

std::vector<int> orderCuthillMcKee(const Graph& g) {
  return cuthillMcKee(g, false);
}

std::vector<int> orderReverseCuthillMcKee(const Graph& g) {
  return cuthillMcKee(g, true);
}

} // namespace suite::fem
