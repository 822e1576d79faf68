// Cuthill-McKee (Cuthill & McKee 1969) and reverse Cuthill-McKee (George 1971) orderings: breadth-first
// search from a pseudo-peripheral node (George & Liu 1979, SPARSEPAK FNROOT/RCM; George & Liu 1981, ch. 4),
// neighbours visited by increasing degree, each connected component in turn. Never worse than the input order
// in profile. Linear in the number of graph edges per BFS, no allocation inside the searches (the work arrays
// are allocated once per call), insertion sort of the few neighbours of a vertex by degree.
#include "fem/ordering.hpp"

#include <algorithm>

namespace suite::fem {
namespace {

// seen[v] == kDone: numbered already (outside the remaining graph); seen[v] == stamp: visited by the current
// search. One random access per edge, no reset between searches.
constexpr int kDone = 1 << 30;

struct Work {
  std::vector<int> seen, order, start, order2, start2;
  int stamp = 0;
  explicit Work(int n) : seen(n, 0), order(n), start(n + 1), order2(n), start2(n + 1) {}
};

// Rooted level structure from root over the remaining vertices: BFS order in order[0..), level k =
// order[start[k] .. start[k+1]). Returns the number of levels.
int levelStructure(const Graph& g, int root, Work& w, int* order, int* start) {
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  int* seen = w.seen.data();
  const int stamp = ++w.stamp;
  int head = 0, tail = 0, nlev = 0;
  order[tail++] = root;
  seen[root] = stamp;
  while (head < tail) {
    start[nlev++] = head;
    const int end = tail;
    for (; head < end; ++head) {
      const int v = order[head];
      for (int k = xadj[v]; k < xadj[v + 1]; ++k) {
        const int u = adj[k];
        if (seen[u] < stamp) {
          seen[u] = stamp;
          order[tail++] = u;
        }
      }
    }
  }
  start[nlev] = tail;
  return nlev;
}

// SPARSEPAK FNROOT: repeat the level structure from a minimum-degree node of the last level while the number of
// levels grows.
int findRoot(const Graph& g, int root, Work& w) {
  int nlev = levelStructure(g, root, w, w.order.data(), w.start.data());
  for (;;) {
    int best = -1, bestdeg = 1 << 30;
    for (int q = w.start[nlev - 1]; q < w.start[nlev]; ++q) {
      const int v = w.order[q];
      int d = 0;
      for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) d += w.seen[g.adj[k]] != kDone ? 1 : 0;
      if (d < bestdeg) bestdeg = d, best = v;
    }
    if (nlev == 1 || best == root) return root;
    const int n2 = levelStructure(g, best, w, w.order2.data(), w.start2.data());
    if (n2 <= nlev) return root;
    root = best, nlev = n2;
    w.order.swap(w.order2), w.start.swap(w.start2);
  }
}

// CM order of the component containing start; appends to out[*pos..] and marks its vertices done.
void cuthillMcKeeComponent(const Graph& g, int start, Work& w, int* out, int* pos) {
  const int* xadj = g.xadj.data();
  const int* adj = g.adj.data();
  int* seen = w.seen.data();
  int tail = *pos;
  out[tail++] = start;
  seen[start] = kDone;
  for (int q = *pos; q < tail; ++q) {
    const int v = out[q];
    const int first = tail;
    for (int k = xadj[v]; k < xadj[v + 1]; ++k) {
      const int u = adj[k];
      if (seen[u] == kDone) continue;
      seen[u] = kDone;
      // insertion by increasing degree, stable (ties keep adjacency order)
      const int du = xadj[u + 1] - xadj[u];
      int i = tail++;
      while (i > first && xadj[out[i - 1] + 1] - xadj[out[i - 1]] > du) {
        out[i] = out[i - 1];
        --i;
      }
      out[i] = u;
    }
  }
  *pos = tail;
}

std::vector<int> cuthillMcKee(const Graph& g) {
  std::vector<int> out(g.n);
  Work w(g.n);
  int pos = 0;
  // The pseudo-peripheral search starts from a vertex of minimum degree (usually a corner of the mesh: fewer
  // FNROOT iterations), then every other component from its first vertex.
  int vmin = 0;
  for (int v = 1; v < g.n; ++v)
    if (g.degree(v) < g.degree(vmin)) vmin = v;
  for (int k = -1; k < g.n; ++k) {
    const int v = k < 0 ? vmin : k;
    if (g.n == 0 || w.seen[v] == kDone) continue;
    const int start = g.degree(v) == 0 ? v : findRoot(g, v, w);
    cuthillMcKeeComponent(g, start, w, out.data(), &pos);
  }
  return out;
}

// The permutation if its profile is not larger than the natural order's, else the natural order: both profiles
// in one pass over the edges.
std::vector<int> keepIfBetter(const Graph& g, std::vector<int> perm) {
  std::vector<int> inv(g.n);
  for (int i = 0; i < g.n; ++i) inv[perm[i]] = i;
  long long p_new = 0, p_nat = 0;
  for (int v = 0; v < g.n; ++v) {
    int f_nat = v, f_new = inv[v];
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) {
      const int u = g.adj[k];
      f_nat = std::min(f_nat, u);
      f_new = std::min(f_new, inv[u]);
    }
    p_nat += v - f_nat;
    p_new += inv[v] - f_new;
  }
  if (p_new > p_nat) return orderNatural(g);
  return perm;
}

} // namespace

int pseudoPeripheralNode(const Graph& g, int root, const std::vector<char>& mask) {
  Work w(g.n);
  for (int v = 0; v < g.n; ++v)
    if (!mask[v]) w.seen[v] = kDone;
  return findRoot(g, root, w);
}

std::vector<int> orderCuthillMcKee(const Graph& g) {
  return keepIfBetter(g, cuthillMcKee(g));
}

std::vector<int> orderReverseCuthillMcKee(const Graph& g) {
  auto p = cuthillMcKee(g);
  std::reverse(p.begin(), p.end());
  return keepIfBetter(g, p);
}

} // namespace suite::fem
