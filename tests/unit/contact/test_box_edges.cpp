// Box-box edge-edge contact (separating axis over the nine edge cross products): two boxes with crossed
// edges, one 45 degrees about x, the other 45 degrees about y above it, touch in one point between the edges,
// with the normal along z and the gap as signed distance; and a box falling edge-first on such a box does not
// sink in (without the edge axes the face axes report a 0.35 m overlap there).
#include "contact/collision.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::contact;

namespace {
std::vector<Body> crossed(double gap) {
  Shape s;
  s.type = ShapeType::Box;
  s.half = Vec3::Constant(0.5);
  const double h = 0.5 * std::sqrt(2.0);
  return {makeBody("low", s, 1000, 0, Vec3::Zero(), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX())), true),
          makeBody("up", s, 1000, 0, Vec3(0, 0, 2 * h + gap),
                   Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY())), false)};
}
} // namespace

TEST(ContactBoxEdges, CrossedEdgesOnePoint) {
  const double h = 0.5 * std::sqrt(2.0);
  for (double gap : {-1e-3, 0.0, 5e-4}) {
    auto b = crossed(gap);
    std::vector<Contact> cs;
    collide(b, 1, 0, 1e-3, &cs);
    ASSERT_EQ(cs.size(), 1u) << "gap " << gap;
    EXPECT_NEAR(cs[0].phi, gap, 1e-12);
    EXPECT_NEAR(cs[0].n.z(), 1.0, 1e-12); // from b (low) into a (up)
    EXPECT_NEAR((cs[0].p - Vec3(0, 0, h + 0.5 * gap)).norm(), 0.0, 1e-12);
  }
  std::vector<Contact> cs;
  auto b = crossed(2e-3); // beyond the margin: nothing
  collide(b, 1, 0, 1e-3, &cs);
  EXPECT_TRUE(cs.empty());
  // stacked aligned boxes still give the 4 face points (edge axes coincide with face axes there)
  SceneParams p;
  p.scene = "box_stack";
  p.stack_height = 2;
  auto st = buildScene(p);
  cs.clear();
  collide(st, 2, 1, 1e-3, &cs);
  EXPECT_EQ(cs.size(), 4u);
}

TEST(ContactBoxEdges, EdgeDropDoesNotSink) {
  auto b = crossed(0.05);
  b[1].v = Vec3(0, 0, -1.0);
  StepperOptions o;
  o.friction = FrictionModel::Splitting;
  Stepper stepper(o);
  double worst = 0.0;
  for (int k = 0; k < 30; ++k) {
    StepStats st = stepper.step(&b);
    ASSERT_FALSE(st.failed) << st.message;
    std::vector<Contact> cs;
    collide(b, 1, 0, 1e-3, &cs);
    for (const Contact& c : cs) worst = std::min(worst, c.phi);
  }
  std::printf("edge drop: deepest penetration %.3e m\n", worst);
  EXPECT_GE(worst, -5e-3);
}
