// Rigid bodies: mass properties of sphere, box, capsule and cylinder from density (closed forms; capsule
// = cylinder + two hemispheres with the parallel-axis shift of each hemisphere's centroid 3r/8).
#include "contact/body.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace suite::contact {

const char* shapeName(ShapeType t) {
  switch (t) {
  case ShapeType::Plane:
    return "plane";
  case ShapeType::Sphere:
    return "sphere";
  case ShapeType::Box:
    return "box";
  case ShapeType::Capsule:
    return "capsule";
  case ShapeType::Cylinder:
    return "cylinder";
  }
  return "?";
}

ShapeType shapeFromName(const std::string& name) {
  for (ShapeType t :
       {ShapeType::Plane, ShapeType::Sphere, ShapeType::Box, ShapeType::Capsule, ShapeType::Cylinder})
    if (name == shapeName(t)) return t;
  throw SceneError("unknown body type '" + name + "' (plane, sphere, box, capsule, cylinder)");
}

Mat3 Body::invInertiaWorld() const {
  const Mat3 r = R();
  return r * inv_inertia.asDiagonal() * r.transpose();
}

Mat3 Body::inertiaWorld() const {
  const Mat3 r = R();
  return r * inertia.asDiagonal() * r.transpose();
}

double Body::kineticEnergy() const {
  if (is_static) return 0.0;
  return 0.5 * mass * v.squaredNorm() + 0.5 * w.dot(inertiaWorld() * w);
}

double Body::boundingRadius() const {
  switch (shape.type) {
  case ShapeType::Plane:
    return INFINITY;
  case ShapeType::Sphere:
    return shape.radius;
  case ShapeType::Box:
    return shape.half.norm();
  case ShapeType::Capsule:
    return shape.radius + shape.half_length;
  case ShapeType::Cylinder:
    return std::hypot(shape.radius, shape.half_length);
  }
  return INFINITY;
}

namespace {
void requirePositive(const std::string& body, const char* what, double v) {
  if (!(v > 0) || !std::isfinite(v)) {
    std::ostringstream s;
    s << "body '" << body << "': " << what << " " << v << ": must be > 0 and finite";
    throw SceneError(s.str());
  }
}
} // namespace

Body makeBody(const std::string& name, const Shape& shape, double density, double mass, const Vec3& x,
              const Quat& q, bool is_static) {
  Body b;
  b.name = name;
  b.shape = shape;
  b.x = x;
  b.q = q.normalized();
  if (!x.allFinite() || !q.coeffs().allFinite())
    throw SceneError("body '" + name + "': non-finite position or orientation");
  const double pi = M_PI;
  double vol = 0.0;
  Vec3 unit_i = Vec3::Zero(); // inertia per unit mass
  switch (shape.type) {
  case ShapeType::Plane:
    is_static = true;
    break;
  case ShapeType::Sphere: {
    requirePositive(name, "radius", shape.radius);
    const double r = shape.radius;
    vol = 4.0 / 3.0 * pi * r * r * r;
    unit_i.setConstant(0.4 * r * r);
    break;
  }
  case ShapeType::Box: {
    for (int k = 0; k < 3; ++k) requirePositive(name, "half extent", shape.half[k]);
    const Vec3 h = shape.half;
    vol = 8.0 * h.prod();
    unit_i =
        Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(), h.x() * h.x() + h.y() * h.y()) /
        3.0;
    break;
  }
  case ShapeType::Cylinder: {
    requirePositive(name, "radius", shape.radius);
    requirePositive(name, "half_length", shape.half_length);
    const double r = shape.radius, L = 2 * shape.half_length;
    vol = pi * r * r * L;
    unit_i = Vec3((3 * r * r + L * L) / 12.0, (3 * r * r + L * L) / 12.0, 0.5 * r * r);
    break;
  }
  case ShapeType::Capsule: {
    requirePositive(name, "radius", shape.radius);
    requirePositive(name, "half_length", shape.half_length);
    const double r = shape.radius, L = 2 * shape.half_length;
    const double vc = pi * r * r * L, vs = 4.0 / 3.0 * pi * r * r * r;
    vol = vc + vs;
    const double ix =
        vc * (L * L / 12.0 + r * r / 4.0) + vs * (0.4 * r * r + L * L / 4.0 + 3.0 * L * r / 8.0);
    const double iz = vc * r * r / 2.0 + vs * 0.4 * r * r;
    unit_i = Vec3(ix, ix, iz) / vol;
    break;
  }
  }
  b.is_static = is_static;
  if (is_static) return b; // infinite mass: inv_mass = 0, inv_inertia = 0
  if (mass != 0.0) {
    requirePositive(name, "mass", mass);
    b.mass = mass;
  } else {
    requirePositive(name, "density", density);
    b.mass = density * vol;
  }
  b.inv_mass = 1.0 / b.mass;
  b.inertia = b.mass * unit_i;
  b.inv_inertia = b.inertia.cwiseInverse();
  return b;
}

void packState(const Body& b, double* r) {
  const double v[kStateSize] = {b.x.x(), b.x.y(), b.x.z(), b.q.x(), b.q.y(), b.q.z(), b.q.w(),
                                b.v.x(), b.v.y(), b.v.z(), b.w.x(), b.w.y(), b.w.z()};
  std::copy(v, v + kStateSize, r);
}

void unpackState(const double* r, Body* b) {
  b->x = Vec3(r[0], r[1], r[2]);
  b->q = Quat(r[6], r[3], r[4], r[5]); // Eigen: (w, x, y, z)
  b->v = Vec3(r[7], r[8], r[9]);
  b->w = Vec3(r[10], r[11], r[12]);
}

void advancePose(Body* b, const Vec3& v, const Vec3& w, double dt) {
  b->x += dt * v;
  const double ang = w.norm() * dt;
  if (ang > 0) b->q = (Quat(Eigen::AngleAxisd(ang, w.normalized())) * b->q).normalized();
}

} // namespace suite::contact
