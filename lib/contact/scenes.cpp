// Scene builders (incline, drop, box_stack, pyramid, pile_grid, log_heap, file) and the static-overlap check.
// The log heap follows the experiment of Lacoursiere, SIGRAD 2003 (N identical logs dropped into a heap),
// with the logs modelled as capsules.
#include "contact/scenes.hpp"

#include "contact/collision.hpp"
#include "contact/mjcf.hpp"

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace suite::contact {

namespace {
constexpr double kDeg = M_PI / 180.0;

void require(bool ok, const std::string& msg) {
  if (!ok) throw SceneError(msg);
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

Shape boxShape(double edge) {
  Shape s;
  s.type = ShapeType::Box;
  s.half = Vec3::Constant(0.5 * edge);
  return s;
}

} // namespace

Body makePlane(const std::string& name, const Vec3& n, const Vec3& point) {
  Shape s;
  s.type = ShapeType::Plane;
  return makeBody(name, s, 0.0, 0.0, point, Quat::FromTwoVectors(Vec3::UnitZ(), n.normalized()), true);
}

namespace {

std::vector<Body> inclineScene(const SceneParams& p) {
  require(p.theta_deg >= 0 && p.theta_deg < 90,
          "-theta " + num(p.theta_deg) + ": must be in [0, 90) degrees");
  const Quat q(Eigen::AngleAxisd(-p.theta_deg * kDeg, Vec3::UnitY()));
  const Vec3 n = q * Vec3::UnitZ();
  Shape s;
  s.type = ShapeType::Plane;
  std::vector<Body> b;
  b.push_back(makeBody("incline", s, 0, 0, Vec3::Zero(), q, true));
  b.push_back(makeBody("box", boxShape(p.size), p.density, p.mass, 0.5 * p.size * n, q, false));
  const Vec3 downhill = q * Vec3(-1, 0, 0);
  b.back().v = p.v0 * downhill;
  return b;
}

// Height of the body's lowest point below its centre (orientation R).
double lowestPoint(const Shape& s, const Mat3& R) {
  switch (s.type) {
  case ShapeType::Sphere:
    return s.radius;
  case ShapeType::Box:
    return (R.transpose() * Vec3::UnitZ()).cwiseAbs().dot(s.half);
  case ShapeType::Capsule:
    return s.radius + s.half_length * std::abs(R(2, 2));
  case ShapeType::Cylinder:
    return s.half_length * std::abs(R(2, 2)) + s.radius * std::sqrt(std::max(0.0, 1 - R(2, 2) * R(2, 2)));
  default:
    return 0.0;
  }
}

std::vector<Body> dropScene(const SceneParams& p) {
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  require(p.height >= 0, "-height " + num(p.height) + ": must be >= 0");
  Shape s;
  s.type = shapeFromName(p.drop_body);
  require(s.type != ShapeType::Plane, "-drop_body plane: a plane cannot be dropped");
  s.radius = 0.5 * p.size;
  s.half = Vec3::Constant(0.5 * p.size);
  s.half_length = 0.5 * p.size;
  const Quat q(Eigen::AngleAxisd(p.tilt_deg * kDeg, Vec3::UnitX()));
  Body body = makeBody(p.drop_body, s, p.density, p.mass, Vec3::Zero(), q, false);
  body.x = Vec3(0, 0, lowestPoint(s, body.R()) + p.height); // lowest point at 'height' above the plane
  body.v = Vec3(p.v0, 0, 0);
  body.w = Vec3(0, p.spin, 0);
  b.push_back(body);
  return b;
}

std::vector<Body> boxStackScene(const SceneParams& p) {
  require(p.stack_height >= 1, "-stack_height " + std::to_string(p.stack_height) + ": must be >= 1");
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  for (int i = 0; i < p.stack_height; ++i)
    b.push_back(makeBody("box" + std::to_string(i), boxShape(p.size), p.density, 0.0,
                         Vec3(0, 0, (i + 0.5) * p.size), Quat::Identity(), false));
  return b;
}

// A planar pyramid of boxes (base boxes in the bottom row, gaps of 0.1 size in a row) centred at (cx, cy).
void addPyramid(const SceneParams& p, int base, double cx, double cy, const std::string& prefix,
                std::vector<Body>* b) {
  const double pitch = 1.1 * p.size; // gap of 0.1 size between neighbours of a row
  for (int k = 0; k < base; ++k)
    for (int j = 0; j < base - k; ++j) {
      const double x = cx + (j - 0.5 * (base - k - 1)) * pitch;
      b->push_back(makeBody(prefix + "box" + std::to_string(k) + "_" + std::to_string(j), boxShape(p.size),
                            p.density, 0.0, Vec3(x, cy, (k + 0.5) * p.size), Quat::Identity(), false));
    }
}

std::vector<Body> pyramidScene(const SceneParams& p) {
  require(p.pyramid_base >= 1, "-pyramid_base " + std::to_string(p.pyramid_base) + ": must be >= 1");
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  addPyramid(p, p.pyramid_base, 0.0, 0.0, "", &b);
  return b;
}

// -piles pyramids of base -pyramid_base on one ground, on a square grid with one box edge between neighbours:
// independent piles that touch only the (static) ground, the islands of -contact_islands.
std::vector<Body> pileGridScene(const SceneParams& p) {
  require(p.pyramid_base >= 1, "-pyramid_base " + std::to_string(p.pyramid_base) + ": must be >= 1");
  require(p.piles >= 1, "-piles " + std::to_string(p.piles) + ": must be >= 1");
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero())};
  const int cols = (int)std::ceil(std::sqrt((double)p.piles));
  const double dx = (1.1 * p.pyramid_base + 1.0) * p.size, dy = 2.0 * p.size;
  for (int k = 0; k < p.piles; ++k)
    addPyramid(p, p.pyramid_base, (k % cols) * dx, (k / cols) * dy, "pile" + std::to_string(k) + "_", &b);
  return b;
}

std::vector<Body> logHeapScene(const SceneParams& p) {
  require(p.n_logs >= 1, "-n_logs " + std::to_string(p.n_logs) + ": must be >= 1");
  require(p.log_radius > 0, "-log_radius " + num(p.log_radius) + ": must be > 0");
  require(p.log_length > 0, "-log_length " + num(p.log_length) + ": must be > 0");
  const double r = p.log_radius, hl = 0.5 * p.log_length;
  const int per_layer = 5;
  const double pitch = 3.0 * r;
  const double wx = 0.5 * per_layer * pitch + 2 * r, wy = hl + r + 0.3 * p.log_length;
  std::vector<Body> b{makePlane("ground", Vec3::UnitZ(), Vec3::Zero()),
                      makePlane("wall_xm", Vec3::UnitX(), Vec3(-wx, 0, 0)),
                      makePlane("wall_xp", -Vec3::UnitX(), Vec3(wx, 0, 0)),
                      makePlane("wall_ym", Vec3::UnitY(), Vec3(0, -wy, 0)),
                      makePlane("wall_yp", -Vec3::UnitY(), Vec3(0, wy, 0))};
  std::mt19937 rng(p.seed);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = r;
  s.half_length = hl;
  for (int i = 0; i < p.n_logs; ++i) {
    const int layer = i / per_layer, j = i % per_layer;
    const double x = (j - 0.5 * (per_layer - 1)) * pitch + 0.3 * r * jitter(rng);
    const double z = r + 0.5 * r + layer * 3.0 * r;
    const double yaw = 0.15 * jitter(rng), pitch_ang = 0.1 * jitter(rng);
    const Quat q = Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ())) *
                   Quat(Eigen::AngleAxisd(pitch_ang, Vec3::UnitY())) *
                   Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())); // axis along y
    b.push_back(
        makeBody("log" + std::to_string(i), s, p.density, 0.0, Vec3(x, 0.1 * r * jitter(rng), z), q, false));
  }
  return b;
}

Model fileScene(const SceneParams& p) {
  require(!p.file.empty(), "-scene file needs -scene_file PATH");
  return readSceneFile(p.file);
}

Model mjcfScene(const SceneParams& p) {
  require(!p.file.empty(), "-scene mjcf needs -scene_file PATH (an MJCF model)");
  return readMjcfFile(p.file);
}

// n capsule links hinged to the world at the origin (see SceneParams), the end sphere of chain.
// The end sphere has radius ball_radius (0: 2 link radii) and the chain hangs from origin.
Model linkChain(const SceneParams& p, int n, bool end_load, const Vec3& origin = Vec3::Zero(),
                double ball_radius = 0.0) {
  require(n >= 1, "-links " + std::to_string(n) + ": must be >= 1");
  require(p.link_length > 0 && std::isfinite(p.link_length),
          "-link_length " + num(p.link_length) + ": must be > 0");
  require(p.link_radius > 0 && std::isfinite(p.link_radius),
          "-link_radius " + num(p.link_radius) + ": must be > 0");
  require(p.link_mass > 0 && std::isfinite(p.link_mass), "-link_mass " + num(p.link_mass) + ": must be > 0");
  require(p.end_mass_ratio >= 0 && std::isfinite(p.end_mass_ratio),
          "-end_mass_ratio " + num(p.end_mass_ratio) + ": must be >= 0");
  require(std::isfinite(p.angle_deg), "-angle: must be finite");
  const JointType type = jointFromName(p.joint_type);
  require(type == JointType::Hinge || type == JointType::Ball,
          "-joint_type " + p.joint_type + ": the chain scenes take hinge or ball");
  const double L = p.link_length, th = p.angle_deg * kDeg;
  const Vec3 d(std::sin(th), 0.0, -std::cos(th)); // along the chain, from the world anchor
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = p.link_radius;
  s.half_length = 0.5 * L;
  const Quat q = Quat::FromTwoVectors(Vec3::UnitZ(), d);
  Model m;
  for (int k = 0; k < n; ++k) {
    m.bodies.push_back(
        makeBody("link" + std::to_string(k), s, 0.0, p.link_mass, origin + (k + 0.5) * L * d, q, false));
    m.joints.push_back(makeJoint("joint" + std::to_string(k), type, m.bodies, k, k > 0 ? k - 1 : -1,
                                 origin + k * L * d, Vec3::UnitY()));
  }
  if (end_load && p.end_mass_ratio > 0) {
    Shape ball;
    ball.type = ShapeType::Sphere;
    ball.radius = ball_radius > 0 ? ball_radius : 2 * p.link_radius;
    m.bodies.push_back(makeBody("load", ball, 0.0, p.end_mass_ratio * p.link_mass,
                                origin + (n * L + ball.radius) * d, Quat::Identity(), false));
    m.joints.push_back(makeJoint("joint_load", type, m.bodies, n, n - 1, origin + n * L * d, Vec3::UnitY()));
  }
  for (Body& b : m.bodies)
    b.contype = 2, b.conaffinity = 1; // links collide with other bodies, not each other
  return m;
}

Model pendulumScene(const SceneParams& p) {
  return linkChain(p, 1, false);
}
Model doublePendulumScene(const SceneParams& p) {
  return linkChain(p, 2, false);
}
Model chainScene(const SceneParams& p) {
  return linkChain(p, p.links, true);
}

// The lever of motor_limit (SceneParams): the pendulum's link with a limit and a motor on its hinge. The hinge
// coordinate is the world's turn relative to the link about y (joint.hpp): raising the link (turning it about
// -y) increases it, so the motor's target speed is +motor_speed.
Model motorLimitScene(const SceneParams& p) {
  require(p.limit_angle_deg > 0 && p.limit_angle_deg < 180,
          "-limit_angle " + num(p.limit_angle_deg) + ": must be in (0, 180) degrees");
  require(std::isfinite(p.motor_speed), "-motor_speed: must be finite");
  require(p.motor_torque > 0 && std::isfinite(p.motor_torque),
          "-motor_torque " + num(p.motor_torque) + ": must be > 0");
  Model m = linkChain(p, 1, false);
  Joint& j = m.joints[0];
  j.name = "lever";
  j.limited = true;
  j.lower = -p.limit_angle_deg * kDeg;
  j.upper = p.limit_angle_deg * kDeg;
  j.motor = true;
  j.target_speed = p.motor_speed;
  j.max_force = p.motor_torque;
  return m;
}

// The wrecking ball (SceneParams): the chain of -links links with an end sphere of -ball_radius and
// -end_mass_ratio link masses, hung so that the sphere passes just above the ground, released at -angle, and a
// pyramid of -pyramid_base cubes (edge -ball_radius, -density) in its path.
Model wreckingBallScene(const SceneParams& p) {
  require(p.end_mass_ratio > 0, "wrecking_ball: needs -end_mass_ratio > 0 (the ball)");
  require(p.ball_radius > 0 && std::isfinite(p.ball_radius),
          "-ball_radius " + num(p.ball_radius) + ": must be > 0");
  require(p.pyramid_base >= 1, "-pyramid_base " + std::to_string(p.pyramid_base) + ": must be >= 1");
  const double r = p.ball_radius, h = p.links * p.link_length + 2 * r + 0.1 * r;
  Model m = linkChain(p, p.links, true, Vec3(0, 0, h), r);
  m.bodies.push_back(makePlane("ground", Vec3::UnitZ(), Vec3::Zero()));
  SceneParams q = p;
  q.size = r;
  addPyramid(q, p.pyramid_base, 0.55 * p.pyramid_base * r + 1.5 * r, 0.0, "", &m.bodies);
  return m;
}

// A capsule link of radius r and mass m from p to q (its axis along q - p).
Body linkBetween(const std::string& name, const Vec3& p, const Vec3& q, double r, double m) {
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = r;
  s.half_length = 0.5 * (q - p).norm();
  Body b = makeBody(name, s, 0.0, m, 0.5 * (p + q), Quat::FromTwoVectors(Vec3::UnitZ(), q - p), false);
  b.contype = 2, b.conaffinity = 1; // the links collide with other bodies, not with each other
  return b;
}

// The four-bar (SceneParams): crank O2-A, coupler A-B, rocker O4-B in the x-z plane, hinges about y at the
// ground pivots O2 = 0 and O4 = (ground, 0, 0), the crank at -crank_angle from +x towards +z.
Model fourBarScene(const SceneParams& p) {
  const double a = p.crank_length, b = p.coupler_length, c = p.rocker_length, d = p.ground_length;
  require(a > 0 && b > 0 && c > 0 && d > 0,
          "-crank_length, -coupler_length, -rocker_length, -ground_length: must be > 0");
  const Vec3 A(a * std::cos(p.crank_angle_deg * kDeg), 0, a * std::sin(p.crank_angle_deg * kDeg)),
      O4(d, 0, 0);
  Vec3 B;
  require(fourBarJoint(A, b, O4, c, &B),
          "four_bar: the links do not close at -crank_angle " + num(p.crank_angle_deg));
  Model m;
  m.bodies = {linkBetween("crank", Vec3::Zero(), A, p.link_radius, p.link_mass),
              linkBetween("coupler", A, B, p.link_radius, p.link_mass),
              linkBetween("rocker", O4, B, p.link_radius, p.link_mass)};
  m.bodies[0].w = Vec3(0, -p.crank_speed, 0); // a turn about -y raises the angle from +x towards +z
  m.joints = {makeJoint("O2", JointType::Hinge, m.bodies, 0, -1, Vec3::Zero(), Vec3::UnitY()),
              makeJoint("A", JointType::Hinge, m.bodies, 1, 0, A, Vec3::UnitY()),
              makeJoint("O4", JointType::Hinge, m.bodies, 2, -1, O4, Vec3::UnitY()),
              makeJoint("B", JointType::Hinge, m.bodies, 1, 2, B, Vec3::UnitY())};
  return m;
}

// The slider-crank (SceneParams): crank O-A, connecting rod A-B, a box slider at B on a slider joint along x
// (to the world) hinged to the rod.
Model sliderCrankScene(const SceneParams& p) {
  const double a = p.crank_length, b = p.coupler_length;
  require(a > 0 && b > a, "slider_crank: needs -coupler_length > -crank_length > 0");
  const double th = p.crank_angle_deg * kDeg;
  const Vec3 A(a * std::cos(th), 0, a * std::sin(th));
  const Vec3 B(sliderCrankPosition(a, b, th), 0, 0);
  Shape box;
  box.type = ShapeType::Box;
  box.half = Vec3(2, 1, 1) * p.link_radius;
  Model m;
  m.bodies = {linkBetween("crank", Vec3::Zero(), A, p.link_radius, p.link_mass),
              linkBetween("rod", A, B, p.link_radius, p.link_mass),
              makeBody("slider", box, 0.0, p.link_mass, B, Quat::Identity(), false)};
  m.bodies[2].contype = 2, m.bodies[2].conaffinity = 1;
  m.bodies[0].w = Vec3(0, -p.crank_speed, 0);
  m.joints = {makeJoint("O", JointType::Hinge, m.bodies, 0, -1, Vec3::Zero(), Vec3::UnitY()),
              makeJoint("A", JointType::Hinge, m.bodies, 1, 0, A, Vec3::UnitY()),
              makeJoint("B", JointType::Hinge, m.bodies, 2, 1, B, Vec3::UnitY()),
              makeJoint("guide", JointType::Slider, m.bodies, 2, -1, B, Vec3::UnitX())};
  return m;
}

// The rope bridge (SceneParams): -links planks hinged edge to edge about y, the end edges hinged to the world,
// hanging in a V of -sag_angle degrees, and -bridge_boxes boxes dropped onto its middle.
Model ropeBridgeScene(const SceneParams& p) {
  require(p.links >= 2, "-links " + std::to_string(p.links) + ": rope_bridge needs >= 2 planks");
  require(p.bridge_boxes >= 0, "-bridge_boxes " + std::to_string(p.bridge_boxes) + ": must be >= 0");
  require(p.sag_angle_deg > 0 && p.sag_angle_deg < 90,
          "-sag_angle " + num(p.sag_angle_deg) + ": must be in (0, 90)");
  const double L = p.link_length, al = p.sag_angle_deg * kDeg;
  Shape plank;
  plank.type = ShapeType::Box;
  plank.half = Vec3(0.5 * L, 2 * L, 0.1 * L);
  Model m;
  Vec3 at = Vec3::Zero(), low = at;
  for (int k = 0; k < p.links; ++k) { // the left half goes down, the right half up
    const Vec3 d(std::cos(al), 0, 2 * k < p.links ? -std::sin(al) : std::sin(al));
    m.bodies.push_back(makeBody("plank" + std::to_string(k), plank, 0.0, p.link_mass, at + 0.5 * L * d,
                                Quat::FromTwoVectors(Vec3::UnitX(), d), false));
    m.bodies.back().contype = 2, m.bodies.back().conaffinity = 1; // planks collide with the boxes only
    m.joints.push_back(makeJoint("hinge" + std::to_string(k), JointType::Hinge, m.bodies, k,
                                 k > 0 ? k - 1 : -1, at, Vec3::UnitY()));
    at += L * d;
    if (at.z() < low.z()) low = at;
  }
  m.joints.push_back(makeJoint("hinge" + std::to_string(p.links), JointType::Hinge, m.bodies, p.links - 1, -1,
                               at, Vec3::UnitY()));
  Shape box;
  box.type = ShapeType::Box;
  box.half = Vec3::Constant(0.25 * L);
  for (int i = 0; i < p.bridge_boxes; ++i)
    m.bodies.push_back(makeBody("box" + std::to_string(i), box, 0.0, p.link_mass,
                                low + Vec3(0, 0, (1.5 + 1.0 * i) * L), Quat::Identity(), false));
  return m;
}

// A builder of bodies only, as a model without joints.
template <std::vector<Body> (*F)(const SceneParams&)> Model bodiesOnly(const SceneParams& p) {
  Model m;
  m.bodies = F(p);
  return m;
}

// The scene registry: one line per scene (name, one-line description for -help, builder).
struct SceneEntry {
  const char* name;
  const char* description;
  Model (*build)(const SceneParams&);
};

const std::vector<SceneEntry>& registry() {
  static const std::vector<SceneEntry> r = {
      {"incline", "a box on a plane inclined by -theta degrees", bodiesOnly<inclineScene>},
      {"drop", "one -drop_body dropped from -height onto a plane", bodiesOnly<dropScene>},
      {"box_stack", "a column of -stack_height boxes on the ground", bodiesOnly<boxStackScene>},
      {"pyramid", "a pyramid of boxes, -pyramid_base in the bottom row", bodiesOnly<pyramidScene>},
      {"pile_grid", "-piles pyramids of base -pyramid_base on a grid (independent piles)",
       bodiesOnly<pileGridScene>},
      {"log_heap", "-n_logs capsule logs dropped between four walls (Lacoursiere 2003)",
       bodiesOnly<logHeapScene>},
      {"pendulum", "one capsule link on a hinge to the world, released at -angle degrees", pendulumScene},
      {"double_pendulum", "two capsule links on hinges, released at -angle degrees", doublePendulumScene},
      {"chain", "-links capsule links on -joint_type joints with an end load of -end_mass_ratio", chainScene},
      {"four_bar", "a four-bar linkage of capsule links (closed loop), the crank turning at -crank_speed",
       fourBarScene},
      {"slider_crank",
       "a crank, connecting rod and slider on a guide (closed loop), the crank at -crank_speed",
       sliderCrankScene},
      {"rope_bridge",
       "-links planks hinged in a V between two world hinges, -bridge_boxes boxes dropped on it",
       ropeBridgeScene},
      {"wrecking_ball",
       "a chain with a heavy sphere (-end_mass_ratio, -ball_radius) swung into a box pyramid",
       wreckingBallScene},
      {"motor_limit",
       "a link on a hinge driven by a bounded motor (-motor_speed, -motor_torque) against a limit "
       "(-limit_angle)",
       motorLimitScene},
      {"file", "the bodies and joints of -scene_file (format: docs/contact.md#scene-file-format)", fileScene},
      {"mjcf", "the MJCF model -scene_file (MuJoCo's XML; the subset: docs/contact.md#mjcf-models)",
       mjcfScene},
  };
  return r;
}

} // namespace

std::vector<std::string> sceneNames() {
  std::vector<std::string> v;
  for (const SceneEntry& e : registry()) v.push_back(e.name);
  return v;
}

std::vector<Choice> sceneChoices() {
  return choicesOf(registry());
}

std::vector<Body> buildScene(const SceneParams& p) {
  return buildModel(p).bodies;
}

Model buildModel(const SceneParams& p) {
  require(p.size > 0 && std::isfinite(p.size), "-size " + num(p.size) + ": must be > 0");
  require(p.density > 0 && std::isfinite(p.density), "-density " + num(p.density) + ": must be > 0");
  require(p.mass >= 0 && std::isfinite(p.mass), "-mass " + num(p.mass) + ": must be > 0 (0 = from -density)");
  for (const SceneEntry& e : registry())
    if (p.scene == e.name) return e.build(p);
  std::string list;
  for (const auto& s : sceneNames()) list += (list.empty() ? "" : ", ") + s;
  throw SceneError("-scene " + p.scene + ": unknown scene (" + list + ")");
}

namespace {
Vec3 parseVec(const std::string& where, const std::string& key, const std::string& v, int n, double* extra) {
  std::vector<double> x;
  std::stringstream ss(v);
  std::string tok;
  while (std::getline(ss, tok, ',')) {
    char* end = nullptr;
    const double d = std::strtod(tok.c_str(), &end);
    require(end && *end == '\0' && !tok.empty() && std::isfinite(d),
            where + ": bad number '" + tok + "' in " + key);
    x.push_back(d);
  }
  require((int)x.size() == n,
          where + ": " + key + " needs " + std::to_string(n) + " comma-separated numbers");
  if (extra && n == 4) *extra = x[3];
  return Vec3(x[0], x[1], n > 2 ? x[2] : 0.0); // n = 2: (x0, x1, 0)
}
} // namespace

Model readSceneFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  require((bool)in, "scene file " + path + ": cannot open");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  require(size >= 0 && size <= kMaxSceneBytes,
          "scene file " + path + ": larger than " + std::to_string(kMaxSceneBytes) + " bytes");
  in.seekg(0);
  std::string text((size_t)size, '\0');
  in.read(&text[0], size);
  return parseSceneModel(text, path);
}

namespace {
// The keys of one body line, with their defaults.
struct BodyLine {
  Shape s;
  std::string name;
  Vec3 pos = Vec3::Zero(), normal = Vec3::UnitZ(), vel = Vec3::Zero(), omega = Vec3::Zero();
  Quat q = Quat::Identity();
  double density = 1000.0, mass = 0.0;
  bool is_static = false;
};

double parseScalar(const std::string& where, const std::string& k, const std::string& v) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  require(end && *end == '\0' && !v.empty() && std::isfinite(d), where + ": bad number '" + v + "' for " + k);
  return d;
}

// One key=value token (or "static") of a body line.
void parseKey(const std::string& where, const std::string& tok, BodyLine* b) {
  if (tok == "static") {
    b->is_static = true;
    return;
  }
  const auto eq = tok.find('=');
  require(eq != std::string::npos, where + ": expected key=value, got '" + tok + "'");
  const std::string k = tok.substr(0, eq), v = tok.substr(eq + 1);
  double deg = 0.0;
  if (k == "name")
    b->name = v;
  else if (k == "pos" || k == "point")
    b->pos = parseVec(where, k, v, 3, nullptr);
  else if (k == "normal")
    b->normal = parseVec(where, k, v, 3, nullptr);
  else if (k == "vel")
    b->vel = parseVec(where, k, v, 3, nullptr);
  else if (k == "omega")
    b->omega = parseVec(where, k, v, 3, nullptr);
  else if (k == "half")
    b->s.half = parseVec(where, k, v, 3, nullptr);
  else if (k == "axis_angle") {
    const Vec3 ax = parseVec(where, k, v, 4, &deg);
    require(ax.norm() > 0, where + ": axis_angle needs a non-zero axis");
    b->q = Quat(Eigen::AngleAxisd(deg * kDeg, ax.normalized()));
  } else if (k == "radius")
    b->s.radius = parseScalar(where, k, v);
  else if (k == "half_length")
    b->s.half_length = parseScalar(where, k, v);
  else if (k == "density")
    b->density = parseScalar(where, k, v);
  else if (k == "mass") {
    b->mass = parseScalar(where, k, v);
    require(b->mass > 0, where + ": body '" + b->name + "': mass " + v + ": must be > 0 and finite");
  } else
    throw SceneError(where + ": unknown key '" + k + "'");
}

// The body of a line "type key=value ...", default name type<index>; errors name `where`.
Body parseBody(const std::string& where, const std::string& type, std::stringstream& ss, size_t index) {
  BodyLine b;
  try {
    b.s.type = shapeFromName(type);
  } catch (const SceneError& e) {
    throw SceneError(where + ": " + e.what());
  }
  b.name = type + std::to_string(index);
  b.is_static = b.s.type == ShapeType::Plane;
  for (std::string tok; ss >> tok;) parseKey(where, tok, &b);
  try {
    if (b.s.type == ShapeType::Plane) {
      require(b.normal.norm() > 0, "plane normal must be non-zero");
      return makePlane(b.name, b.normal, b.pos);
    }
    Body body = makeBody(b.name, b.s, b.density, b.mass, b.pos, b.q, b.is_static);
    body.v = b.vel;
    body.w = b.omega;
    return body;
  } catch (const SceneError& e) {
    throw SceneError(where + ": " + e.what());
  }
}
// A joint line (scene file): its keys, the bodies by name until every body is read.
struct JointLine {
  std::string where, name, type, a, b = "world";
  Vec3 anchor = Vec3::Zero(), axis = Vec3::Zero(), anchor_b = Vec3::Zero();
  bool has_anchor = false, has_anchor_b = false;
  Vec3 limit = Vec3::Zero(), motor = Vec3::Zero(); // (lower, upper, 0), (speed, bound, 0)
  bool has_limit = false, has_motor = false;
};

JointLine parseJointLine(const std::string& where, std::stringstream& ss, size_t index) {
  JointLine j;
  j.where = where;
  j.name = "joint" + std::to_string(index);
  for (std::string tok; ss >> tok;) {
    const auto eq = tok.find('=');
    require(eq != std::string::npos, where + ": expected key=value, got '" + tok + "'");
    const std::string k = tok.substr(0, eq), v = tok.substr(eq + 1);
    if (k == "name")
      j.name = v;
    else if (k == "type")
      j.type = v;
    else if (k == "a")
      j.a = v;
    else if (k == "b")
      j.b = v;
    else if (k == "anchor")
      j.anchor = parseVec(where, k, v, 3, nullptr), j.has_anchor = true;
    else if (k == "axis")
      j.axis = parseVec(where, k, v, 3, nullptr);
    else if (k == "anchor_b")
      j.anchor_b = parseVec(where, k, v, 3, nullptr), j.has_anchor_b = true;
    else if (k == "limit")
      j.limit = parseVec(where, k, v, 2, nullptr), j.has_limit = true;
    else if (k == "motor")
      j.motor = parseVec(where, k, v, 2, nullptr), j.has_motor = true;
    else
      throw SceneError(where + ": unknown joint key '" + k + "'");
  }
  require(!j.type.empty(), where + ": joint needs type=ball|hinge|slider|fixed|distance");
  require(!j.a.empty(), where + ": joint needs a=BODY");
  require(j.has_anchor, where + ": joint needs anchor=x,y,z");
  return j;
}

// The index of the body named name (-1 for "world"); a missing or ambiguous name is an error at where.
int bodyIndex(const std::vector<Body>& bodies, const std::string& name, const std::string& where) {
  if (name == "world") return -1;
  int found = -1;
  for (int i = 0; i < (int)bodies.size(); ++i)
    if (bodies[i].name == name) {
      require(found < 0, where + ": body name '" + name + "' is not unique");
      found = i;
    }
  require(found >= 0, where + ": no body named '" + name + "'");
  return found;
}

std::vector<Joint> resolveJoints(const std::vector<JointLine>& lines, const std::vector<Body>& bodies) {
  std::vector<Joint> joints;
  for (const JointLine& l : lines) {
    try {
      const JointType type = jointFromName(l.type);
      require(type != JointType::Distance || l.has_anchor_b, "a distance joint needs anchor_b=x,y,z");
      const int a = bodyIndex(bodies, l.a, l.where), b = bodyIndex(bodies, l.b, l.where);
      Joint j = makeJoint(l.name, type, bodies, a, b, l.anchor, l.axis, l.anchor_b);
      const bool axial = type == JointType::Hinge || type == JointType::Slider;
      require(axial || !(l.has_limit || l.has_motor), "limit= and motor= need a hinge or a slider");
      const double unit = type == JointType::Hinge ? M_PI / 180 : 1.0; // hinge limits in degrees
      if (l.has_limit) j.limited = true, j.lower = l.limit[0] * unit, j.upper = l.limit[1] * unit;
      if (l.has_motor) j.motor = true, j.target_speed = l.motor[0], j.max_force = l.motor[1];
      joints.push_back(j);
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      throw SceneError(msg.rfind(l.where, 0) == 0 ? msg : l.where + ": " + msg);
    }
  }
  return joints;
}
} // namespace

bool fourBarJoint(const Vec3& A, double b, const Vec3& O4, double c, Vec3* B) {
  const Vec3 e = O4 - A; // in the x-z plane; B on the circles |B - A| = b, |B - O4| = c, the upper branch
  const double d = e.norm();
  if (!(d > 0) || d > b + c || d < std::abs(b - c)) return false;
  const double along = (b * b - c * c + d * d) / (2 * d), h = std::sqrt(std::max(0.0, b * b - along * along));
  const Vec3 u = e / d, n(-u.z(), 0, u.x()); // n: u turned by +90 degrees towards +z
  *B = A + along * u + h * n;
  return true;
}

double sliderCrankPosition(double a, double b, double th) {
  return a * std::cos(th) + std::sqrt(b * b - a * a * std::sin(th) * std::sin(th));
}

std::vector<Body> parseScene(const std::string& text, const std::string& path) {
  return parseSceneModel(text, path).bodies;
}

Model parseSceneModel(const std::string& text, const std::string& path) {
  require(text.size() <= (size_t)kMaxSceneBytes,
          "scene file " + path + ": larger than " + std::to_string(kMaxSceneBytes) + " bytes");
  std::istringstream in(text);
  std::vector<Body> bodies;
  std::vector<JointLine> joint_lines;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    require(bodies.size() < (size_t)kMaxSceneBodies, path + ":" + std::to_string(lineno) + ": more than " +
                                                         std::to_string(kMaxSceneBodies) + " bodies");
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::stringstream ss(line);
    std::string type;
    if (!(ss >> type)) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    if (type == "joint")
      joint_lines.push_back(parseJointLine(where, ss, joint_lines.size()));
    else
      bodies.push_back(parseBody(where, type, ss, bodies.size()));
  }
  require(!bodies.empty(), "scene file " + path + ": no bodies");
  Model m;
  m.joints = resolveJoints(joint_lines, bodies);
  m.bodies = std::move(bodies);
  return m;
}

Model buildValidModel(const SceneParams& p, double overlap_tol) {
  Model m = buildModel(p);
  std::vector<Body>& bodies = m.bodies;
  validateScene(bodies, overlap_tol);
  for (size_t i = 0; i < bodies.size(); ++i) // every pair the scene can produce has a contact generator
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      std::vector<Contact> tmp;
      collide(bodies, (int)i, (int)j, -INFINITY, &tmp);
    }
  return m;
}

void validateScene(const std::vector<Body>& bodies, double tol) {
  for (auto& [i, j] : broadPhase(bodies, 0.0, true)) {
    if (!bodies[i].is_static || !bodies[j].is_static) continue;
    std::vector<Contact> cs;
    collide(bodies, i, j, 0.0, &cs);
    for (const Contact& c : cs)
      require(c.phi >= -tol, "static bodies '" + bodies[i].name + "' and '" + bodies[j].name +
                                 "' overlap by " + num(-c.phi) + " (tolerance " + num(tol) + ")");
  }
}

} // namespace suite::contact
