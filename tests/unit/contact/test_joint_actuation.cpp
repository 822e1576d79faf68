// Unit tests of joint limits and motors (joint_actuation.hpp): a hinge falling onto its limit stops there and
// holds the gravity torque, a slider stops at its travel limit and holds the weight, a bounded velocity motor
// reaches its target speed in one step when its bound allows and otherwise accelerates at bound / inertia, and
// the motor_limit scene's lever rests on the limit it is driven against (or the other one, when the motor is
// too weak to lift it).
#include "contact/joint_system.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::contact;

namespace {
constexpr double kG = 9.81;

StepperOptions options(double dt, const Vec3& gravity = Vec3(0, 0, -kG)) {
  StepperOptions o;
  o.dt = dt;
  o.gravity = gravity;
  o.friction = FrictionModel::None;
  return o;
}

Model lever(double angle_deg) {
  SceneParams p;
  p.scene = "pendulum";
  p.angle_deg = angle_deg;
  return buildModel(p);
}

// The link's moment of inertia about its hinge at one end (the compound pendulum's I_p).
double hingeInertia(const Body& link, double L) {
  return link.inertia.x() + link.mass * 0.25 * L * L;
}

double coordinate(const Model& m, int joint = 0) {
  return jointCoordinate(m.joints[joint], m.bodies).phi;
}
} // namespace

// The pendulum released from horizontal with limits +-30 degrees about that pose: it falls (the coordinate
// decreases), stops at -30 degrees and rests there, the hinge holding the gravity torque m g L/2 cos 30 about
// its axis. dt = 1e-3, 1 s. Measured: the coordinate at most 4.4e-16 below the limit, at its end 0 from it,
// torque relative error below 1e-15; at most 2 solves per step.
TEST(ContactJointActuation, HingeStopsAtItsLimit) {
  Model m = lever(90);
  const double lim = M_PI / 6, L = 0.1;
  m.joints[0].limited = true, m.joints[0].lower = -lim, m.joints[0].upper = lim;
  Stepper st(options(1e-3));
  st.setJoints(m.joints);
  double lowest = 0.0;
  int solves = 0;
  for (int k = 0; k < 1000; ++k) {
    const StepStats s = st.step(&m.bodies);
    ASSERT_FALSE(s.failed) << s.message;
    lowest = std::min(lowest, coordinate(m));
    solves = std::max(solves, s.actuation_solves);
  }
  Vec3 f, tq;
  st.jointReaction(0, m.bodies, &f, &tq);
  const double expect = m.bodies[0].mass * kG * 0.5 * L * std::cos(lim);
  std::printf("limit: lowest %.17g (limit %.17g), end %.3e from it, torque %.6f (exact %.6f), solves <= %d\n",
              lowest, -lim, coordinate(m) + lim, std::abs(tq.y()), expect, solves);
  EXPECT_GE(lowest, -lim - 1e-14);
  EXPECT_NEAR(coordinate(m), -lim, 1e-14);
  EXPECT_NEAR(std::abs(tq.y()) / expect, 1.0, 1e-12);
  EXPECT_LE(solves, 2); // one switch: the limit becomes active
}

// A box on a vertical slider to the world falls; its travel (the world relative to the box along z: +d when
// the box has fallen d) is limited to 0.05 m: it stops 0.05 m below its start and the slider holds its weight.
// dt = 1e-3, 0.5 s. Measured: |z end - (z0 - 0.05)| 4e-17, travel at most 4.4e-17 past the limit, relative
// force error below 1e-15.
TEST(ContactJointActuation, SliderStopsAtItsTravelLimit) {
  Shape box;
  box.type = ShapeType::Box;
  box.half = Vec3(0.05, 0.05, 0.05);
  Model m;
  m.bodies.push_back(makeBody("box", box, 0.0, 2.0, Vec3(0, 0, 1), Quat::Identity(), false));
  m.joints.push_back(makeJoint("slide", JointType::Slider, m.bodies, 0, -1, Vec3(0, 0, 1), Vec3::UnitZ()));
  m.joints[0].limited = true, m.joints[0].lower = -0.05, m.joints[0].upper = 0.05;
  Stepper st(options(1e-3));
  st.setJoints(m.joints);
  double highest = 0.0;
  for (int k = 0; k < 500; ++k) {
    ASSERT_FALSE(st.step(&m.bodies).failed);
    highest = std::max(highest, coordinate(m));
  }
  Vec3 f, tq;
  st.jointReaction(0, m.bodies, &f, &tq);
  std::printf("slider limit: z end %.17g, highest travel %.17g, force %.6f N (weight %.6f)\n",
              m.bodies[0].x.z(), highest, f.z(), 2.0 * kG);
  EXPECT_NEAR(m.bodies[0].x.z(), 0.95, 1e-14);
  EXPECT_LE(highest, 0.05 + 1e-14);
  EXPECT_NEAR(f.z() / (2.0 * kG), 1.0, 1e-12);
}

// Without gravity, a motor of target 3 rad/s on the lever's hinge. Bound 100 N m (the one-step impulse
// I_p 3 / dt = 1.0 N m is within it): the speed is the target after the first step. Bound 0.01 N m: the speed
// is F t / I_p until it reaches the target (t* = 3 I_p / F = 1.08 s), the target after; the motor's power is
// F times the speed meanwhile. dt = 1e-3. Measured: largest relative speed error 0 (bound 100) and 1.04e-6
// (bound 0.01, just before t*: SHAKE's O(dt^2) velocity error on the swinging link, 4.17e-6 at dt = 2e-3);
// power relative error 0.
TEST(ContactJointActuation, BoundedMotorReachesTargetOrAcceleratesAtBound) {
  const double dt = 1e-3, target = 3.0, L = 0.1;
  for (double bound : {100.0, 0.01}) {
    SCOPED_TRACE(bound);
    Model m = lever(90);
    m.joints[0].motor = true, m.joints[0].target_speed = target, m.joints[0].max_force = bound;
    const double ip = hingeInertia(m.bodies[0], L);
    Stepper st(options(dt, Vec3::Zero()));
    st.setJoints(m.joints);
    double worst = 0.0, worst_power = 0.0;
    for (int k = 1; k <= 1500; ++k) {
      ASSERT_FALSE(st.step(&m.bodies).failed);
      const double speed =
          -m.bodies[0].w.y(); // the coordinate's rate: the world turning relative to the link
      const double exact = std::min(target, bound * k * dt / ip);
      worst = std::max(worst, std::abs(speed / exact - 1));
      if (exact < target)
        worst_power = std::max(worst_power, std::abs(st.motorPower(0) / (bound * speed) - 1));
    }
    std::printf("motor bound %g N m: largest relative speed error %.2e, power %.2e\n", bound, worst,
                worst_power);
    EXPECT_LE(worst, 1.5e-6);
    EXPECT_LE(worst_power, 1e-11);
  }
}

// The motor_limit scene (a lever driven up at 2 rad/s by at most 1 N m against its +60 degree limit): after 2 s
// it rests on the upper limit, the motor doing no work, the hinge holding the gravity torque m g
// L/2 cos 60 = 0.245 N m. With a 0.2 N m bound (below the gravity torque at every angle of the range) it cannot
// hold the lever, which falls onto the lower limit. dt = 0.01. Measured: |theta - limit| 0 and 2.2e-16, torque
// relative error 1.1e-15.
TEST(ContactJointActuation, MotorDrivesTheLeverAgainstItsLimit) {
  for (double torque : {1.0, 0.2}) {
    SCOPED_TRACE(torque);
    SceneParams p;
    p.scene = "motor_limit";
    p.motor_torque = torque;
    Model m = buildModel(p);
    Stepper st(options(0.01));
    st.setJoints(m.joints);
    for (int k = 0; k < 200; ++k) ASSERT_FALSE(st.step(&m.bodies).failed);
    const double lim = M_PI / 3, at = torque > 0.49 ? lim : -lim;
    Vec3 f, tq;
    st.jointReaction(0, m.bodies, &f, &tq);
    const double expect = m.bodies[0].mass * kG * 0.05 * std::cos(lim);
    std::printf("motor_limit %g N m: theta %.17g (limit %.17g), torque %.6f (exact %.6f), power %.2e W\n",
                torque, coordinate(m), at, std::abs(tq.y()), expect, st.motorPower(0));
    EXPECT_NEAR(coordinate(m), at, 1e-12);
    EXPECT_NEAR(std::abs(tq.y()) / expect, 1.0, 1e-12);
    EXPECT_NEAR(st.motorPower(0), 0.0, 1e-12);
  }
}

// A motor and a limit on a ball joint, or a limit with lower >= upper, are refused by the stepper.
TEST(ContactJointActuation, BadLimitsAndMotorsAreRefused) {
  Model m = lever(90);
  m.joints[0].limited = true, m.joints[0].lower = 0.2, m.joints[0].upper = 0.1;
  Stepper st(options(0.01));
  EXPECT_THROW(st.setJoints(m.joints), std::runtime_error);
  m.joints[0].lower = -4.0, m.joints[0].upper = 0.1; // beyond -pi
  EXPECT_THROW(st.setJoints(m.joints), std::runtime_error);
  m.joints[0].limited = false, m.joints[0].motor = true, m.joints[0].max_force = 0.0;
  EXPECT_THROW(st.setJoints(m.joints), std::runtime_error);
  m.joints[0].type = JointType::Ball, m.joints[0].max_force = 1.0;
  EXPECT_THROW(st.setJoints(m.joints), std::runtime_error);
}
