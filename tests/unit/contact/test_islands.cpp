// Unit tests of contact islands: the split of a hand-built scene (two piles and a resting box on
// the ground: three islands with the expected bodies and contacts; a static slab shared by two piles does
// not join them), the renumbered island scene, and the stepper per island: the same motion as the whole-scene
// solve to the LCP tolerance, bitwise the same whatever order the islands are solved in (what makes 1 and 2
// ranks agree), warm starts and contact identities carried per island, a failed island named.
#include "contact/islands.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace suite::contact;

namespace {

Shape box(double edge) {
  Shape s;
  s.type = ShapeType::Box;
  s.half = Vec3::Constant(0.5 * edge);
  return s;
}

Body boxAt(const std::string& name, double x, double z, bool is_static = false) {
  return makeBody(name, box(1.0), 1000.0, 0.0, Vec3(x, 0, z), Quat::Identity(), is_static);
}

// 0 ground; pile A: 1 on the ground, 2 on 1; pile B: 3, 4 likewise; 5 a box resting alone; 6 a static slab
// (top at z = 1) with 7 and 8 resting on it apart, and 9 on 7.
std::vector<Body> handScene() {
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  b.push_back(boxAt("a1", 0, 0.5)), b.push_back(boxAt("a2", 0, 1.5));
  b.push_back(boxAt("b1", 5, 0.5)), b.push_back(boxAt("b2", 5, 1.5));
  b.push_back(boxAt("c", 10, 0.5));
  b.push_back(makeBody("slab", box(1.0), 1000.0, 0.0, Vec3(20, 0, 0.5), Quat::Identity(), true));
  b.back().shape.half = Vec3(2.0, 0.5, 0.5);
  b.push_back(boxAt("d1", 19, 1.5)), b.push_back(boxAt("e1", 21, 1.5)), b.push_back(boxAt("d2", 19, 2.5));
  return b;
}

std::vector<int> bodiesOf(const std::vector<Contact>& cs, const Island& isl) {
  std::vector<int> v;
  for (int k : isl.contacts) v.push_back(cs[k].a), v.push_back(cs[k].b);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

double maxDiff(const std::vector<Body>& a, const std::vector<Body>& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    d = std::max(
        {d, (a[i].x - b[i].x).lpNorm<Eigen::Infinity>(), (a[i].v - b[i].v).lpNorm<Eigen::Infinity>()});
  return d;
}

bool bitwiseEqual(const std::vector<Body>& a, const std::vector<Body>& b) {
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].v != b[i].v || a[i].w != b[i].w || a[i].q.coeffs() != b[i].q.coeffs())
      return false;
  return true;
}

} // namespace

TEST(ContactIslands, TwoPilesAndABoxOnTheGround) {
  const std::vector<Body> b = handScene();
  const std::vector<Contact> cs = findContacts(b, 1e-3, Vec3(0, 0, -9.81));
  const std::vector<Island> isl = splitIslands(b, cs);
  ASSERT_EQ(isl.size(), 5u); // A, B, the slab's two piles (d: 2 boxes, e: 1) and c
  // largest first (most contacts: 4 points per face pair), ties by the first body
  EXPECT_EQ(isl[0].bodies, (std::vector<int>{1, 2}));
  EXPECT_EQ(isl[1].bodies, (std::vector<int>{3, 4}));
  EXPECT_EQ(isl[2].bodies, (std::vector<int>{7, 9}));
  EXPECT_EQ(isl[3].bodies, (std::vector<int>{5}));
  EXPECT_EQ(isl[4].bodies, (std::vector<int>{8}));
  EXPECT_EQ(bodiesOf(cs, isl[0]), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(bodiesOf(cs, isl[2]), (std::vector<int>{6, 7, 9})); // the slab, not the ground, not 8
  EXPECT_EQ(bodiesOf(cs, isl[4]), (std::vector<int>{6, 8}));
  EXPECT_EQ(isl[0].contacts.size(), 8u);
  EXPECT_EQ(isl[3].contacts.size(), 4u);
  size_t total = 0;
  for (const Island& s : isl) total += s.contacts.size();
  EXPECT_EQ(total, cs.size()); // every contact in exactly one island
}

TEST(ContactIslands, StaticBodiesDoNotJoinIslands) {
  // hand-made contacts: 1-2, 2-3 chain; 4 and 5 both on static 0; 6 on static 7, 8 on 7: three islands of
  // one or more bodies, static 0 and 7 shared
  std::vector<Body> b(9, boxAt("x", 0, 0));
  b[0].is_static = b[7].is_static = true;
  std::vector<Contact> cs;
  for (auto [a, c] :
       std::vector<std::pair<int, int>>{{1, 2}, {2, 3}, {4, 0}, {5, 0}, {6, 7}, {8, 7}, {3, 1}}) {
    Contact k;
    k.a = a, k.b = c;
    cs.push_back(k);
  }
  const std::vector<Island> isl = splitIslands(b, cs);
  ASSERT_EQ(isl.size(), 5u);
  EXPECT_EQ(isl[0].bodies, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(isl[0].contacts, (std::vector<int>{0, 1, 6}));
  for (size_t k = 1; k < 5; ++k) EXPECT_EQ(isl[k].bodies.size(), 1u) << k;
  EXPECT_EQ(isl[1].bodies[0], 4);
  EXPECT_EQ(isl[4].bodies[0], 8);
}

TEST(ContactIslands, IslandSceneRenumbers) {
  const std::vector<Body> b = handScene();
  const std::vector<Contact> cs = findContacts(b, 1e-3, Vec3(0, 0, -9.81));
  const std::vector<Island> isl = splitIslands(b, cs);
  const IslandScene s = islandScene(b, cs, isl[2]);
  EXPECT_EQ(s.global, (std::vector<int>{6, 7, 9}));
  ASSERT_EQ(s.contacts.size(), isl[2].contacts.size());
  for (size_t k = 0; k < s.contacts.size(); ++k) {
    const Contact& g = cs[isl[2].contacts[k]];
    EXPECT_EQ(s.global[s.contacts[k].a], g.a);
    EXPECT_EQ(s.global[s.contacts[k].b], g.b);
    EXPECT_EQ(s.contacts[k].p, g.p);
  }
  EXPECT_TRUE(s.bodies[0].is_static);
}

// The hand scene for 100 steps, islands off, on, and on with the islands solved in reverse order.
TEST(ContactIslands, StepperPerIslandAgreesWithWholeScene) {
  const std::vector<Body> b0 = handScene();
  for (FrictionModel f : {FrictionModel::Splitting, FrictionModel::Box, FrictionModel::Polyhedral}) {
    auto whole = b0, on = b0, rev = b0;
    StepperOptions o;
    o.friction = f;
    o.dense_max_rows = 20; // the pile islands sparse, the single boxes dense
    Stepper sw(o);
    o.islands = true;
    Stepper si(o), sr(o);
    sr.setTaskRunner([](int n, const TaskSolveFn& solve, std::vector<std::vector<double>>* out) {
      out->assign(n, {});
      for (int k = n - 1; k >= 0; --k) (*out)[k] = solve(k);
      return std::string();
    });
    for (int k = 0; k < 100; ++k) {
      const StepStats a = sw.step(&whole), c = si.step(&on), d = sr.step(&rev);
      ASSERT_FALSE(a.failed || c.failed || d.failed) << k;
      ASSERT_EQ(c.islands, 5);
      ASSERT_EQ(c.largest_island_bodies, 2);
      ASSERT_EQ(c.largest_island_contacts, 8);
      ASSERT_EQ(a.islands, 0);
      // identities carried per island as for the whole scene (the same set; the order of a face's clipped
      // points may differ by round-off)
      std::vector<long long> ia = sw.contactIds(), ic = si.contactIds();
      std::sort(ia.begin(), ia.end()), std::sort(ic.begin(), ic.end());
      ASSERT_EQ(ia, ic) << k;
    }
    std::printf("%s: islands vs whole scene, 100 steps: max |dx|, |dv| = %.2e, drift %.2e\n", frictionName(f),
                maxDiff(on, whole), maxDiff(on, b0));
    // acceptance residual lcp_tol (1 + |b|) = 1e-8 (1 + 0.1) m/s per step, over 1 s
    EXPECT_LE(maxDiff(on, whole), 1e-8) << frictionName(f);
    EXPECT_TRUE(bitwiseEqual(on, rev)) << frictionName(f);
  }
}

TEST(ContactIslands, FailedIslandIsNamed) {
  std::vector<Body> b = handScene();
  b[1].v = Vec3(1, 0, -1), b[2].w = Vec3(0, 2, 0); // pile A hits the ground
  StepperOptions o;
  o.islands = true;
  o.lcp_solver = "pgs";
  o.lcp_max_iterations = 1;
  // below round-off: no answer is accepted (one sweep and its active-set refinement solve the problem)
  o.lcp_tol = 1e-30;
  o.fallback_solvers = {};
  o.dense_max_rows = 1 << 20;
  Stepper st(o);
  const std::vector<Body> b0 = b;
  const StepStats s = st.step(&b);
  ASSERT_TRUE(s.failed);
  std::printf("%s\n", s.message.c_str());
  EXPECT_EQ(s.message.rfind("island 1 of 5 (2 bodies, 8 contacts): contact problem of size", 0), 0u);
  EXPECT_TRUE(bitwiseEqual(b, b0)); // bodies unchanged
  ASSERT_FALSE(st.lastProblems().empty());
  // the failed island's problem (at most 3 rows per contact), for the dump
  const int n = st.lastProblems().back().size();
  EXPECT_LE(n, 8 * 3);
  EXPECT_NE(s.message.find("problem of size " + std::to_string(n) + " not solved"), std::string::npos);
}
