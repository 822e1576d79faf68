// MJCF reader of mjcf.hpp (tinyxml2's DOM, the sections in dependency order; the writer: mjcf_write.cpp). MuJoCo's conventions followed here (MuJoCo 3.x, src/user/user_objects.cc):
// euler angles accumulate in the eulerseq order, lower case = moving axes (post-multiply), upper case = fixed
// axes (pre-multiply); fromto sets the geom centre to the midpoint and its z axis by the minimal rotation from
// (0,0,1) to from - to (mjuu_z2quat); quaternions are "w x y z", normalised; inertia from a geom's mass and
// shape: box m (b^2+c^2)/3, sphere 2 m r^2/5, cylinder m (3 r^2 + h^2)/12 and m r^2/2, capsule with the mass
// split between the cylinder and the two hemispheres by volume and each hemisphere's centroid 3r/8 from its
// flat face: makeBody (body.cpp) uses the same closed forms, written per volume instead of per mass (equal up to
// rounding).
#include "contact/mjcf.hpp"
#include "contact/mjcf_conventions.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace suite::contact {

namespace {
using namespace mjcf;
using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;

constexpr double kMjEps = 1e-14;         // MuJoCo's mjEPS: fromto points closer than this are an error
constexpr double kDefaultFriction = 1.0; // MuJoCo's geom friction (sliding)

std::string clip(const std::string& s) {
  return s.size() <= 40 ? s : s.substr(0, 40) + "...";
}

std::string shortNum(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// v / |v| computed without overflow; false for a zero (or non-finite) vector.
template <class V> bool unitOf(V v, V* out) {
  const double mx = v.cwiseAbs().maxCoeff();
  if (!(mx > 0) || !std::isfinite(mx)) return false;
  v /= mx;
  *out = v.normalized();
  return true;
}

// MuJoCo's mjuu_z2quat: the minimal rotation from (0,0,1) to the unit vector v.
Quat z2quat(const Vec3& v) {
  Vec3 a = Vec3::UnitZ().cross(v);
  const double s = a.norm();
  a = s < 1e-10 ? Vec3::UnitX() : Vec3(a / s);
  return Quat(Eigen::AngleAxisd(std::atan2(s, v.z()), a));
}

class Reader {
public:
  explicit Reader(std::string path) : path_(std::move(path)) {}
  Model parse(const std::string& text);

private:
  struct Frame { // an MJCF body frame in the world
    Vec3 p = Vec3::Zero();
    Quat q = Quat::Identity();
  };
  struct GeomSpec { // one <geom>, its pose in the body frame
    const XMLElement* el = nullptr;
    Shape shape;
    Vec3 pos = Vec3::Zero();
    Quat q = Quat::Identity();
    bool has_mass = false;
    double mass = 0.0, density = 1000.0;
    unsigned contype = 1, conaffinity = 1;
  };
  struct Inertia {
    double mass = 0.0;
    Vec3 diag = Vec3::Zero(); // in the geom frame
  };
  struct FrictionUse {
    double mu;
    bool given;
    int line;
  };
  struct Actuator {
    int joint;
    bool clamp;
    double lo, hi;
  };

  [[noreturn]] void fail(const XMLElement* e, const std::string& msg) const {
    throw SceneError(path_ + ":" + std::to_string(e->GetLineNum()) + ": " + msg);
  }
  static std::string tag(const XMLElement* e) { return std::string("<") + e->Name() + ">"; }
  void allow(const XMLElement* e, std::initializer_list<const char*> names) const;
  void noChildren(const XMLElement* e) const;
  const char* need(const XMLElement* e, const char* attr) const;
  std::vector<double> numbers(const XMLElement* e, const char* attr, size_t lo, size_t hi) const;
  double scalar(const XMLElement* e, const char* attr) const { return numbers(e, attr, 1, 1)[0]; }
  Vec3 vec3(const XMLElement* e, const char* attr, const Vec3& def) const;
  unsigned bits(const XMLElement* e, const char* attr) const;
  std::string keyword(const XMLElement* e, const char* attr, std::initializer_list<const char*> choices,
                      const char* def) const;
  Quat orientation(const XMLElement* e) const;

  void compiler(const XMLElement* e);
  void option(const XMLElement* e);
  void worldbody(const XMLElement* e);
  void body(const XMLElement* e, int parent, bool parent_static, const Frame& pf);
  std::string bodyName(const XMLElement* e, const char* name, bool referable, int index);
  int addBody(const XMLElement* e, const std::string& name, const GeomSpec& g, const XMLElement* inert,
              const Frame& f, bool is_static);
  GeomSpec geom(const XMLElement* e);
  void geomSize(const XMLElement* e, bool fromto, Shape* s) const;
  void fromto(const XMLElement* e, GeomSpec* g) const;
  Inertia inertial(const XMLElement* e, const GeomSpec& g) const;
  void joint(const XMLElement* e, int a, int parent, const Frame& f);
  void limits(const XMLElement* e, JointType t, Joint* j) const;
  void addJoint(const XMLElement* e, const std::string& name, JointType t, int a, int b, const Vec3& anchor,
                const Vec3& axis);
  void equality(const XMLElement* e);
  int bodyRef(const XMLElement* e, const char* attr, const char* def) const;
  void actuator(const XMLElement* e);
  void velocity(const XMLElement* e);
  void keyframe(const XMLElement* e);
  void finishFriction();

  std::string path_;
  bool degree_ = true;
  std::string eulerseq_ = "xyz";
  bool key_seen_ = false;
  Model m_;
  std::vector<Frame> frames_;                                     // each body's MJCF body frame
  std::unordered_map<std::string, int> body_index_, joint_index_; // <body> names; hinge, slide, ball joints
  std::unordered_set<std::string> body_names_;                    // every body's (world geoms' too)
  std::vector<FrictionUse> friction_;
  std::vector<Actuator> actuators_;
};

void Reader::allow(const XMLElement* e, std::initializer_list<const char*> names) const {
  for (const XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
    bool ok = false;
    for (const char* n : names) ok = ok || std::strcmp(n, a->Name()) == 0;
    if (ok) continue;
    std::string list;
    for (const char* n : names) list += (list.empty() ? "" : ", ") + std::string(n);
    fail(e, tag(e) + ": attribute '" + clip(a->Name()) + "' is not supported" +
                (list.empty() ? std::string(" (it takes none)") : " (supported: " + list + ")"));
  }
}

void Reader::noChildren(const XMLElement* e) const {
  if (const XMLElement* c = e->FirstChildElement())
    fail(c, "unknown element " + tag(c) + " in " + tag(e) + " (it takes no child elements here)");
}

const char* Reader::need(const XMLElement* e, const char* attr) const {
  const char* v = e->Attribute(attr);
  if (!v) fail(e, tag(e) + ": attribute '" + attr + "' is required");
  return v;
}

std::vector<double> Reader::numbers(const XMLElement* e, const char* attr, size_t lo, size_t hi) const {
  const char* p = e->Attribute(attr);
  std::vector<double> v;
  const std::string count = lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi);
  while (p && *p) {
    while (*p && std::isspace((unsigned char)*p)) ++p;
    if (!*p) break;
    const char* q = p;
    while (*q && !std::isspace((unsigned char)*q)) ++q;
    const std::string tok(p, q);
    if (v.size() == hi) fail(e, tag(e) + ": attribute '" + attr + "' needs " + count + " numbers, got more");
    char* end = nullptr;
    const double d = std::strtod(tok.c_str(), &end);
    if (end != tok.c_str() + tok.size() || !std::isfinite(d))
      fail(e, tag(e) + ": bad number '" + clip(tok) + "' in attribute '" + attr + "'");
    v.push_back(d);
    p = q;
  }
  if (v.size() < lo)
    fail(e,
         tag(e) + ": attribute '" + attr + "' needs " + count + " numbers, got " + std::to_string(v.size()));
  return v;
}

Vec3 Reader::vec3(const XMLElement* e, const char* attr, const Vec3& def) const {
  if (!e->Attribute(attr)) return def;
  const std::vector<double> v = numbers(e, attr, 3, 3);
  return Vec3(v[0], v[1], v[2]);
}

unsigned Reader::bits(const XMLElement* e, const char* attr) const {
  const char* v = e->Attribute(attr);
  if (!v) return 1u; // MuJoCo's default contype and conaffinity
  std::string s(v);
  s.erase(0, s.find_first_not_of(" \t\r\n"));
  s.erase(s.find_last_not_of(" \t\r\n") + 1);
  const bool digits = !s.empty() && s.size() <= 10 &&
                      std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || std::stoull(s) > (unsigned long long)INT_MAX)
    fail(e, tag(e) + ": bad integer '" + clip(v) + "' in attribute '" + attr + "' (0 to 2^31-1)");
  return (unsigned)std::stoull(s);
}

std::string Reader::keyword(const XMLElement* e, const char* attr, std::initializer_list<const char*> choices,
                            const char* def) const {
  const char* v = e->Attribute(attr);
  if (!v) return def;
  std::string list;
  for (const char* c : choices) {
    if (std::strcmp(v, c) == 0) return v;
    list += (list.empty() ? "" : ", ") + std::string(c);
  }
  fail(e, tag(e) + ": " + attr + "=\"" + clip(v) + "\" is not supported (" + list + ")");
}

Quat Reader::orientation(const XMLElement* e) const {
  const int n = !!e->Attribute("quat") + !!e->Attribute("euler") + !!e->Attribute("axisangle");
  if (n > 1) fail(e, tag(e) + ": more than one of quat, euler, axisangle");
  const double unit = degree_ ? M_PI / 180.0 : 1.0;
  if (e->Attribute("quat")) {
    const std::vector<double> v = numbers(e, "quat", 4, 4);
    Eigen::Vector4d u;
    if (!unitOf(Eigen::Vector4d(v[0], v[1], v[2], v[3]), &u)) fail(e, tag(e) + ": quat must be non-zero");
    return Quat(u[0], u[1], u[2], u[3]); // w x y z
  }
  if (e->Attribute("axisangle")) {
    const std::vector<double> v = numbers(e, "axisangle", 4, 4);
    Vec3 axis;
    if (!unitOf(Vec3(v[0], v[1], v[2]), &axis)) fail(e, tag(e) + ": axisangle needs a non-zero axis");
    return Quat(Eigen::AngleAxisd(v[3] * unit, axis));
  }
  Quat q = Quat::Identity();
  if (!e->Attribute("euler")) return q;
  const std::vector<double> v = numbers(e, "euler", 3, 3);
  for (int i = 0; i < 3; ++i) {
    const char c = eulerseq_[i];
    const int k = std::tolower((unsigned char)c) - 'x';
    const Quat r(Eigen::AngleAxisd(v[i] * unit, Vec3::Unit(k)));
    q = std::islower((unsigned char)c) ? Quat(q * r) : Quat(r * q); // moving axes: post-multiply
  }
  return q.normalized();
}

void Reader::compiler(const XMLElement* e) {
  allow(e, {"angle", "eulerseq"});
  noChildren(e);
  degree_ = keyword(e, "angle", {"degree", "radian"}, degree_ ? "degree" : "radian") == "degree";
  if (const char* s = e->Attribute("eulerseq")) {
    const std::string seq(s);
    const bool ok = seq.size() == 3 && std::all_of(seq.begin(), seq.end(), [](char c) {
                      return std::strchr("xyzXYZ", c) != nullptr && c != '\0';
                    });
    if (!ok) fail(e, "<compiler>: eulerseq=\"" + clip(seq) + "\" must be 3 of x, y, z, X, Y, Z");
    eulerseq_ = seq;
  }
}

void Reader::option(const XMLElement* e) {
  allow(e, {"timestep", "gravity", "integrator"});
  noChildren(e);
  if (e->Attribute("timestep")) {
    m_.timestep = scalar(e, "timestep");
    if (!(m_.timestep > 0)) fail(e, "<option>: timestep must be > 0");
  }
  if (e->Attribute("gravity")) {
    m_.gravity = vec3(e, "gravity", Vec3::Zero());
    m_.has_gravity = true;
  }
  keyword(e, "integrator", {"Euler", "RK4", "implicit", "implicitfast"}, "Euler"); // checked, not used
}

void Reader::worldbody(const XMLElement* e) {
  allow(e, {});
  for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string n = c->Name();
    if (n == "body") {
      body(c, -1, true, Frame());
    } else if (n == "geom") {
      const GeomSpec g = geom(c);
      addBody(c, bodyName(c, c->Attribute("name"), false, (int)m_.bodies.size()), g, nullptr, Frame(), true);
    } else {
      fail(c, "unknown element <" + clip(n) + "> in <worldbody> (supported: body, geom)");
    }
  }
}

// A body name: the attribute, else body<index>; unique among all bodies ("world" is the world's).
std::string Reader::bodyName(const XMLElement* e, const char* name, bool referable, int index) {
  std::string s = name ? name : "";
  if (s.empty()) {
    s = "body" + std::to_string(index);
    while (body_names_.count(s)) s += "_";
  } else if (s == "world") {
    fail(e, tag(e) + ": the name 'world' is the world body's");
  } else if (body_names_.count(s)) {
    fail(e, tag(e) + ": body name '" + clip(s) + "' is used twice");
  }
  body_names_.insert(s);
  if (referable) body_index_[s] = index;
  return s;
}

void Reader::body(const XMLElement* e, int parent, bool parent_static, const Frame& pf) {
  allow(e, {"name", "pos", "quat", "euler", "axisangle"});
  Frame f;
  f.p = pf.p + pf.q * vec3(e, "pos", Vec3::Zero());
  f.q = (pf.q * orientation(e)).normalized();
  std::vector<const XMLElement*> geoms, joints, children;
  const XMLElement* inert = nullptr;
  for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string n = c->Name();
    if (n == "geom")
      geoms.push_back(c);
    else if (n == "joint" || n == "freejoint")
      joints.push_back(c);
    else if (n == "body")
      children.push_back(c);
    else if (n == "inertial" && !inert)
      inert = c;
    else if (n == "inertial")
      fail(c, "<body>: more than one <inertial>");
    else
      fail(c,
           "unknown element <" + clip(n) + "> in <body> (supported: geom, inertial, joint, freejoint, body)");
  }
  const std::string name = bodyName(e, e->Attribute("name"), true, (int)m_.bodies.size());
  if (geoms.empty() && !inert) fail(e, "body '" + clip(name) + "' has no mass");
  if (geoms.size() != 1)
    fail(e, "body '" + clip(name) + "' has " + std::to_string(geoms.size()) +
                " geoms: one per body is supported");
  if (joints.size() > 1)
    fail(joints[1], "body '" + clip(name) + "' has " + std::to_string(joints.size()) +
                        " joints: at most one per body is supported");
  const XMLElement* j = joints.empty() ? nullptr : joints[0];
  const bool freejoint = j && std::strcmp(j->Name(), "freejoint") == 0;
  const bool free =
      freejoint || (j && keyword(j, "type", {"hinge", "slide", "ball", "free"}, "hinge") == "free");
  if (freejoint) allow(j, {"name"});
  if (free && !freejoint) allow(j, {"name", "type"});
  if (free) noChildren(j);
  if (free && parent != -1)
    fail(j, "body '" + clip(name) + "': a free joint only in a child of <worldbody> (as in MuJoCo)");
  const bool is_static = !j && (parent < 0 || parent_static);
  const int idx = addBody(e, name, geom(geoms[0]), inert, f, is_static);
  if (j && !free) joint(j, idx, parent, f);
  if (!j && !is_static) addJoint(e, "weld_" + name, JointType::Fixed, idx, parent, f.p, Vec3::UnitZ());
  for (const XMLElement* c : children) body(c, idx, is_static, f);
}

int Reader::addBody(const XMLElement* e, const std::string& name, const GeomSpec& g, const XMLElement* inert,
                    const Frame& f, bool is_static) {
  if (m_.bodies.size() >= (size_t)kMaxSceneBodies)
    fail(e, "more than " + std::to_string(kMaxSceneBodies) + " bodies");
  if (g.shape.type == ShapeType::Plane && !is_static)
    fail(g.el,
         "body '" + clip(name) + "': a plane must be static (in <worldbody>, or a body without joint there)");
  Inertia in;
  if (inert) in = inertial(inert, g);
  double mass = g.has_mass ? g.mass : 0.0;
  if (inert)
    mass = in.mass;
  else if (!is_static && (g.has_mass ? g.mass == 0 : g.density == 0))
    fail(e, "body '" + clip(name) + "' has no mass");
  Body b;
  try {
    b = makeBody(name, g.shape, g.density, mass, f.p + f.q * g.pos, f.q * g.q, is_static);
  } catch (const SceneError& err) {
    fail(g.el, err.what());
  }
  if (inert && !is_static) {
    b.inertia = in.diag;
    b.inv_inertia = in.diag.cwiseInverse();
  }
  const bool finite = std::isfinite(b.mass) && std::isfinite(b.inv_mass) && b.inertia.allFinite() &&
                      b.inv_inertia.allFinite();
  if (!is_static && !finite) fail(e, "body '" + clip(name) + "': mass or inertia too small or too large");
  b.contype = g.contype;
  b.conaffinity = g.conaffinity;
  m_.bodies.push_back(b);
  frames_.push_back(f);
  return (int)m_.bodies.size() - 1;
}

Reader::GeomSpec Reader::geom(const XMLElement* e) {
  allow(e, {"name", "type", "size", "fromto", "pos", "quat", "euler", "axisangle", "mass", "density",
            "friction", "contype", "conaffinity", "rgba"});
  noChildren(e);
  GeomSpec g;
  g.el = e;
  g.shape.type =
      shapeFromName(keyword(e, "type", {"plane", "sphere", "box", "capsule", "cylinder"}, "sphere"));
  const bool ft = e->Attribute("fromto") != nullptr;
  geomSize(e, ft, &g.shape);
  if (ft) {
    fromto(e, &g);
  } else {
    g.pos = vec3(e, "pos", Vec3::Zero());
    g.q = orientation(e);
  }
  g.has_mass = e->Attribute("mass") != nullptr;
  if (g.has_mass) g.mass = scalar(e, "mass");
  if (e->Attribute("density")) g.density = scalar(e, "density");
  if (!(g.mass >= 0) || !(g.density >= 0)) fail(e, "<geom>: mass and density must be >= 0");
  FrictionUse fr{kDefaultFriction, false, e->GetLineNum()};
  if (e->Attribute("friction")) {
    fr = {numbers(e, "friction", 1, 3)[0], true, e->GetLineNum()};
    if (!(fr.mu >= 0)) fail(e, "<geom>: friction must be >= 0");
  }
  friction_.push_back(fr);
  g.contype = bits(e, "contype");
  g.conaffinity = bits(e, "conaffinity");
  if (e->Attribute("rgba")) numbers(e, "rgba", 4, 4); // visual: checked, not used
  return g;
}

void Reader::geomSize(const XMLElement* e, bool fromto, Shape* s) const {
  const ShapeType t = s->type;
  const size_t need = t == ShapeType::Plane                                 ? 0
                      : t == ShapeType::Sphere || fromto                    ? 1
                      : t == ShapeType::Capsule || t == ShapeType::Cylinder ? 2
                                                                            : 3;
  if (!e->Attribute("size")) {
    if (need == 0) return;
    fail(e,
         std::string("<geom>: type ") + shapeName(t) + " needs size= (" + std::to_string(need) + " numbers)");
  }
  const std::vector<double> v = numbers(e, "size", std::max<size_t>(need, 1), 3);
  if (t == ShapeType::Sphere || t == ShapeType::Capsule || t == ShapeType::Cylinder) s->radius = v[0];
  if ((t == ShapeType::Capsule || t == ShapeType::Cylinder) && !fromto) s->half_length = v[1];
  if (t == ShapeType::Box) s->half = fromto ? Vec3(v[0], v[0], 0.0) : Vec3(v[0], v[1], v[2]);
}

void Reader::fromto(const XMLElement* e, GeomSpec* g) const {
  const ShapeType t = g->shape.type;
  if (t != ShapeType::Capsule && t != ShapeType::Cylinder && t != ShapeType::Box)
    fail(e, "<geom>: fromto needs type capsule, cylinder or box");
  if (e->Attribute("pos") || e->Attribute("quat") || e->Attribute("euler") || e->Attribute("axisangle"))
    fail(e, "<geom>: fromto with pos or an orientation (fromto sets both)");
  const std::vector<double> v = numbers(e, "fromto", 6, 6);
  const Vec3 from(v[0], v[1], v[2]), to(v[3], v[4], v[5]);
  const Vec3 d = from - to; // MuJoCo: the geom's z axis along from - to
  const double len = d.norm();
  if (!(len >= kMjEps) || !std::isfinite(len)) fail(e, "<geom>: fromto points too close (or too far apart)");
  if (t == ShapeType::Box)
    g->shape.half.z() = 0.5 * len;
  else
    g->shape.half_length = 0.5 * len;
  g->pos = 0.5 * (from + to);
  g->q = z2quat(d / len);
}

Reader::Inertia Reader::inertial(const XMLElement* e, const GeomSpec& g) const {
  allow(e, {"pos", "mass", "diaginertia"});
  noChildren(e);
  need(e, "pos"), need(e, "mass"), need(e, "diaginertia");
  const Vec3 pos = vec3(e, "pos", Vec3::Zero());
  if (!((pos - g.pos).norm() <= 1e-9 * (1.0 + g.pos.norm())))
    fail(e, "<inertial>: pos must be the geom's centre (a body's centre of mass is its shape's centre here)");
  Inertia in;
  in.mass = scalar(e, "mass");
  if (!(in.mass > 0)) fail(e, "<inertial>: mass must be > 0");
  const Vec3 d = vec3(e, "diaginertia", Vec3::Zero());
  if (!(d.minCoeff() > 0)) fail(e, "<inertial>: diaginertia must be > 0");
  const Mat3 R = g.q.toRotationMatrix();
  const Mat3 I = R.transpose() * d.asDiagonal() * R; // in the geom frame
  const Mat3 off = I - Mat3(I.diagonal().asDiagonal());
  if (!(off.cwiseAbs().maxCoeff() <= 1e-9 * d.maxCoeff()))
    fail(e, "<inertial>: diaginertia is not diagonal in the geom's frame (rotated geom)");
  in.diag = I.diagonal();
  return in;
}

void Reader::joint(const XMLElement* e, int a, int parent, const Frame& f) {
  allow(e, {"name", "type", "pos", "axis", "range", "limited"});
  noChildren(e);
  const std::string type = keyword(e, "type", {"hinge", "slide", "ball", "free"}, "hinge");
  const JointType t = type == "hinge"   ? JointType::Hinge
                      : type == "slide" ? JointType::Slider
                                        : JointType::Ball;
  const Vec3 pos = vec3(e, "pos", Vec3::Zero());
  Vec3 axis = Vec3::UnitZ();
  if (!unitOf(vec3(e, "axis", Vec3::UnitZ()), &axis) && t != JointType::Ball)
    fail(e, "<joint>: axis must be non-zero");
  const char* n = e->Attribute("name");
  const std::string name = n && *n ? n : "joint" + std::to_string(m_.joints.size());
  if (n && *n && !joint_index_.emplace(name, (int)m_.joints.size()).second)
    fail(e, "<joint>: joint name '" + clip(name) + "' is used twice");
  addJoint(e, name, t, a, parent, f.p + f.q * pos, f.q * axis);
  limits(e, t, &m_.joints.back());
}

void Reader::limits(const XMLElement* e, JointType t, Joint* j) const {
  const std::string lim = keyword(e, "limited", {"true", "false", "auto"}, "auto");
  const bool has_range = e->Attribute("range") != nullptr;
  std::vector<double> r = has_range ? numbers(e, "range", 2, 2) : std::vector<double>{0.0, 0.0};
  // MuJoCo's autolimits (its default): a range without limited= limits the joint when range[0] < range[1]
  if (lim == "false" || (lim == "auto" && !(r[0] < r[1]))) return;
  if (!has_range) fail(e, "<joint>: limited=\"true\" needs range=");
  if (!(r[0] < r[1])) fail(e, "<joint>: range[0] must be < range[1]");
  if (t == JointType::Ball) fail(e, "<joint>: limits of a ball joint are not supported");
  const double unit = t == JointType::Hinge && degree_ ? M_PI / 180.0 : 1.0;
  const double lo = kJointSign * r[0] * unit, hi = kJointSign * r[1] * unit;
  j->limited = true;
  j->lower = std::min(lo, hi);
  j->upper = std::max(lo, hi);
}

void Reader::addJoint(const XMLElement* e, const std::string& name, JointType t, int a, int b,
                      const Vec3& anchor, const Vec3& axis) {
  try {
    m_.joints.push_back(makeJoint(name, t, m_.bodies, a, b, anchor, axis));
  } catch (const SceneError& err) {
    fail(e, err.what());
  }
}

int Reader::bodyRef(const XMLElement* e, const char* attr, const char* def) const {
  const char* v = def ? (e->Attribute(attr) ? e->Attribute(attr) : def) : need(e, attr);
  if (std::strcmp(v, "world") == 0) return -1;
  const auto it = body_index_.find(v);
  if (it == body_index_.end()) fail(e, tag(e) + ": " + attr + "=\"" + clip(v) + "\": no body of that name");
  return it->second;
}

void Reader::equality(const XMLElement* sec) {
  allow(sec, {});
  for (const XMLElement* c = sec->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string n = c->Name();
    if (n != "connect" && n != "weld")
      fail(c, "unknown element <" + clip(n) + "> in <equality> (supported: connect, weld)");
    allow(c, {"name", "body1", "body2", "anchor"});
    noChildren(c);
    int a = bodyRef(c, "body1", nullptr), b = bodyRef(c, "body2", "world");
    const bool connect = n == "connect";
    if (connect) need(c, "anchor");
    const Vec3 local = vec3(c, "anchor", Vec3::Zero());
    const int in = connect ? a : b; // connect: anchor in body1's frame; weld: in body2's
    const Vec3 anchor = in < 0 ? local : Vec3(frames_[in].p + frames_[in].q * local);
    if (a < 0) std::swap(a, b); // our joints' a is a body
    if (a < 0) fail(c, tag(c) + ": body1 and body2 are both the world");
    const char* name = c->Attribute("name");
    addJoint(c, name && *name ? name : "joint" + std::to_string(m_.joints.size()),
             connect ? JointType::Ball : JointType::Fixed, a, b, anchor, Vec3::UnitZ());
  }
}

void Reader::actuator(const XMLElement* sec) {
  allow(sec, {});
  for (const XMLElement* c = sec->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::strcmp(c->Name(), "velocity") != 0)
      fail(c, "unknown element <" + clip(c->Name()) + "> in <actuator> (supported: velocity)");
    velocity(c);
  }
}

void Reader::velocity(const XMLElement* e) {
  allow(e, {"name", "joint", "kv", "forcerange", "forcelimited", "ctrlrange", "ctrllimited"});
  noChildren(e);
  const std::string jn = need(e, "joint");
  const auto it = joint_index_.find(jn);
  if (it == joint_index_.end())
    fail(e, "<velocity>: joint=\"" + clip(jn) + "\": no hinge, slide or ball joint of that name");
  Joint& j = m_.joints[it->second];
  if (j.type != JointType::Hinge && j.type != JointType::Slider)
    fail(e, "<velocity>: joint '" + clip(jn) + "' is a ball joint (velocity actuators: hinge or slide)");
  if (j.motor) fail(e, "<velocity>: joint '" + clip(jn) + "' has a second actuator");
  if (e->Attribute("kv") && !(scalar(e, "kv") > 0)) fail(e, "<velocity>: kv must be > 0");
  if (keyword(e, "forcelimited", {"true", "false", "auto"}, "auto") == "false")
    fail(e, "<velocity>: forcelimited=\"false\": a motor needs a force bound (forcerange, "
            "forcelimited=\"true\")");
  need(e, "forcerange");
  const std::vector<double> f = numbers(e, "forcerange", 2, 2);
  if (!(f[1] > 0 && f[0] == -f[1])) fail(e, "<velocity>: forcerange must be symmetric, \"-F F\" with F > 0");
  const std::string cl = keyword(e, "ctrllimited", {"true", "false", "auto"}, "auto");
  Actuator act{it->second, false, 0.0, 0.0};
  if (e->Attribute("ctrlrange")) {
    const std::vector<double> r = numbers(e, "ctrlrange", 2, 2);
    act = {it->second, cl == "true" || (cl == "auto" && r[0] < r[1]), r[0], r[1]};
    if (act.clamp && !(r[0] < r[1])) fail(e, "<velocity>: ctrlrange[0] must be < ctrlrange[1]");
  } else if (cl == "true") {
    fail(e, "<velocity>: ctrllimited=\"true\" needs ctrlrange=");
  }
  j.motor = true;
  j.max_force = f[1];
  j.target_speed = 0.0;
  actuators_.push_back(act);
}

void Reader::keyframe(const XMLElement* sec) {
  allow(sec, {});
  for (const XMLElement* c = sec->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::strcmp(c->Name(), "key") != 0)
      fail(c, "unknown element <" + clip(c->Name()) + "> in <keyframe> (supported: key)");
    allow(c, {"name", "ctrl"});
    noChildren(c);
    const size_t n = actuators_.size();
    const std::vector<double> u =
        c->Attribute("ctrl") ? numbers(c, "ctrl", n, n) : std::vector<double>(n, 0.0);
    if (key_seen_) continue; // the first key sets the motors' target speeds
    key_seen_ = true;
    for (size_t k = 0; k < n; ++k) {
      const Actuator& a = actuators_[k];
      m_.joints[a.joint].target_speed = kJointSign * (a.clamp ? std::clamp(u[k], a.lo, a.hi) : u[k]);
    }
  }
}

void Reader::finishFriction() {
  const auto first =
      std::find_if(friction_.begin(), friction_.end(), [](const FrictionUse& f) { return f.given; });
  if (first == friction_.end()) return; // no friction= anywhere: unset
  for (const FrictionUse& f : friction_)
    if (f.mu != first->mu)
      throw SceneError(path_ + ":" + std::to_string(f.line) + ": geom friction " + shortNum(f.mu) +
                       (f.given ? "" : " (MuJoCo's default)") + " differs from " + shortNum(first->mu) +
                       " (line " + std::to_string(first->line) + "): the model has one friction coefficient");
  m_.friction = first->mu;
}

Model Reader::parse(const std::string& text) {
  if (text.size() > (size_t)kMaxSceneBytes)
    throw SceneError("mjcf file " + path_ + ": larger than " + std::to_string(kMaxSceneBytes) + " bytes");
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw SceneError(path_ + ":" + std::to_string(std::max(1, doc.ErrorLineNum())) +
                     ": malformed XML: " + doc.ErrorStr());
  const XMLElement* root = doc.RootElement();
  if (!root) throw SceneError(path_ + ":1: malformed XML: no root element");
  if (std::strcmp(root->Name(), "mujoco") != 0)
    fail(root, "the root element is " + tag(root) + ", not <mujoco>");
  if (const XMLElement* next = root->NextSiblingElement()) fail(next, "a second root element " + tag(next));
  allow(root, {"model"});
  // compiler first (it sets the angle unit of everything), then the bodies, then what refers to them
  const std::vector<std::string> order = {"compiler", "option",   "worldbody",
                                          "equality", "actuator", "keyframe"};
  for (const std::string& section : order)
    for (const XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string n = c->Name();
      if (n == section && n == "compiler")
        compiler(c);
      else if (n == section && n == "option")
        option(c);
      else if (n == section && n == "worldbody")
        worldbody(c);
      else if (n == section && n == "equality")
        equality(c);
      else if (n == section && n == "actuator")
        actuator(c);
      else if (n == section && n == "keyframe")
        keyframe(c);
      else if (n == "default")
        fail(c, "<default> is not supported: write the attributes on each element");
      else if (std::find(order.begin(), order.end(), n) == order.end())
        fail(c, "unknown element <" + clip(n) +
                    "> in <mujoco> (supported: compiler, option, worldbody, equality, "
                    "actuator, keyframe)");
    }
  if (m_.bodies.empty()) fail(root, "no bodies");
  finishFriction();
  return std::move(m_);
}

} // namespace

Model parseMjcf(const std::string& text, const std::string& path) {
  return Reader(path).parse(text);
}

Model readMjcfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("mjcf file " + path + ": cannot open");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0 || size > kMaxSceneBytes)
    throw SceneError("mjcf file " + path + ": larger than " + std::to_string(kMaxSceneBytes) + " bytes");
  in.seekg(0);
  std::string text((size_t)size, '\0');
  in.read(&text[0], size);
  return parseMjcf(text, path);
}

} // namespace suite::contact
