// Joint rows (see joint.hpp for the constraint functions Phi and their Jacobians).
#include "contact/joint.hpp"

#include <cmath>

namespace suite::contact {

namespace {
using V6 = Eigen::Matrix<double, 6, 1>;

const char* const kJointNames[] = {"ball", "hinge", "slider", "fixed", "distance"};

// An orthonormal frame with column 2 along axis (unit).
Mat3 frameAlong(const Vec3& axis) {
  const Vec3 z = axis.normalized();
  const Vec3 t = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = (t - t.dot(z) * z).normalized();
  Mat3 f;
  f.col(0) = x;
  f.col(1) = z.cross(x);
  f.col(2) = z;
  return f;
}

// The world pose of side a or b of a joint: rotation (identity for the world) and anchor point.
struct Side {
  Mat3 R = Mat3::Identity();
  Vec3 x = Vec3::Zero(), p = Vec3::Zero();
};

Side sideA(const Joint& j, const std::vector<Body>& bodies) {
  const Body& B = bodies[j.a];
  Side s;
  s.R = B.R();
  s.x = B.x;
  s.p = B.x + s.R * j.ra;
  return s;
}

Side sideB(const Joint& j, const std::vector<Body>& bodies) {
  Side s;
  if (j.b < 0) {
    s.p = s.x = j.rb;
    return s;
  }
  const Body& B = bodies[j.b];
  s.R = B.R();
  s.x = B.x;
  s.p = B.x + s.R * j.rb;
  return s;
}

// Phi = c . (p_a - p_b) for a constant world vector c.
JointRow pointRow(const Side& A, const Side& B, const Vec3& c) {
  JointRow r;
  r.phi = c.dot(A.p - B.p);
  r.ja << c, (A.p - A.x).cross(c);
  r.jb << -c, -(B.p - B.x).cross(c);
  return r;
}

// Phi = u . w for u fixed in a and w fixed in b (world vectors now): dPhi/dt = (w_a - w_b) . (u x w).
JointRow axisRow(const Vec3& u, const Vec3& w) {
  JointRow r;
  r.phi = u.dot(w);
  const Vec3 c = u.cross(w);
  r.ja << Vec3::Zero(), c;
  r.jb << Vec3::Zero(), -c;
  return r;
}

// Phi = u . (p_b - p_a) for u fixed in a.
JointRow sliderRow(const Side& A, const Side& B, const Vec3& u) {
  JointRow r;
  const Vec3 d = B.p - A.p;
  r.phi = u.dot(d);
  r.ja << -u, u.cross(B.p - A.x);
  r.jb << u, (B.p - B.x).cross(u);
  return r;
}

// The relative orientation rows: the frames' columns (e1, e2, e3) of a and (f1, f2, f3) of b stay equal.
void orientationRows(const Mat3& ea, const Mat3& fb, std::vector<JointRow>* rows) {
  rows->push_back(axisRow(ea.col(1), fb.col(2)));
  rows->push_back(axisRow(ea.col(2), fb.col(0)));
  rows->push_back(axisRow(ea.col(0), fb.col(1)));
}
} // namespace

const char* jointName(JointType t) {
  return kJointNames[(int)t];
}

JointType jointFromName(const std::string& name) {
  for (int k = 0; k < 5; ++k)
    if (name == kJointNames[k]) return (JointType)k;
  throw SceneError("unknown joint type '" + name + "' (ball, hinge, slider, fixed, distance)");
}

int jointRowCount(JointType t) {
  static const int n[] = {3, 5, 5, 6, 1};
  return n[(int)t];
}

Joint makeJoint(const std::string& name, JointType type, const std::vector<Body>& bodies, int a, int b,
                const Vec3& anchor, const Vec3& axis, const Vec3& anchor_b) {
  const int nb = (int)bodies.size();
  const std::string who = "joint '" + name + "'";
  if (a < 0 || a >= nb || b < -1 || b >= nb) throw SceneError(who + ": body index out of range");
  if (a == b) throw SceneError(who + ": joins body '" + bodies[a].name + "' to itself");
  if (bodies[a].is_static && (b < 0 || bodies[b].is_static))
    throw SceneError(who + ": joins two static bodies (or a static body to the world)");
  if (!anchor.allFinite() || !axis.allFinite() || !anchor_b.allFinite())
    throw SceneError(who + ": non-finite anchor or axis");
  const bool axial = type == JointType::Hinge || type == JointType::Slider;
  if (axial && !(axis.norm() > 0)) throw SceneError(who + ": needs a non-zero axis");
  Joint j;
  j.name = name;
  j.type = type;
  j.a = a;
  j.b = b;
  const Mat3 world = axial ? frameAlong(axis) : Mat3::Identity();
  const Mat3 Ra = bodies[a].R();
  j.ra = Ra.transpose() * (anchor - bodies[a].x);
  j.fa = Ra.transpose() * world;
  const Vec3 pb = type == JointType::Distance ? anchor_b : anchor;
  if (b < 0) {
    j.rb = pb;
    j.fb = world;
  } else {
    const Mat3 Rb = bodies[b].R();
    j.rb = Rb.transpose() * (pb - bodies[b].x);
    j.fb = Rb.transpose() * world;
  }
  if (type == JointType::Distance) {
    j.length = (anchor_b - anchor).norm();
    if (!(j.length > 0)) throw SceneError(who + ": distance joint needs two distinct anchors");
  }
  return j;
}

void jointRows(const Joint& j, const std::vector<Body>& bodies, std::vector<JointRow>* rows) {
  const Side A = sideA(j, bodies), B = sideB(j, bodies);
  const Mat3 ea = A.R * j.fa, fb = B.R * j.fb;
  switch (j.type) {
  case JointType::Ball:
  case JointType::Fixed:
  case JointType::Hinge:
    for (int k = 0; k < 3; ++k) rows->push_back(pointRow(A, B, Vec3::Unit(k)));
    if (j.type == JointType::Fixed) orientationRows(ea, fb, rows);
    if (j.type == JointType::Hinge) { // a's two normals stay orthogonal to b's axis
      rows->push_back(axisRow(ea.col(0), fb.col(2)));
      rows->push_back(axisRow(ea.col(1), fb.col(2)));
    }
    return;
  case JointType::Slider:
    orientationRows(ea, fb, rows);
    rows->push_back(sliderRow(A, B, ea.col(0)));
    rows->push_back(sliderRow(A, B, ea.col(1)));
    return;
  case JointType::Distance: {
    const Vec3 d = A.p - B.p;
    const double len = d.norm();
    JointRow r = pointRow(A, B, len > 0 ? Vec3(d / len) : Vec3::UnitZ());
    r.phi = len - j.length;
    rows->push_back(r);
    return;
  }
  }
}

JointRow jointCoordinate(const Joint& j, const std::vector<Body>& bodies) {
  const Side A = sideA(j, bodies), B = sideB(j, bodies);
  const Mat3 ea = A.R * j.fa, fb = B.R * j.fb;
  const Vec3 axis = ea.col(2);
  if (j.type == JointType::Slider) return sliderRow(A, B, axis);
  JointRow r; // hinge
  r.phi = std::atan2(axis.dot(ea.col(0).cross(fb.col(0))), ea.col(0).dot(fb.col(0)));
  r.ja << Vec3::Zero(), -axis;
  r.jb << Vec3::Zero(), axis;
  return r;
}

} // namespace suite::contact
