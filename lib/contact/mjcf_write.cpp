// MJCF writer of mjcf.hpp (tinyxml2's streaming printer): the model's bodies as a forest of nested <body>
// elements, the remaining joints as <equality> constraints (mjcf.hpp says what is written and what is refused).
#include "contact/mjcf.hpp"
#include "contact/mjcf_conventions.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_set>
#include <string>
#include <vector>

namespace suite::contact {

namespace {
using namespace mjcf;

class Writer {
public:
  explicit Writer(const Model& m) : m_(m), pr_(nullptr, false) {}
  std::string write(const std::string& model_name);

private:
  [[noreturn]] void fail(int k, const std::string& why) const {
    throw SceneError("joint '" + m_.joints[k].name + "' cannot be written as MJCF: " + why);
  }
  void names();
  void plan();
  int root(int i);
  void checkDepth() const;
  static std::string num(const char* name, double v); // %.17g; throws for a non-finite number
  void attr(const char* name, const std::string& v) { pr_.PushAttribute(name, v.c_str()); }
  void attr(const char* name, double v) { attr(name, num(name, v)); }
  void attr(const char* name, double a, double b) { attr(name, num(name, a) + " " + num(name, b)); }
  void attr(const char* name, const Vec3& v) {
    attr(name, num(name, v.x()) + " " + num(name, v.y()) + " " + num(name, v.z()));
  }
  void attr(const char* name, const Quat& q) {
    attr(name, num(name, q.w()) + " " + num(name, q.x()) + " " + num(name, q.y()) + " " + num(name, q.z()));
  }
  void options();
  void body(int i, const Vec3& px, const Quat& pq);
  void geom(int i, bool in_world);
  void joint(int k);
  void equality();
  void actuators();

  const Model& m_;
  tinyxml2::XMLPrinter pr_;
  std::vector<std::string> body_names_, joint_names_;
  std::vector<int> parent_, tree_joint_, uf_, loops_, motors_;
  std::vector<std::vector<int>> children_;
  std::vector<char> as_body_; // a static body written as a jointless <body> (a joint refers to it)
};

std::string Writer::num(const char* name, double v) {
  if (!std::isfinite(v))
    throw SceneError(std::string("cannot write MJCF: a non-finite number in ") + name + "=");
  return fmt(v);
}

// Names for MJCF's references: unique, printable, not "world"; unnamed bodies and joints get body<i>, joint<k>.
void Writer::names() {
  auto check = [](const std::string& s, const char* what, std::unordered_set<std::string>* seen) {
    if (s == "world") throw SceneError(std::string("cannot write MJCF: a ") + what + " named 'world'");
    if (std::any_of(s.begin(), s.end(), [](char c) { return (unsigned char)c < 0x20; }))
      throw SceneError(std::string("cannot write MJCF: ") + what + " name with control characters");
    if (!seen->insert(s).second)
      throw SceneError(std::string("cannot write MJCF: ") + what + " name '" + s + "' is not unique");
  };
  std::unordered_set<std::string> seen, jseen;
  for (size_t i = 0; i < m_.bodies.size(); ++i) {
    body_names_.push_back(m_.bodies[i].name.empty() ? "body" + std::to_string(i) : m_.bodies[i].name);
    check(body_names_.back(), "body", &seen);
  }
  for (size_t k = 0; k < m_.joints.size(); ++k) {
    joint_names_.push_back(m_.joints[k].name.empty() ? "joint" + std::to_string(k) : m_.joints[k].name);
    check(joint_names_.back(), "joint", &jseen);
  }
}

int Writer::root(int i) { // union-find over the tree edges chosen so far
  while (uf_[i] != i) i = uf_[i] = uf_[uf_[i]];
  return i;
}

// The tree joints (a body's first hinge, slider or ball joint that closes no loop) and the loop closures.
void Writer::plan() {
  const int n = (int)m_.bodies.size();
  parent_.assign(n, -1), tree_joint_.assign(n, -1), as_body_.assign(n, 0), children_.assign(n, {});
  uf_.resize(n);
  for (int i = 0; i < n; ++i) uf_[i] = i;
  for (int k = 0; k < (int)m_.joints.size(); ++k) {
    const Joint& j = m_.joints[k];
    if (j.a < 0 || j.a >= n || j.b < -1 || j.b >= n) fail(k, "body index out of range");
    if (j.type == JointType::Distance) fail(k, "MJCF has no distance joint");
    const bool axial = j.type == JointType::Hinge || j.type == JointType::Slider;
    const bool tree = (axial || j.type == JointType::Ball) && !m_.bodies[j.a].is_static &&
                      tree_joint_[j.a] < 0 &&
                      (j.b < 0 || root(j.b) != j.a); // a is the root of its tree: b in it closes a loop
    if ((j.limited || j.motor) && (!tree || !axial))
      fail(k, "limits and motors only on hinge and slide joints");
    if (j.b >= 0 && m_.bodies[j.b].is_static) as_body_[j.b] = 1;
    if (tree) {
      tree_joint_[j.a] = k, parent_[j.a] = j.b;
      if (j.b >= 0) uf_[j.a] = j.b, children_[j.b].push_back(j.a);
      if (j.motor) motors_.push_back(k);
      continue;
    }
    if (axial) fail(k, "it closes a loop (MJCF's loop closures are connect and weld: ball and fixed joints)");
    if (m_.bodies[j.a].is_static) as_body_[j.a] = 1;
    loops_.push_back(k);
  }
  for (auto& c : children_) std::sort(c.begin(), c.end());
  checkDepth();
}

void Writer::checkDepth() const {
  std::vector<std::pair<int, int>> stack; // (body, depth)
  for (int i = 0; i < (int)m_.bodies.size(); ++i)
    if (parent_[i] < 0) stack.push_back({i, 1});
  while (!stack.empty()) {
    const auto [i, d] = stack.back();
    stack.pop_back();
    if (d > kMaxBodyDepth)
      throw SceneError("cannot write MJCF: body '" + m_.bodies[i].name + "' is nested " + std::to_string(d) +
                       " bodies deep, more than the XML parser reads back (" + std::to_string(kMaxBodyDepth) +
                       ")");
    for (int c : children_[i]) stack.push_back({c, d + 1});
  }
}

void Writer::options() {
  pr_.OpenElement("compiler");
  attr("angle", std::string("radian"));
  pr_.CloseElement();
  if (!(m_.timestep > 0) && !m_.has_gravity && motors_.empty()) return;
  pr_.OpenElement("option");
  if (m_.timestep > 0) attr("timestep", m_.timestep);
  if (m_.has_gravity) attr("gravity", m_.gravity);
  if (!motors_.empty()) attr("integrator", std::string("implicitfast")); // kv implicit: stable for any kv
  pr_.CloseElement();
}

void Writer::geom(int i, bool in_world) {
  const Body& b = m_.bodies[i];
  const Shape& s = b.shape;
  pr_.OpenElement("geom");
  if (in_world) attr("name", body_names_[i]);
  attr("type", std::string(shapeName(s.type)));
  if (s.type == ShapeType::Plane) attr("size", std::string("0 0 1")); // infinite; 1: the grid spacing drawn
  if (s.type == ShapeType::Sphere) attr("size", s.radius);
  if (s.type == ShapeType::Box) attr("size", s.half);
  if (s.type == ShapeType::Capsule || s.type == ShapeType::Cylinder) attr("size", s.radius, s.half_length);
  if (in_world) attr("pos", b.x), attr("quat", b.q);
  if (!b.is_static) attr("mass", b.mass);
  if (m_.friction >= 0)
    attr("friction", num("friction", m_.friction) + " 0.005 0.0001"); // MuJoCo's torsional, rolling
  for (auto [name, v] :
       {std::pair<const char*, unsigned>{"contype", b.contype}, {"conaffinity", b.conaffinity}}) {
    if (v > (unsigned)INT_MAX)
      throw SceneError("cannot write MJCF: body '" + b.name + "': " + name + " > 2^31-1");
    if (v != 1u) attr(name, std::to_string(v));
  }
  pr_.CloseElement();
}

void Writer::joint(int k) {
  const Joint& j = m_.joints[k];
  pr_.OpenElement("joint");
  attr("name", joint_names_[k]);
  attr("type", std::string(j.type == JointType::Hinge    ? "hinge"
                           : j.type == JointType::Slider ? "slide"
                                                         : "ball"));
  attr("pos", j.ra);
  if (j.type != JointType::Ball) attr("axis", Vec3(j.fa.col(2)));
  if (j.limited) {
    if (!(j.lower < j.upper)) fail(k, "its limits need lower < upper");
    const double lo = kJointSign * j.lower, hi = kJointSign * j.upper;
    attr("range", std::min(lo, hi), std::max(lo, hi));
    attr("limited", std::string("true"));
  }
  pr_.CloseElement();
}

// Body i and its subtree; px, pq: the parent body's pose (the MJCF body frame is our body's pose).
void Writer::body(int i, const Vec3& px, const Quat& pq) {
  const Body& b = m_.bodies[i];
  const Quat inv = pq.normalized().conjugate();
  pr_.OpenElement("body");
  attr("name", body_names_[i]);
  attr("pos", Vec3(inv * (b.x - px)));
  attr("quat", Quat(inv * b.q.normalized()));
  if (tree_joint_[i] >= 0) {
    joint(tree_joint_[i]);
  } else if (!b.is_static) {
    pr_.OpenElement("freejoint");
    pr_.CloseElement();
  }
  geom(i, false);
  if (!b.is_static && makeBody(b.name, b.shape, 0.0, b.mass, b.x, b.q, false).inertia != b.inertia) {
    pr_.OpenElement("inertial"); // an inertia other than the shape's
    attr("pos", std::string("0 0 0"));
    attr("mass", b.mass);
    attr("diaginertia", b.inertia);
    pr_.CloseElement();
  }
  for (int c : children_[i]) body(c, b.x, b.q);
  pr_.CloseElement();
}

void Writer::equality() {
  if (loops_.empty()) return;
  pr_.OpenElement("equality");
  for (int k : loops_) {
    const Joint& j = m_.joints[k];
    const bool ball = j.type == JointType::Ball;
    pr_.OpenElement(ball ? "connect" : "weld");
    attr("name", joint_names_[k]);
    attr("body1", body_names_[j.a]);
    attr("body2", j.b < 0 ? std::string("world") : body_names_[j.b]);
    attr("anchor", ball ? j.ra : j.rb); // connect: in body1's frame; weld: in body2's
    pr_.CloseElement();
  }
  pr_.CloseElement();
}

void Writer::actuators() {
  if (motors_.empty()) return;
  pr_.OpenElement("actuator");
  std::string ctrl;
  for (int k : motors_) {
    const Joint& j = m_.joints[k];
    if (!(j.max_force > 0) || !std::isfinite(j.max_force)) fail(k, "a motor needs 0 < max_force < inf");
    pr_.OpenElement("velocity");
    attr("name", "motor_" + joint_names_[k]);
    attr("joint", joint_names_[k]);
    attr("kv", j.max_force / kMotorSpeedBand);
    attr("forcerange", -j.max_force, j.max_force);
    attr("forcelimited", std::string("true"));
    pr_.CloseElement();
    ctrl += (ctrl.empty() ? "" : " ") + num("ctrl", kJointSign * j.target_speed);
  }
  pr_.CloseElement();
  pr_.OpenElement("keyframe");
  pr_.OpenElement("key");
  attr("ctrl", ctrl);
  pr_.CloseElement();
  pr_.CloseElement();
}

std::string Writer::write(const std::string& model_name) {
  names();
  plan();
  pr_.OpenElement("mujoco");
  attr("model", model_name);
  options();
  pr_.OpenElement("worldbody");
  for (int i = 0; i < (int)m_.bodies.size(); ++i) {
    if (m_.bodies[i].is_static && !as_body_[i])
      geom(i, true);
    else if (parent_[i] < 0)
      body(i, Vec3::Zero(), Quat::Identity());
  }
  pr_.CloseElement();
  equality();
  actuators();
  pr_.CloseElement();
  return pr_.CStr();
}

} // namespace

std::string writeMjcf(const Model& m, const std::string& model_name) {
  return Writer(m).write(model_name);
}

} // namespace suite::contact
