// Contact islands by union-find over the contact list (see islands.hpp; Tarjan, J. ACM 22 (1975)).
#include "contact/islands.hpp"

#include <algorithm>
#include <numeric>

namespace suite::contact {

namespace {

// Disjoint sets with path halving and union by size.
class DisjointSets {
public:
  explicit DisjointSets(int n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

private:
  std::vector<int> parent_, size_;
};

// The body whose island a contact joins: a when a is dynamic, else b (a static-static contact: a).
int anchor(const std::vector<Body>& bodies, const Contact& c) {
  return bodies[c.a].is_static ? c.b : c.a;
}

} // namespace

std::vector<Island> splitIslands(const std::vector<Body>& bodies, const std::vector<Contact>& cs,
                                 const std::vector<std::pair<int, int>>& joined) {
  const int nb = (int)bodies.size();
  DisjointSets sets(nb);
  for (const Contact& c : cs)
    if (!bodies[c.a].is_static && !bodies[c.b].is_static) sets.unite(c.a, c.b);
  for (const auto& [a, b] : joined)
    if (!bodies[a].is_static && !bodies[b].is_static) sets.unite(a, b);
  std::vector<int> slot(nb, -1); // root -> island
  std::vector<Island> islands;
  for (int k = 0; k < (int)cs.size(); ++k) {
    const int root = sets.find(anchor(bodies, cs[k]));
    if (slot[root] < 0) slot[root] = (int)islands.size(), islands.emplace_back();
    islands[slot[root]].contacts.push_back(k);
  }
  for (int i = 0; i < nb; ++i)
    if (!bodies[i].is_static && slot[sets.find(i)] >= 0) islands[slot[sets.find(i)]].bodies.push_back(i);
  auto first = [&](const Island& s) { return s.bodies.empty() ? cs[s.contacts[0]].a : s.bodies[0]; };
  std::sort(islands.begin(), islands.end(), [&](const Island& x, const Island& y) {
    if (x.contacts.size() != y.contacts.size()) return x.contacts.size() > y.contacts.size();
    return first(x) < first(y);
  });
  return islands;
}

IslandScene islandScene(const std::vector<Body>& bodies, const std::vector<Contact>& cs,
                        const Island& island) {
  IslandScene s;
  s.global = island.bodies;
  for (int k : island.contacts)
    for (int b : {cs[k].a, cs[k].b})
      if (bodies[b].is_static) s.global.push_back(b);
  std::sort(s.global.begin(), s.global.end());
  s.global.erase(std::unique(s.global.begin(), s.global.end()), s.global.end());
  for (int g : s.global) s.bodies.push_back(bodies[g]);
  // local index of a global body: its place in the sorted list (O(log) per contact, no array of every body)
  auto local = [&](int g) {
    return (int)(std::lower_bound(s.global.begin(), s.global.end(), g) - s.global.begin());
  };
  for (int k : island.contacts) {
    Contact c = cs[k];
    c.a = local(c.a), c.b = local(c.b);
    s.contacts.push_back(c);
  }
  return s;
}

} // namespace suite::contact
