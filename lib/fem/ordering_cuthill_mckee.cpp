// Cuthill-McKee (Cuthill & McKee 1969) and reverse Cuthill-McKee (George 1971) orderings: breadth-first
// search from a pseudo-peripheral node (George & Liu 1979, SPARSEPAK FNROOT/RCM; George & Liu 1981, ch. 4),
// neighbours visited by increasing degree, each connected component in turn. Never worse than the input order
// in profile.
// Cost, one pass over the edges per search and no allocation inside the searches (work arrays once per call):
// the first search of FNROOT is itself the Cuthill-McKee traversal from the start node (a CM order is a BFS:
// same levels), which also accumulates the profiles of the CM, RCM and input orders on the way (the
// never-worse guard needs no extra pass); the searches that only check a candidate root are plain BFS. A
// typical mesh takes two passes (CM from the start node, BFS from the candidate: no more levels, keep the
// start node) instead of three plus the guard's pass.
#include "fem/ordering.hpp"

#include <algorithm>
#include <climits>

namespace suite::fem {
namespace {

constexpr int kMasked = INT_MAX; // outside the subgraph (pseudoPeripheralNode's mask)

struct Traversal {
  int size = 0, nlev = 0, last_level = 0; // vertices, levels, start of the last level in the order
  long long prof_cm = 0, prof_rcm = 0, prof_nat = 0;
};

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

// Cuthill-McKee traversal of the unvisited vertices reachable from root into out[0..size): BFS levels (a
// level is what the expansion of the previous one appended), the new neighbours of a vertex appended by
// increasing degree (stable: ties keep the adjacency order). Profiles on the way: row p of the CM order starts
// at the smallest position among its neighbours, row n-1-p of the reversed order at the largest (all
// neighbours are numbered once p is expanded; kReverse: this one, else the CM one), input row v at its
// smallest neighbour id.
template <bool kWithMask, bool kReverse> Traversal cmTraversal(const Graph& g, int root, Work& w, int* out) {
  w.newSearch();
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  const int* deg = w.deg.data();
  int* mark = w.mark.data();
  int* nb = w.fresh.data();
  const int base = w.base;
  Traversal t;
  int head = 0, tail = 0;
  out[tail++] = root;
  mark[root] = base;
  while (head < tail) {
    t.last_level = head;
    ++t.nlev;
    const int end = tail;
    for (; head < end; ++head) {
      const int v = out[head], p = head;
      int mn = p, mx = p, vmin = v, cnt = 0;
      for (int k = xadj[v], k1 = xadj[v + 1]; k < k1; ++k) {
        const int u = adj[k];
        const int m = mark[u];
        if (kWithMask && m == kMasked) continue;
        vmin = std::min(vmin, u);
        if (m >= base) {
          if (kReverse)
            mx = std::max(mx, m - base);
          else
            mn = std::min(mn, m - base);
        } else {
          mark[u] = base;
          nb[cnt++] = u;
        }
      }
      for (int i = 1; i < cnt; ++i) { // stable insertion sort of the few new neighbours by degree
        const int u = nb[i], du = deg[u];
        int j = i;
        for (; j > 0 && deg[nb[j - 1]] > du; --j) nb[j] = nb[j - 1];
        nb[j] = u;
      }
      for (int i = 0; i < cnt; ++i) mark[nb[i]] = base + tail, out[tail++] = nb[i];
      if (cnt > 0) mx = tail - 1;
      if (kReverse)
        t.prof_rcm += mx - p;
      else
        t.prof_cm += p - mn;
      t.prof_nat += v - vmin;
    }
  }
  t.size = tail;
  return t;
}

// Number of BFS levels from root over the unvisited (unmasked) vertices, stopping once it exceeds stop.
int bfsLevels(const Graph& g, int root, Work& w, int stop) {
  w.newSearch();
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  int* mark = w.mark.data();
  int* q = w.bfs.data();
  const int base = w.base;
  int head = 0, tail = 0, nlev = 0;
  q[tail++] = root;
  mark[root] = base;
  while (head < tail && nlev <= stop) {
    ++nlev;
    for (const int end = tail; head < end; ++head) {
      const int v = q[head];
      for (int k = xadj[v], k1 = xadj[v + 1]; k < k1; ++k) {
        const int u = adj[k];
        if (mark[u] < base) mark[u] = base, q[tail++] = u; // kMasked is never < base
      }
    }
  }
  return nlev;
}

// Degree of v within the subgraph (masked vertices excluded when a mask is in use).
int subDegree(const Graph& g, const Work& w, int v, bool masked) {
  if (!masked) return w.deg[v];
  int d = 0;
  for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) d += w.mark[g.adj[k]] != kMasked ? 1 : 0;
  return d;
}

// SPARSEPAK FNROOT: from root, move to a minimum-degree node of the last level while the number of levels
// grows. Leaves the CM traversal from the root found in out (that traversal's data returned).
Traversal findRootAndOrder(const Graph& g, int root, Work& w, bool masked, bool reverse, int* out) {
  auto traverse = masked ? (reverse ? cmTraversal<true, true> : cmTraversal<true, false>)
                         : (reverse ? cmTraversal<false, true> : cmTraversal<false, false>);
  Traversal t = traverse(g, root, w, out);
  while (t.nlev > 1 && t.nlev < t.size) {
    int best = out[t.last_level], bestdeg = INT_MAX;
    for (int q = t.last_level; q < t.size; ++q) {
      const int d = subDegree(g, w, out[q], masked);
      if (d < bestdeg) bestdeg = d, best = out[q];
    }
    if (best == root || bfsLevels(g, best, w, t.nlev) <= t.nlev) break;
    root = best;
    t = traverse(g, root, w, out);
  }
  return t;
}

struct CmResult {
  std::vector<int> order; // CM order, components one after the other
  long long prof_cm = 0, prof_rcm = 0, prof_nat = 0;
};

// CM order; the profiles of the CM order (reverse = false) or of the RCM order (reverse = true), and of the input.
CmResult cuthillMcKee(const Graph& g, bool reverse) {
  CmResult r;
  r.order.resize(g.n);
  if (g.n == 0) return r;
  Work w(g);
  // The pseudo-peripheral search starts from a vertex of minimum degree (usually a corner of the mesh: fewer
  // FNROOT iterations), then every other component from its first vertex.
  int vmin = 0;
  for (int v = 1; v < g.n; ++v)
    if (w.deg[v] < w.deg[vmin]) vmin = v;
  std::vector<char> numbered; // only for graphs of several components
  int pos = 0;
  for (int k = -1; k < g.n && pos < g.n; ++k) {
    const int v = k < 0 ? vmin : k;
    if (k >= 0 && numbered[v]) continue;
    const Traversal t = findRootAndOrder(g, v, w, false, reverse, r.order.data() + pos);
    pos += t.size;
    r.prof_cm += t.prof_cm, r.prof_rcm += t.prof_rcm, r.prof_nat += t.prof_nat;
    if (pos < g.n) {
      if (numbered.empty()) numbered.assign(g.n, 0);
      for (int i = pos - t.size; i < pos; ++i) numbered[r.order[i]] = 1;
    }
  }
  return r;
}

} // namespace

int pseudoPeripheralNode(const Graph& g, int root, const std::vector<char>& mask) {
  Work w(g);
  for (int v = 0; v < g.n; ++v)
    if (!mask[v]) w.mark[v] = kMasked;
  std::vector<int> order(g.n);
  findRootAndOrder(g, root, w, true, true, order.data());
  return order[0];
}

std::vector<int> orderCuthillMcKee(const Graph& g) {
  CmResult r = cuthillMcKee(g, false);
  if (r.prof_cm > r.prof_nat) return orderNatural(g);
  return std::move(r.order);
}

std::vector<int> orderReverseCuthillMcKee(const Graph& g) {
  CmResult r = cuthillMcKee(g, true);
  if (r.prof_rcm > r.prof_nat) return orderNatural(g);
  std::reverse(r.order.begin(), r.order.end());
  return std::move(r.order);
}

} // namespace suite::fem
