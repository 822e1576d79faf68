// Unit tests of the contact library's joints (joint.hpp, joint_system.hpp): the rows' Jacobians against finite
// differences of their constraint functions, the pendulum's period against the compound-pendulum formula and
// the elliptic integral, the joint tensions of a hanging chain against the weight below each joint, the energy
// of a swinging chain, the position error of a long chain at a large step, and the scene file's joint lines.
#include "contact/joint_system.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace suite::contact;

namespace {
constexpr double kG = 9.81;

Model chain(const std::string& scene, int links, double angle_deg, double end_ratio = 0.0,
            const std::string& type = "hinge") {
  SceneParams p;
  p.scene = scene;
  p.links = links;
  p.angle_deg = angle_deg;
  p.end_mass_ratio = end_ratio;
  p.joint_type = type;
  return buildModel(p);
}

StepperOptions jointOptions(double dt) {
  StepperOptions o;
  o.dt = dt;
  o.friction = FrictionModel::None;
  return o;
}

// Kinetic plus potential energy (gravity along -z).
double energy(const std::vector<Body>& bodies) {
  double e = 0.0;
  for (const Body& b : bodies)
    if (!b.is_static) e += b.kineticEnergy() + b.mass * kG * b.x.z();
  return e;
}

// Steps the model n times at dt (frictionless, exact), calling after() after each step; returns the largest
// joint error of the steps (infinite when a step failed).
template <class F> double stepModel(Model* m, double dt, int n, F after) {
  Stepper st(jointOptions(dt));
  st.setJoints(m->joints);
  double joint_error = 0.0;
  for (int k = 0; k < n; ++k) {
    const StepStats s = st.step(&m->bodies);
    EXPECT_FALSE(s.failed) << s.message;
    if (s.failed) return INFINITY;
    joint_error = std::max(joint_error, s.joint_error);
    after();
  }
  return joint_error;
}

// Angle of a link from the downward vertical, in the x-z plane.
double linkAngle(const Body& b) {
  const Vec3 d = b.axis();
  return std::atan2(d.x(), -d.z());
}

// The period of the first link's swing: the time between the first and the third upward zero crossing of
// its angle (linear interpolation between steps).
double swingPeriod(Model m, double dt, int max_steps) {
  Stepper st(jointOptions(dt));
  st.setJoints(m.joints);
  std::vector<double> crossings;
  double prev = linkAngle(m.bodies[0]);
  for (int k = 1; k <= max_steps && crossings.size() < 3; ++k) {
    EXPECT_FALSE(st.step(&m.bodies).failed);
    const double a = linkAngle(m.bodies[0]);
    if (prev < 0 && a >= 0) crossings.push_back(dt * (k - 1 + prev / (prev - a)));
    if (prev > 0 && a <= 0) crossings.push_back(dt * (k - 1 + prev / (prev - a)));
    prev = a;
  }
  return crossings.size() == 3 ? crossings[2] - crossings[0] : NAN;
}

// Small-amplitude period of a link hinged at one end: 2 pi sqrt(I_p / (m g L/2)), I_p = I_perp + m (L/2)^2.
double compoundPeriod(const Body& link, double L) {
  const double ip = link.inertia.x() + link.mass * 0.25 * L * L;
  return 2 * M_PI * std::sqrt(ip / (link.mass * kG * 0.5 * L));
}

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return M_PI / (2 * a);
}

// Phi of every row of joint j at the bodies' poses.
std::vector<double> phis(const Joint& j, const std::vector<Body>& bodies) {
  std::vector<JointRow> rows;
  jointRows(j, bodies, &rows);
  std::vector<double> p;
  for (const JointRow& r : rows) p.push_back(r.phi);
  return p;
}
} // namespace

// G v against (Phi(q + h v) - Phi(q - h v)) / 2h at poses moved off the assembly, for every joint type, to the
// world and between two bodies. Measured: largest difference 2.5e-10 (round-off of the differences at h = 1e-5).
TEST(ContactJoints, RowsAreTheJacobianOfPhi) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Shape s;
  s.type = ShapeType::Box;
  s.half = Vec3(0.2, 0.3, 0.1);
  for (JointType t :
       {JointType::Ball, JointType::Hinge, JointType::Slider, JointType::Fixed, JointType::Distance})
    for (int to_world = 0; to_world < 2; ++to_world) {
      std::vector<Body> b = {makeBody("a", s, 1000, 0, Vec3(0, 0, 0), Quat::Identity(), false),
                             makeBody("b", s, 1000, 0, Vec3(0.5, 0.1, 0.2), Quat::Identity(), false)};
      const Joint j = makeJoint("j", t, b, 1, to_world ? -1 : 0, Vec3(0.25, 0.05, 0.1), Vec3(0.3, 1.0, 0.2),
                                Vec3(0.1, -0.2, 0.3));
      for (Body& B : b) { // off the manifold: Phi != 0, G not at its assembly value
        advancePose(&B, Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)), 0.2);
        B.v = Vec3(u(rng), u(rng), u(rng));
        B.w = Vec3(u(rng), u(rng), u(rng));
      }
      std::vector<JointRow> rows;
      jointRows(j, b, &rows);
      ASSERT_EQ((int)rows.size(), jointRowCount(t));
      const double h = 1e-5;
      std::vector<Body> plus = b, minus = b;
      for (int i = 0; i < 2; ++i) {
        advancePose(&plus[i], b[i].v, b[i].w, h);
        advancePose(&minus[i], -b[i].v, -b[i].w, h);
      }
      const std::vector<double> pp = phis(j, plus), pm = phis(j, minus);
      for (size_t k = 0; k < rows.size(); ++k) {
        double gv = rows[k].ja.head<3>().dot(b[1].v) + rows[k].ja.tail<3>().dot(b[1].w);
        if (!to_world) gv += rows[k].jb.head<3>().dot(b[0].v) + rows[k].jb.tail<3>().dot(b[0].w);
        EXPECT_NEAR(gv, (pp[k] - pm[k]) / (2 * h), 1e-8)
            << jointName(t) << " row " << k << " world " << to_world;
      }
    }
}

// A capsule link hinged at its end, released at 5 degrees, dt = 1e-4: its period against the compound pendulum's
// 2 pi sqrt(I_p / (m g L/2)) times the elliptic factor 2 K(sin(th0/2)) / pi (1.00048 at 5 degrees). Measured:
// relative difference -5.7e-8.
TEST(ContactJoints, PendulumSmallAmplitudePeriod) {
  const Model m = chain("pendulum", 1, 5.0);
  const double th0 = 5.0 * M_PI / 180, L = 0.1;
  const double exact = compoundPeriod(m.bodies[0], L) * 2 * ellipticK(std::sin(th0 / 2)) / M_PI;
  const double t = swingPeriod(m, 1e-4, 20000);
  std::printf("5-degree pendulum: period %.6f s, exact %.6f s, relative %.2e\n", t, exact, t / exact - 1);
  EXPECT_NEAR(t / exact, 1.0, 3e-7);
}

// Released from horizontal (90 degrees): the period is 2 K(sin 45 deg) / pi = 1.18034 times the small-amplitude
// one. dt = 1e-4; measured: relative difference -1.1e-7.
TEST(ContactJoints, PendulumNinetyDegreePeriodIsTheEllipticIntegral) {
  const Model m = chain("pendulum", 1, 90.0);
  const double exact = compoundPeriod(m.bodies[0], 0.1) * 2 * ellipticK(std::sin(M_PI / 4)) / M_PI;
  const double t = swingPeriod(m, 1e-4, 20000);
  std::printf("90-degree pendulum: period %.6f s, exact %.6f s, relative %.2e\n", t, exact, t / exact - 1);
  EXPECT_NEAR(t / exact, 1.0, 5e-7);
}

// A 10-link chain hanging at rest with an end load of 1, 1e2, 1e4 link masses: after a step, each joint's force
// on the link below it is the weight hanging below the joint. Measured: largest relative difference 4e-14 (load
// 1e4; 1.2e-16 at 1 and 1e2).
TEST(ContactJoints, HangingChainTensionsAreTheWeightBelow) {
  for (double ratio : {1.0, 1e2, 1e4}) {
    Model m = chain("chain", 10, 0.0, ratio);
    Stepper st(jointOptions(0.01));
    st.setJoints(m.joints);
    const StepStats s = st.step(&m.bodies);
    ASSERT_FALSE(s.failed) << s.message;
    double worst = 0.0;
    for (int k = 0; k < (int)m.joints.size(); ++k) {
      double below = 0.0;
      for (int i = m.joints[k].a; i < (int)m.bodies.size(); ++i) below += m.bodies[i].mass * kG;
      Vec3 f, t;
      st.jointReaction(k, m.bodies, &f, &t);
      worst = std::max(worst, (f - Vec3(0, 0, below)).norm() / below);
    }
    std::printf("hanging chain, end load %g: largest relative tension error %.2e\n", ratio, worst);
    EXPECT_LE(worst, 1e-12);
  }
}

// A frictionless 10-link hinge chain released at 45 degrees, dt = 1e-3, 10 s: SHAKE keeps the energy without
// drift. Measured: largest |E - E0| 0.027 J, of a swing energy (E0 - E_rest, the 45-degree release) of 14.4 J.
TEST(ContactJoints, TenLinkChainEnergyStaysBounded) {
  Model m = chain("chain", 10, 45.0);
  const double e0 = energy(m.bodies);
  double worst = 0.0;
  const double joint_error =
      stepModel(&m, 1e-3, 10000, [&] { worst = std::max(worst, std::abs(energy(m.bodies) - e0)); });
  std::printf("10-link chain, 10 s at dt 1e-3: largest |E - E0| %.3e J, joint error %.2e\n", worst,
              joint_error);
  EXPECT_LE(joint_error, 1e-9);
  EXPECT_LE(worst, 0.04);
}

// A 100-link chain falling from horizontal at dt = 0.01 (its tip turns by up to about 1 rad per step): every
// step ends on the joints' manifold, and the energy never rises above its start. Measured over 300 steps:
// largest joint error 1e-11 m, largest rise 0 J.
TEST(ContactJoints, LongChainAtLargeStepStaysOnTheManifold) {
  Model m = chain("chain", 100, 90.0);
  const double e0 = energy(m.bodies);
  double rise = 0.0;
  const double joint_error = stepModel(&m, 0.01, 300, [&] { rise = std::max(rise, energy(m.bodies) - e0); });
  std::printf("100-link chain from horizontal, dt 0.01: joint error %.2e m, energy rise %.2e J\n",
              joint_error, rise);
  EXPECT_LE(joint_error, 1e-9);
  EXPECT_LE(rise, 1e-9);
}

TEST(ContactJoints, SceneFileJointLines) {
  const std::string bodies = "sphere name=s radius=0.1 pos=0,0,-1\nbox name=b half=0.1,0.1,0.1 pos=1,0,-1\n";
  const Model m = parseSceneModel(bodies + "joint type=ball a=s anchor=0,0,0 name=top\n"
                                           "joint type=hinge a=b b=s anchor=0.5,0,-1 axis=0,1,0\n",
                                  "t.scene");
  ASSERT_EQ(m.joints.size(), 2u);
  EXPECT_EQ(m.joints[0].name, "top");
  EXPECT_EQ(m.joints[0].b, -1);
  EXPECT_EQ(m.joints[1].type, JointType::Hinge);
  EXPECT_EQ(m.joints[1].a, 1);
  EXPECT_EQ(m.joints[1].b, 0);
  auto msg = [&](const std::string& line) {
    try {
      parseSceneModel(bodies + line, "t.scene");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(msg("joint type=screw a=s anchor=0,0,0\n").find("t.scene:3: unknown joint type 'screw'"),
            std::string::npos);
  EXPECT_NE(msg("joint type=ball a=s\n").find("t.scene:3: joint needs anchor=x,y,z"), std::string::npos);
  EXPECT_NE(msg("joint type=ball a=nobody anchor=0,0,0\n").find("t.scene:3: no body named 'nobody'"),
            std::string::npos);
  EXPECT_NE(
      msg("joint type=ball a=s anchor=0,0,0 colour=red\n").find("t.scene:3: unknown joint key 'colour'"),
      std::string::npos);
  EXPECT_NE(msg("joint type=hinge a=s anchor=0,0,0 axis=0,0,0\n").find("t.scene:3:"), std::string::npos);
  EXPECT_NE(msg("joint type=distance a=s anchor=0,0,0\n").find("t.scene:3: a distance joint needs anchor_b"),
            std::string::npos);
}

namespace {
// Angle of a link's axis in the x-z plane from +x towards +z, and its end point farther from p.
Vec3 farEnd(const Body& b, const Vec3& p) {
  const Vec3 e = b.x + b.shape.half_length * b.axis(), f = b.x - b.shape.half_length * b.axis();
  return (e - p).norm() > (f - p).norm() ? e : f;
}
} // namespace

// The four-bar (a Grashof crank-rocker, closed loop with 3 redundant hinge rows), turning under gravity at
// dt = 1e-3 for 2 s: at every step the coupler-rocker joint lies where the closed-form position analysis puts it
// for the crank's angle, and the loop stays closed. Measured: largest distance 3.1e-11 m, joint error 1e-11, the
// crank turned 17.4 rad.
TEST(ContactJoints, FourBarFollowsItsClosedFormKinematics) {
  SceneParams p;
  p.scene = "four_bar";
  p.crank_speed = 40.0; // the first step shares it with the coupler and rocker: enough to go round
  Model m = buildModel(p);
  const Vec3 O4(p.ground_length, 0, 0);
  double worst = 0.0, turned = 0.0, last = M_PI / 2; // the crank starts at -crank_angle 90
  const double joint_error = stepModel(&m, 1e-3, 2000, [&] {
    const Vec3 A = farEnd(m.bodies[0], Vec3::Zero());
    Vec3 B;
    worst = fourBarJoint(A, p.coupler_length, O4, p.rocker_length, &B)
                ? std::max(worst, (farEnd(m.bodies[2], O4) - B).norm())
                : INFINITY;
    const double th = std::atan2(A.z(), A.x());
    turned += std::remainder(th - last, 2 * M_PI);
    last = th;
  });
  std::printf("four-bar: rocker joint against closed form %.2e m, joint error %.2e, crank turned %.1f rad\n",
              worst, joint_error, turned);
  EXPECT_GT(std::abs(turned), 2 * M_PI); // the crank went round at least once
  EXPECT_LE(joint_error, 1e-9);
  EXPECT_LE(worst, 1e-9);
}

// The slider-crank under gravity at dt = 1e-3 for 2 s: the slider's x against a cos th + sqrt(b^2 - a^2 sin^2 th)
// at the crank's angle. Measured: largest difference 2.0e-11 m.
TEST(ContactJoints, SliderCrankFollowsItsClosedFormKinematics) {
  SceneParams p;
  p.scene = "slider_crank";
  Model m = buildModel(p);
  double worst = 0.0;
  const double joint_error = stepModel(&m, 1e-3, 2000, [&] {
    const Vec3 A = farEnd(m.bodies[0], Vec3::Zero());
    const double x = sliderCrankPosition(p.crank_length, p.coupler_length, std::atan2(A.z(), A.x()));
    worst = std::max(worst, (m.bodies[2].x - Vec3(x, 0, 0)).norm());
  });
  std::printf("slider-crank: slider against closed form %.2e m, joint error %.2e\n", worst, joint_error);
  EXPECT_LE(joint_error, 1e-9);
  EXPECT_LE(worst, 1e-9);
}
