// Unit tests of -friction auto (friction_auto.hpp): the ladder (none alone for mu = 0), the start rung (warm
// choice, probe one lower, clamped), every problem within the target on a scene of several islands whose
// islands solved in reverse order give bitwise the same motion and rungs (what makes 1 and 2 ranks agree), and
// the checkpoint state (rungs and step count) round trip.
#include "contact/friction_auto.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace suite::contact;

namespace {

Body boxAt(const std::string& name, double x, double z) {
  Shape s;
  s.type = ShapeType::Box;
  s.half = Vec3::Constant(0.5);
  return makeBody(name, s, 1000.0, 0.0, Vec3(x, 0, z), Quat::Identity(), false);
}

// Two piles of two boxes and a box sliding alone (initial speed 2 m/s along x) on the ground.
std::vector<Body> scene() {
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  b.push_back(boxAt("a1", 0, 0.5)), b.push_back(boxAt("a2", 0, 1.5));
  b.push_back(boxAt("b1", 5, 0.5)), b.push_back(boxAt("b2", 5.2, 1.5));
  b.push_back(boxAt("c", 10, 0.5));
  b.back().v = Vec3(2, 0, 0);
  return b;
}

} // namespace

TEST(ContactFrictionAuto, Ladder) {
  StepperOptions o;
  o.mu = 0.0;
  EXPECT_EQ(autoRungNames(o), std::vector<std::string>{"none"});
  o.mu = 0.5;
  const std::vector<std::string> names = {"box",         "scaled_box",   "splitting_2",
                                          "splitting_5", "polyhedral_4", "polyhedral_8"};
  EXPECT_EQ(autoRungNames(o), names);
  const AutoFriction a(o);
  ASSERT_EQ(a.size(), 6);
  EXPECT_EQ(a.options(2).splitting_max_it, 2);
  EXPECT_EQ(a.options(5).polyhedral_directions, 8);
  EXPECT_EQ(a.options(5).friction, FrictionModel::Polyhedral);
}

TEST(ContactFrictionAuto, StartRung) {
  StepperOptions o;
  const AutoFriction a(o);
  EXPECT_EQ(a.startRung({}, false), 0);
  EXPECT_EQ(a.startRung({-1, -1}, false), 0);
  EXPECT_EQ(a.startRung({1, -1, 3}, false), 3);
  EXPECT_EQ(a.startRung({1, -1, 3}, true), 2);
  EXPECT_EQ(a.startRung({0}, true), 0);
  EXPECT_EQ(a.startRung({9}, false), 5);
}

// 100 steps with islands, in order and in reverse order: every step within E, bitwise the same.
TEST(ContactFrictionAuto, WithinTargetAndIndependentOfIslandOrder) {
  StepperOptions o;
  o.friction = FrictionModel::Auto;
  o.target_error = 1e-3;
  o.mu = 0.3;
  o.islands = true;
  Stepper s(o), r(o);
  r.setTaskRunner([](int n, const TaskSolveFn& solve, std::vector<std::vector<double>>* out) {
    out->assign(n, {});
    for (int k = n - 1; k >= 0; --k) (*out)[k] = solve(k);
    return std::string();
  });
  std::vector<Body> a = scene(), b = scene();
  for (int k = 0; k < 100; ++k) {
    const StepStats x = s.step(&a), y = r.step(&b);
    ASSERT_FALSE(x.failed || y.failed) << k << x.message;
    EXPECT_LE(x.cone_violation, o.target_error) << k;
    EXPECT_EQ(x.problem_rungs, y.problem_rungs) << k;
    EXPECT_EQ((int)x.problem_rungs.size(), x.islands) << k;
    for (double v : x.problem_violations) EXPECT_LE(v, o.target_error) << k;
  }
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x) << i;
    EXPECT_EQ(a[i].v, b[i].v) << i;
  }
  // the sliding box: a = -mu g while it slides (2 m/s stops after 0.68 s), then at rest
  EXPECT_LT(a[5].v.norm(), 1e-8);
  EXPECT_NEAR(a[5].x.x() - 10.0, 2.0 * 2.0 / (2 * 0.3 * 9.81), 2e-2);
}

TEST(ContactFrictionAuto, StateRoundTrip) {
  StepperOptions o;
  o.friction = FrictionModel::Auto;
  Stepper s(o), t(o);
  std::vector<Body> a = scene();
  for (int k = 0; k < 15; ++k) ASSERT_FALSE(s.step(&a).failed);
  std::vector<double> body, contacts, rungs;
  s.exportState((int)a.size(), &body, &contacts);
  s.exportAutoState(&rungs);
  ASSERT_EQ(rungs.size(), contacts.size() / 8 + 1);
  EXPECT_EQ(rungs.back(), 15.0);
  t.importState((int)a.size(), body, contacts);
  t.importAutoState(rungs);
  std::vector<double> again;
  t.exportAutoState(&again);
  EXPECT_EQ(again, rungs);
  rungs.pop_back();
  EXPECT_THROW(t.importAutoState(rungs), std::runtime_error);
}
