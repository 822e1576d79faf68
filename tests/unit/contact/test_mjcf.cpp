// MJCF reader and writer (lib/contact/mjcf.hpp; the fuzz target tests/fuzz/fuzz_mjcf.cpp drives the reader): a
// pendulum and a nested chain give the hand-computed poses, masses and joints; euler, axisangle and quat agree;
// the registered scenes survive writeMjcf -> parseMjcf; every kind of bad input throws SceneError naming the
// line and the element or attribute; the sample files inputs/contact/*.xml match their scenes.
#include "contact/mjcf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace suite::contact;

namespace {

constexpr double kDeg = M_PI / 180.0;

std::string inputsDir() {
  std::string f = __FILE__; // .../tests/unit/contact/test_mjcf.cpp
  return f.substr(0, f.rfind("/tests/unit/")) + "/inputs/contact/";
}

std::string errorOf(const std::string& text) {
  try {
    parseMjcf(text, "t.xml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

void expectNear(const Vec3& a, const Vec3& b, double tol, const std::string& what) {
  EXPECT_LE((a - b).norm(), tol) << what << ": " << a.transpose() << " vs " << b.transpose();
}

Vec3 worldAnchor(const Model& m, const Joint& j) {
  const Body& a = m.bodies[j.a];
  return a.x + a.R() * j.ra;
}

Vec3 worldAxis(const Model& m, const Joint& j) {
  return m.bodies[j.a].R() * j.fa.col(2);
}

// The fields of the shape's type.
void expectSameShape(const Shape& a, const Shape& b) {
  EXPECT_EQ(a.type, b.type);
  if (a.type == ShapeType::Sphere || a.type == ShapeType::Capsule || a.type == ShapeType::Cylinder) {
    EXPECT_EQ(a.radius, b.radius);
  }
  if (a.type == ShapeType::Capsule || a.type == ShapeType::Cylinder) {
    EXPECT_EQ(a.half_length, b.half_length);
  }
  if (a.type == ShapeType::Box) {
    EXPECT_EQ(a.half, b.half);
  }
}

int indexOf(const Model& m, const std::string& name) {
  for (size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].name == name) return (int)i;
  return -2;
}

// Same bodies and joints (matched by name), to 1e-12.
void expectSameModel(const Model& a, const Model& b) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (const Body& p : a.bodies) {
    SCOPED_TRACE("body " + p.name);
    const int i = indexOf(b, p.name);
    ASSERT_GE(i, 0);
    const Body& q = b.bodies[i];
    expectSameShape(p.shape, q.shape);
    EXPECT_EQ(p.is_static, q.is_static);
    EXPECT_NEAR(p.mass, q.mass, 1e-12 * p.mass);
    expectNear(p.inertia, q.inertia, 1e-12 * p.inertia.norm(), "inertia");
    expectNear(p.x, q.x, 1e-12 * (1.0 + p.x.norm()), "position");
    EXPECT_LE(p.q.angularDistance(q.q), 1e-12);
    EXPECT_EQ(p.contype, q.contype);
    EXPECT_EQ(p.conaffinity, q.conaffinity);
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  auto name = [](const Model& m, int i) { return i < 0 ? std::string("world") : m.bodies[i].name; };
  for (const Joint& p : a.joints) {
    SCOPED_TRACE("joint " + p.name);
    const auto it =
        std::find_if(b.joints.begin(), b.joints.end(), [&](const Joint& j) { return j.name == p.name; });
    ASSERT_NE(it, b.joints.end());
    const Joint& q = *it;
    EXPECT_EQ(p.type, q.type);
    EXPECT_EQ(name(a, p.a), name(b, q.a));
    EXPECT_EQ(name(a, p.b), name(b, q.b));
    expectNear(p.ra, q.ra, 1e-12, "ra");
    expectNear(p.rb, q.rb, 1e-12 * (1.0 + p.rb.norm()), "rb");
    expectNear(worldAnchor(a, p), worldAnchor(b, q), 1e-12, "anchor");
    if (p.type == JointType::Hinge || p.type == JointType::Slider) {
      expectNear(worldAxis(a, p), worldAxis(b, q), 1e-12, "axis");
    }
    EXPECT_EQ(p.limited, q.limited);
    EXPECT_NEAR(p.lower, q.lower, 1e-15);
    EXPECT_NEAR(p.upper, q.upper, 1e-15);
    EXPECT_EQ(p.motor, q.motor);
    EXPECT_EQ(p.target_speed, q.target_speed);
    EXPECT_EQ(p.max_force, q.max_force);
  }
  EXPECT_EQ(a.timestep, b.timestep);
  EXPECT_EQ(a.has_gravity, b.has_gravity);
  if (a.has_gravity) {
    EXPECT_EQ(a.gravity, b.gravity);
  }
  EXPECT_EQ(a.friction, b.friction);
}

Model roundTrip(const Model& m) {
  return parseMjcf(writeMjcf(m, "test"), "written.xml");
}

Shape capsule(double r, double hl) {
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = r;
  s.half_length = hl;
  return s;
}

} // namespace

TEST(ContactMjcf, PendulumParses) {
  const Model m = parseMjcf(R"(<mujoco model="p">
  <option timestep="0.005" gravity="0 0 -9.81"/>
  <worldbody>
    <body name="link" pos="0 0 1">
      <joint name="hinge" type="hinge" axis="0 1 0" pos="0 0 0"/>
      <geom type="capsule" size="0.01 0.05" pos="0.05 0 0" quat="0.7071067811865476 0 0.7071067811865476 0" mass="2"/>
    </body>
  </worldbody>
</mujoco>)",
                            "p.xml");
  ASSERT_EQ(m.bodies.size(), 1u);
  const Body& b = m.bodies[0];
  EXPECT_EQ(b.name, "link");
  EXPECT_FALSE(b.is_static);
  expectNear(b.x, Vec3(0.05, 0, 1), 1e-15, "centre");
  expectNear(b.axis(), Vec3(1, 0, 0), 1e-15, "capsule axis");
  const Body ref = makeBody("link", capsule(0.01, 0.05), 0.0, 2.0, b.x, b.q, false);
  EXPECT_EQ(b.mass, 2.0);
  EXPECT_EQ(b.inertia, ref.inertia); // exactly makeBody's
  EXPECT_EQ(b.contype, 1u);
  EXPECT_EQ(b.conaffinity, 1u);
  ASSERT_EQ(m.joints.size(), 1u);
  const Joint& j = m.joints[0];
  EXPECT_EQ(j.name, "hinge");
  EXPECT_EQ(j.type, JointType::Hinge);
  EXPECT_EQ(j.a, 0);
  EXPECT_EQ(j.b, -1);
  expectNear(j.rb, Vec3(0, 0, 1), 1e-15, "world anchor");
  expectNear(worldAnchor(m, j), Vec3(0, 0, 1), 1e-15, "anchor");
  expectNear(worldAxis(m, j), Vec3(0, 1, 0), 1e-15, "axis");
  EXPECT_FALSE(j.limited);
  EXPECT_FALSE(j.motor);
  EXPECT_EQ(m.timestep, 0.005);
  EXPECT_TRUE(m.has_gravity);
  EXPECT_EQ(m.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(m.friction, -1.0);
}

TEST(ContactMjcf, NestedChainWorldPoses) {
  // l0 at (0,0,1) turned 90 deg about z; l1 at 0.2 along l0's x (world y), turned 90 deg about its x; l2 at 0.3
  // along l1's z: R0 R1 e_z = Rz(90) Rx(90) e_z = Rz(90) (-e_y) = e_x; its box 0.05 along its x = world y.
  const Model m = parseMjcf(R"(<mujoco>
  <worldbody>
    <body name="l0" pos="0 0 1" euler="0 0 90">
      <joint type="hinge" axis="1 0 0"/>
      <geom type="sphere" size="0.05"/>
      <body name="l1" pos="0.2 0 0" axisangle="1 0 0 90">
        <joint type="hinge"/>
        <geom type="sphere" size="0.05"/>
        <body name="l2" pos="0 0 0.3">
          <joint name="j2" type="hinge" axis="0 0 1"/>
          <geom type="box" size="0.1 0.02 0.03" pos="0.05 0 0"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>)");
  ASSERT_EQ(m.bodies.size(), 3u);
  expectNear(m.bodies[0].x, Vec3(0, 0, 1), 1e-15, "l0");
  expectNear(m.bodies[1].x, Vec3(0, 0.2, 1), 1e-15, "l1");
  const Body& l2 = m.bodies[2];
  expectNear(l2.x, Vec3(0.3, 0.25, 1), 1e-15, "l2 centre");
  expectNear(l2.R().col(0), Vec3(0, 1, 0), 1e-15, "l2 x axis");
  expectNear(l2.R().col(2), Vec3(1, 0, 0), 1e-15, "l2 z axis");
  EXPECT_NEAR(l2.mass, 1000.0 * 8 * 0.1 * 0.02 * 0.03, 1e-15); // MuJoCo's default density
  EXPECT_NEAR(m.bodies[0].mass, 1000.0 * 4.0 / 3.0 * M_PI * 0.05 * 0.05 * 0.05, 1e-15);
  ASSERT_EQ(m.joints.size(), 3u);
  EXPECT_EQ(m.joints[1].a, 1);
  EXPECT_EQ(m.joints[1].b, 0);
  const Joint& j2 = m.joints[2];
  EXPECT_EQ(j2.name, "j2");
  EXPECT_EQ(j2.a, 2);
  EXPECT_EQ(j2.b, 1);
  expectNear(worldAnchor(m, j2), Vec3(0.3, 0.2, 1), 1e-15, "j2 anchor");
  expectNear(worldAxis(m, j2), Vec3(1, 0, 0), 1e-15, "j2 axis");
  expectNear(worldAxis(m, m.joints[0]), Vec3(0, 1, 0), 1e-15, "j0 axis (l0's x)");
}

TEST(ContactMjcf, FromtoCapsulePose) {
  const Model m = parseMjcf(R"(<mujoco>
  <worldbody>
    <body name="a"><freejoint/><geom type="capsule" fromto="0 0 0 0.2 0 0" size="0.01" mass="1"/></body>
    <body name="b" pos="1 0 0" euler="0 0 90">
      <freejoint/><geom type="cylinder" fromto="0 0 0 0.2 0 0" size="0.02" density="500"/>
    </body>
  </worldbody>
</mujoco>)");
  ASSERT_EQ(m.bodies.size(), 2u);
  const Body &a = m.bodies[0], &b = m.bodies[1];
  expectNear(a.x, Vec3(0.1, 0, 0), 1e-15, "a centre");
  EXPECT_DOUBLE_EQ(a.shape.half_length, 0.1);
  EXPECT_EQ(a.shape.radius, 0.01);
  expectNear(a.axis(), Vec3(-1, 0, 0), 1e-15, "a axis"); // MuJoCo: z along from - to
  EXPECT_EQ(a.inertia, makeBody("a", a.shape, 0.0, 1.0, a.x, a.q, false).inertia);
  expectNear(b.x, Vec3(1, 0.1, 0), 1e-15, "b centre");
  expectNear(b.axis(), Vec3(0, -1, 0), 1e-15, "b axis");
  EXPECT_NEAR(b.mass, 500.0 * M_PI * 0.02 * 0.02 * 0.2, 1e-15);
  EXPECT_TRUE(m.joints.empty()); // free bodies
}

TEST(ContactMjcf, OrientationFormsAgree) {
  const Quat ex = Quat(Eigen::AngleAxisd(30 * kDeg, Vec3::UnitX())) *
                  Quat(Eigen::AngleAxisd(45 * kDeg, Vec3::UnitY())) *
                  Quat(Eigen::AngleAxisd(60 * kDeg, Vec3::UnitZ())); // intrinsic x-y-z
  const Quat aa(Eigen::AngleAxisd(60 * kDeg, Vec3(1, 1, 0).normalized()));
  char quat[200], quat2[200];
  std::snprintf(quat, sizeof quat, "%.17g %.17g %.17g %.17g", ex.w(), ex.x(), ex.y(), ex.z());
  std::snprintf(quat2, sizeof quat2, "%.17g %.17g %.17g %.17g", aa.w(), aa.x(), aa.y(), aa.z());
  auto body = [](const std::string& name, const std::string& orient) {
    return "<body name=\"" + name + "\" " + orient +
           "><freejoint/><geom type=\"box\" size=\"0.1 0.2 0.3\"/></body>";
  };
  const Model m =
      parseMjcf("<mujoco><worldbody>" + body("e", "euler=\"30 45 60\"") +
                body("q", std::string("quat=\"") + quat + "\"") + body("a", "axisangle=\"1 1 0 60\"") +
                body("q2", std::string("quat=\"") + quat2 + "\"") + "</worldbody></mujoco>");
  EXPECT_LE(m.bodies[0].q.angularDistance(ex), 1e-14);
  EXPECT_LE(m.bodies[1].q.angularDistance(ex), 1e-14);
  EXPECT_LE(m.bodies[2].q.angularDistance(aa), 1e-14);
  EXPECT_LE(m.bodies[3].q.angularDistance(aa), 1e-14);
  // radians; extrinsic "ZYX" in the reverse order is the same rotation as intrinsic xyz
  const Model r =
      parseMjcf("<mujoco><compiler angle=\"radian\" eulerseq=\"ZYX\"/><worldbody>" +
                body("e", "euler=\"" + std::to_string(60 * kDeg) + " " + std::to_string(45 * kDeg) + " " +
                              std::to_string(30 * kDeg) + "\"") +
                "</worldbody></mujoco>");
  EXPECT_LE(r.bodies[0].q.angularDistance(ex), 1e-6); // std::to_string: 6 decimals
  // an unnormalised quat is normalised, as in MuJoCo
  const Model u = parseMjcf("<mujoco><worldbody>" + body("u", "quat=\"2 0 0 2\"") + "</worldbody></mujoco>");
  EXPECT_LE(u.bodies[0].q.angularDistance(Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()))), 1e-15);
}

TEST(ContactMjcf, LimitsMotorsAndKeyframe) {
  const Model m = parseMjcf(R"(<mujoco>
  <worldbody>
    <body name="a"><joint name="h" axis="0 1 0" range="-90 45" limited="true"/><geom size="0.1"/></body>
    <body name="b" pos="1 0 0"><joint name="s" type="slide" axis="1 0 0" range="-0.5 0.25"/><geom size="0.1"/></body>
  </worldbody>
  <actuator>
    <velocity joint="h" kv="10" forcerange="-5 5" forcelimited="true" ctrlrange="-1 1"/>
    <velocity name="m2" joint="s" forcerange="-2 2"/>
  </actuator>
  <keyframe><key ctrl="3 -0.5"/><key ctrl="0 0"/></keyframe>
</mujoco>)");
  ASSERT_EQ(m.joints.size(), 2u);
  const Joint &h = m.joints[0], &s = m.joints[1];
  EXPECT_EQ(h.type, JointType::Hinge); // MuJoCo's default joint type
  EXPECT_TRUE(h.limited);              // our limit: b relative to a, MuJoCo's: a (child) relative to b
  EXPECT_DOUBLE_EQ(h.lower, -45 * kDeg);
  EXPECT_DOUBLE_EQ(h.upper, 90 * kDeg);
  EXPECT_TRUE(h.motor);
  EXPECT_EQ(h.max_force, 5.0);
  EXPECT_EQ(h.target_speed, -1.0); // ctrl 3 clamped to ctrlrange, sign as for limits
  EXPECT_EQ(s.type, JointType::Slider);
  EXPECT_TRUE(s.limited); // autolimits
  EXPECT_EQ(s.lower, -0.25);
  EXPECT_EQ(s.upper, 0.5);
  EXPECT_EQ(s.max_force, 2.0);
  EXPECT_EQ(s.target_speed, 0.5);
}

TEST(ContactMjcf, EqualityWeldsAndStaticBodies) {
  const Model m = parseMjcf(R"(<mujoco>
  <option gravity="0 0 -1"/>
  <worldbody>
    <geom name="floor" type="plane" friction="0.6"/>
    <body name="p" pos="0 0 1"><freejoint/><geom type="box" size="0.1 0.1 0.1" friction="0.6 0.01 0.001"/>
      <body name="q" pos="0.3 0 0"><geom type="sphere" size="0.05" contype="2" conaffinity="0" friction="0.6"/></body>
    </body>
    <body name="r" pos="1 0 0"><freejoint/><geom size="0.1" friction="0.6"/></body>
    <body name="s" pos="0 0 -1"><geom type="box" size="1 1 0.1" friction="0.6"/></body>
  </worldbody>
  <equality><connect body1="r" body2="p" anchor="0 0 0.5"/><weld name="w" body1="r" anchor="0.1 0 0"/></equality>
</mujoco>)");
  ASSERT_EQ(m.bodies.size(), 5u);
  EXPECT_EQ(m.bodies[0].name, "floor");
  EXPECT_TRUE(m.bodies[0].is_static);
  EXPECT_EQ(m.bodies[0].shape.type, ShapeType::Plane);
  EXPECT_TRUE(m.bodies[4].is_static); // a jointless child of the world
  EXPECT_EQ(m.bodies[2].contype, 2u);
  EXPECT_EQ(m.bodies[2].conaffinity, 0u);
  EXPECT_EQ(m.friction, 0.6);
  ASSERT_EQ(m.joints.size(), 3u);
  const Joint &weld = m.joints[0], &ball = m.joints[1], &fixed = m.joints[2];
  EXPECT_EQ(weld.name, "weld_q"); // welded to its parent
  EXPECT_EQ(weld.type, JointType::Fixed);
  EXPECT_EQ(weld.a, 2);
  EXPECT_EQ(weld.b, 1);
  expectNear(worldAnchor(m, weld), Vec3(0.3, 0, 1), 1e-15, "weld anchor");
  EXPECT_EQ(ball.type, JointType::Ball);
  EXPECT_EQ(ball.a, 3);
  EXPECT_EQ(ball.b, 1);
  expectNear(worldAnchor(m, ball), Vec3(1, 0, 0.5), 1e-15, "connect anchor (body1's frame)");
  EXPECT_EQ(fixed.name, "w");
  EXPECT_EQ(fixed.type, JointType::Fixed);
  EXPECT_EQ(fixed.b, -1);
  expectNear(fixed.rb, Vec3(0.1, 0, 0), 1e-15, "weld anchor (body2's frame: the world)");
}

TEST(ContactMjcf, RoundTripScenes) {
  struct Case {
    std::string scene;
    void (*tweak)(SceneParams*);
  };
  const std::vector<Case> cases = {
      {"pendulum", [](SceneParams*) {}},
      {"double_pendulum", [](SceneParams* p) { p->angle_deg = 30; }},
      {"chain", [](SceneParams* p) { p->links = 5; }},
      {"chain",
       [](SceneParams* p) {
         p->links = 5, p->joint_type = "ball", p->end_mass_ratio = 2, p->angle_deg = 40;
       }},
      {"pyramid", [](SceneParams*) {}},
      {"box_stack", [](SceneParams*) {}},
      {"drop", [](SceneParams*) {}},
      {"drop", [](SceneParams* p) { p->drop_body = "capsule", p->tilt_deg = 30; }},
      {"drop", [](SceneParams* p) { p->drop_body = "cylinder", p->tilt_deg = 70, p->mass = 3; }},
      {"drop", [](SceneParams* p) { p->drop_body = "box", p->tilt_deg = 10; }},
      {"incline", [](SceneParams*) {}},
      {"log_heap", [](SceneParams* p) { p->n_logs = 7; }},
      {"motor_limit", [](SceneParams*) {}},
      {"wrecking_ball", [](SceneParams* p) { p->links = 4, p->end_mass_ratio = 50; }},
  };
  for (const Case& c : cases) {
    SceneParams p;
    p.scene = c.scene;
    c.tweak(&p);
    Model m = buildModel(p);
    SCOPED_TRACE(c.scene);
    expectSameModel(m, roundTrip(m));
    m.timestep = 0.002, m.has_gravity = true, m.gravity = Vec3(0.1, 0, -9.8), m.friction = 0.35;
    expectSameModel(m, roundTrip(m));
  }
}

TEST(ContactMjcf, RoundTripJointFeatures) {
  Model m;
  Shape box;
  box.type = ShapeType::Box;
  box.half = Vec3(0.1, 0.2, 0.3);
  const Quat tilt(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  m.bodies.push_back(makePlane("ground", Vec3(0, 0.1, 1), Vec3(0, 0, -1)));
  m.bodies.push_back(makeBody("post", box, 1000, 0, Vec3(0, 0, 0.5), tilt, true)); // static, a joint's b
  m.bodies.push_back(makeBody("arm", capsule(0.05, 0.4), 800, 0, Vec3(0.5, 0, 1), tilt, false));
  m.bodies.push_back(makeBody("cart", box, 0, 4.0, Vec3(2, 0, 0.3), Quat::Identity(), false));
  m.bodies.push_back(makeBody("lid", box, 300, 0, Vec3(2, 0, 0.9), tilt.conjugate(), false));
  m.bodies.push_back(makeBody("free", capsule(0.1, 0.1), 1000, 0, Vec3(-1, 0, 1), tilt, false));
  m.bodies.back().inertia = Vec3(0.5, 0.6, 0.7); // not the shape's: written as <inertial>
  m.bodies.back().inv_inertia = m.bodies.back().inertia.cwiseInverse();
  m.bodies[3].contype = 3, m.bodies[3].conaffinity = 0;
  m.joints.push_back(makeJoint("hinge", JointType::Hinge, m.bodies, 2, 1, Vec3(0.1, 0, 1), Vec3(0, 1, 0.2)));
  m.joints.back().limited = true, m.joints.back().lower = -0.5, m.joints.back().upper = 1.0;
  m.joints.back().motor = true, m.joints.back().target_speed = 2.0, m.joints.back().max_force = 3.0;
  m.joints.push_back(makeJoint("slide", JointType::Slider, m.bodies, 3, -1, Vec3(2, 0, 0.3), Vec3(1, 0, 0)));
  m.joints.back().limited = true, m.joints.back().lower = -0.2, m.joints.back().upper = 0.7;
  m.joints.back().motor = true, m.joints.back().target_speed = -0.25, m.joints.back().max_force = 10.0;
  m.joints.push_back(makeJoint("loop", JointType::Ball, m.bodies, 2, 3, Vec3(1.2, 0, 0.8), Vec3::Zero()));
  m.joints.push_back(makeJoint("glue", JointType::Fixed, m.bodies, 4, 3, Vec3(2, 0.1, 0.6), Vec3::Zero()));
  m.joints.push_back(makeJoint("pin", JointType::Ball, m.bodies, 5, -1, Vec3(-1, 0, 1.3), Vec3::Zero()));
  m.timestep = 0.001;
  const std::string xml = writeMjcf(m, "features");
  EXPECT_NE(xml.find("<inertial"), std::string::npos);
  EXPECT_NE(xml.find("<connect"), std::string::npos);
  EXPECT_NE(xml.find("<weld"), std::string::npos);
  EXPECT_NE(xml.find("<velocity"), std::string::npos);
  expectSameModel(m, parseMjcf(xml));
}

TEST(ContactMjcf, WriterRefusesWhatMjcfCannotSay) {
  auto writeError = [](const Model& m) {
    try {
      writeMjcf(m, "x");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(written)");
  };
  SceneParams p;
  p.scene = "double_pendulum";
  Model m = buildModel(p);
  Model distance = m;
  distance.joints.push_back(
      makeJoint("rope", JointType::Distance, m.bodies, 1, -1, Vec3(0.1, 0, 0), Vec3::Zero(), Vec3(1, 0, 0)));
  EXPECT_NE(writeError(distance).find("joint 'rope' cannot be written as MJCF"), std::string::npos);
  Model loop = m; // a second hinge on link1: a loop closure MJCF's equality cannot express
  loop.joints.push_back(
      makeJoint("extra", JointType::Hinge, m.bodies, 1, -1, Vec3(0.2, 0, 0), Vec3::UnitY()));
  EXPECT_NE(writeError(loop).find("joint 'extra' cannot be written as MJCF: it closes a loop"),
            std::string::npos);
  p.scene = "chain";
  p.links = 95; // the deepest tree that tinyxml2 9 reads back
  EXPECT_EQ(roundTrip(buildModel(p)).bodies.size(), 95u);
  p.links = 96;
  EXPECT_NE(writeError(buildModel(p)).find("nested 96 bodies deep"), std::string::npos);
}

TEST(ContactMjcf, BadContentThrows) {
  auto has = [](const std::string& msg, const std::string& part) {
    EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg << "\nexpected: " << part;
  };
  const std::string head = "<mujoco>\n  <worldbody>\n"; // lines 1-2; a body from line 3
  const std::string tail = "\n  </worldbody>\n";
  const std::string end = tail + "</mujoco>\n";
  // malformed XML: tinyxml2 names the unclosed element and its line
  std::string e = errorOf(head + "    <body name=\"a\">\n  </worldbody>\n</mujoco>\n");
  has(e, "t.xml:3: malformed XML");
  has(e, "body");
  e = errorOf(head + "    <body name=\"a\">\n      <freejoint/>\n      <site name=\"s\"/>\n    </body>" +
              end);
  has(e, "t.xml:5: unknown element <site> in <body>");
  e = errorOf(
      head +
      "    <body name=\"a\">\n      <freejoint/>\n      <geom size=\"0.1\" condim=\"3\"/>\n    </body>" +
      end);
  has(e, "t.xml:5: <geom>: attribute 'condim' is not supported");
  e = errorOf(head + "    <body name=\"a\">\n      <joint type=\"hinge\"/>\n    </body>" + end);
  has(e, "t.xml:3: body 'a' has no mass");
  e = errorOf(
      head +
      "    <body name=\"a\">\n      <freejoint/>\n      <geom size=\"0.1\"/>\n      <geom size=\"0.2\"/>\n"
      "    </body>" +
      end);
  has(e, "t.xml:3: body 'a' has 2 geoms: one per body is supported");
  e = errorOf(head +
              "    <body name=\"a\">\n      <freejoint/>\n\n      <geom type=\"capsule\" size=\"0.1 abc\"/>\n"
              "    </body>" +
              end);
  has(e, "t.xml:6: <geom>: bad number 'abc' in attribute 'size'");
  e = errorOf(head + "    <body name=\"a\" pos=\"1 2\"/>" + end);
  has(e, "t.xml:3: <body>: attribute 'pos' needs 3 numbers, got 2");
  e = errorOf(head + "    <body name=\"a\" pos=\"1 2 nan\"/>" + end);
  has(e, "t.xml:3: <body>: bad number 'nan' in attribute 'pos'");
  // more of the checks, by message
  const std::string a = "<body name=\"a\"><freejoint/><geom size=\"1\"/></body>";
  const std::string h = "<body name=\"a\"><joint name=\"h\"/><geom size=\"1\"/></body>";
  has(errorOf("<mujoco>\n  <default/>\n</mujoco>"), "t.xml:2: <default> is not supported");
  has(errorOf("<mujoco>\n  <asset/>\n</mujoco>"), "t.xml:2: unknown element <asset> in <mujoco>");
  has(errorOf("<mujoco/>"), "t.xml:1: no bodies");
  has(errorOf("<robot/>"), "t.xml:1: the root element is <robot>, not <mujoco>");
  has(errorOf(""), "t.xml:1: malformed XML");
  has(errorOf(head + a + "\n<body name=\"a\"><geom size=\"1\"/></body>" + end),
      "t.xml:4: <body>: body name 'a' is used twice");
  has(errorOf(
          head +
          "<body name=\"a\"><freejoint/><geom size=\"1\"/>\n<body name=\"b\"><freejoint/><geom size=\"1\"/>"
          "</body></body>" +
          end),
      "t.xml:4: body 'b': a free joint only in a child of <worldbody>");
  has(errorOf(head + "<body name=\"a\"><joint/><joint/><geom size=\"1\"/></body>" + end),
      "t.xml:3: body 'a' has 2 joints: at most one per body is supported");
  has(errorOf(head + "<body><freejoint/><geom type=\"mesh\"/></body>" + end),
      "t.xml:3: <geom>: type=\"mesh\" is not supported");
  has(errorOf(head + "<body><freejoint/><geom type=\"plane\"/></body>" + end), "a plane must be static");
  has(errorOf(head + "<body><freejoint/><geom size=\"1\" mass=\"0\"/></body>" + end), "has no mass");
  has(errorOf(head + "<body><freejoint/><geom size=\"1\" quat=\"1 0 0 0\" euler=\"0 0 1\"/></body>" + end),
      "more than one of quat, euler, axisangle");
  has(errorOf(head +
              "<body><freejoint/><geom size=\"1\" pos=\"0 0 1\"/><inertial pos=\"0 0 0\" mass=\"1\" "
              "diaginertia=\"1 1 1\"/></body>" +
              end),
      "t.xml:3: <inertial>: pos must be the geom's centre");
  has(errorOf(head +
              "<geom type=\"plane\" friction=\"0.5\"/>\n<geom name=\"g\" type=\"sphere\" size=\"1\"/>" + end),
      "t.xml:4: geom friction 1 (MuJoCo's default) differs from 0.5 (line 3)");
  has(errorOf(head + a + tail +
              "<equality><connect body1=\"a\" body2=\"b\" anchor=\"0 0 0\"/></equality></mujoco>"),
      "t.xml:5: <connect>: body2=\"b\": no body of that name");
  has(errorOf(head + h + tail + "<actuator><velocity joint=\"k\" forcerange=\"-1 1\"/></actuator></mujoco>"),
      "<velocity>: joint=\"k\": no hinge, slide or ball joint of that name");
  has(errorOf(head + h + tail + "<actuator><velocity joint=\"h\" forcerange=\"-1 2\"/></actuator></mujoco>"),
      "forcerange must be symmetric");
  has(errorOf(head + h + tail +
              "<actuator><velocity joint=\"h\" forcerange=\"-1 1\"/></actuator><keyframe><key ctrl=\"1 2\"/>"
              "</keyframe></mujoco>"),
      "<key>: attribute 'ctrl' needs 1 numbers, got more");
  has(errorOf(head + "<body><freejoint/><geom size=\"1\" contype=\"-1\"/></body>" + end),
      "bad integer '-1' in attribute 'contype'");
  has(errorOf("<mujoco><option timestep=\"0\"/></mujoco>"), "timestep must be > 0");
  has(errorOf("<mujoco><compiler angle=\"grad\"/></mujoco>"),
      "angle=\"grad\" is not supported (degree, radian)");
}

TEST(ContactMjcf, SampleFilesMatchTheirScenes) {
  SceneParams p;
  p.angle_deg = 90; // horizontal along +x
  for (const char* file : {"pendulum.xml", "chain25.xml"}) {
    SCOPED_TRACE(file);
    const Model m = readMjcfFile(inputsDir() + file);
    p.scene = std::string(file) == "pendulum.xml" ? "pendulum" : "chain";
    p.links = 25;
    const Model ref = buildModel(p);
    ASSERT_EQ(m.bodies.size(), ref.bodies.size());
    ASSERT_EQ(m.joints.size(), ref.joints.size());
    EXPECT_EQ(m.timestep, 0.01);
    EXPECT_TRUE(m.has_gravity);
    EXPECT_EQ(m.gravity, Vec3(0, 0, -9.81));
    for (size_t i = 0; i < m.bodies.size(); ++i) {
      const Body &b = m.bodies[i], &r = ref.bodies[i];
      EXPECT_EQ(b.name, r.name);
      EXPECT_EQ(b.mass, r.mass);
      EXPECT_EQ(b.inertia, r.inertia);
      EXPECT_EQ(b.contype, 1u);
      EXPECT_EQ(b.conaffinity, 1u);
      EXPECT_NEAR(b.shape.half_length, r.shape.half_length, 1e-15);
      expectNear(b.x, r.x, 1e-12, "centre " + b.name);
      EXPECT_NEAR(std::abs(b.axis().dot(r.axis())), 1.0, 1e-15); // fromto: z along from - to
    }
    for (size_t k = 0; k < m.joints.size(); ++k) {
      const Joint &j = m.joints[k], &r = ref.joints[k];
      EXPECT_EQ(j.type, JointType::Hinge);
      EXPECT_EQ(j.a, r.a);
      EXPECT_EQ(j.b, r.b);
      expectNear(worldAnchor(m, j), worldAnchor(ref, r), 1e-12, "anchor " + j.name);
      expectNear(worldAxis(m, j), Vec3(0, 1, 0), 1e-15, "axis " + j.name);
    }
  }
  EXPECT_NE(std::string(errorOf("x")).find("malformed XML"), std::string::npos);
}
