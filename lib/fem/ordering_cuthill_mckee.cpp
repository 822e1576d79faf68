// Cuthill-McKee (Cuthill & McKee 1969) and reverse Cuthill-McKee (George 1971) orderings: breadth-first
// search from a pseudo-peripheral node (George & Liu 1979, SPARSEPAK FNROOT/RCM; George & Liu 1981, ch. 4),
// neighbours visited by increasing degree, each connected component in turn. Never worse than the input order
// in profile.
#include "fem/ordering.hpp"

#include <algorithm>

namespace suite::fem {
namespace {

// Rooted level structure from root over masked vertices; returns the number of levels, fills order (BFS
// order) and level_start (level k = order[level_start[k] .. level_start[k+1])).
int levelStructure(const Graph& g, int root, const std::vector<char>& mask, std::vector<int>* level,
                   std::vector<int>* order, std::vector<int>* level_start) {
  order->clear();
  level_start->clear();
  order->push_back(root);
  (*level)[root] = 0;
  size_t begin = 0;
  int nlev = 0;
  while (begin < order->size()) {
    level_start->push_back(static_cast<int>(begin));
    const size_t end = order->size();
    for (size_t q = begin; q < end; ++q) {
      const int v = (*order)[q];
      for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) {
        const int w = g.adj[k];
        if (mask[w] && (*level)[w] < 0) {
          (*level)[w] = nlev + 1;
          order->push_back(w);
        }
      }
    }
    begin = end;
    ++nlev;
  }
  level_start->push_back(static_cast<int>(order->size()));
  for (int v : *order) (*level)[v] = -1; // reset for the next call
  return nlev;
}

// CM order of the component containing start (vertices with mask set); appends to out and clears their mask.
void cuthillMcKeeComponent(const Graph& g, int start, std::vector<char>& mask, std::vector<int>* out) {
  const size_t first = out->size();
  out->push_back(start);
  mask[start] = 0;
  std::vector<int> nb;
  for (size_t q = first; q < out->size(); ++q) {
    const int v = (*out)[q];
    nb.clear();
    for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k)
      if (mask[g.adj[k]]) {
        nb.push_back(g.adj[k]);
        mask[g.adj[k]] = 0;
      }
    std::stable_sort(nb.begin(), nb.end(), [&](int a, int b) { return g.degree(a) < g.degree(b); });
    out->insert(out->end(), nb.begin(), nb.end());
  }
}

int findRoot(const Graph& g, int root, const std::vector<char>& mask, std::vector<int>& level);

std::vector<int> cuthillMcKee(const Graph& g) {
  std::vector<char> mask(g.n, 1);
  std::vector<int> out, level(g.n, -1);
  out.reserve(g.n);
  for (int v = 0; v < g.n; ++v) {
    if (!mask[v]) continue;
    const int start = g.degree(v) == 0 ? v : findRoot(g, v, mask, level);
    cuthillMcKeeComponent(g, start, mask, &out);
  }
  return out;
}

std::vector<int> keepIfBetter(const Graph& g, std::vector<int> perm) {
  const auto natural = orderNatural(g);
  if (profileOf(g, perm) > profileOf(g, natural)) return natural;
  return perm;
}

int findRoot(const Graph& g, int root, const std::vector<char>& mask, std::vector<int>& level) {
  std::vector<int> order, start;
  int nlev = levelStructure(g, root, mask, &level, &order, &start);
  for (;;) {
    // Last level: the node of minimum degree (SPARSEPAK FNROOT), counting only masked neighbours.
    int best = -1, bestdeg = 1 << 30;
    for (int q = start[nlev - 1]; q < start[nlev]; ++q) {
      const int v = order[q];
      int d = 0;
      for (int k = g.xadj[v]; k < g.xadj[v + 1]; ++k) d += mask[g.adj[k]] ? 1 : 0;
      if (d < bestdeg) bestdeg = d, best = v;
    }
    if (nlev == 1 || best == root) return root;
    std::vector<int> o2, s2;
    const int n2 = levelStructure(g, best, mask, &level, &o2, &s2);
    if (n2 <= nlev) return root;
    root = best, nlev = n2, order.swap(o2), start.swap(s2);
  }
}

} // namespace

int pseudoPeripheralNode(const Graph& g, int root, const std::vector<char>& mask) {
  std::vector<int> level(g.n, -1);
  return findRoot(g, root, mask, level);
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
