// Rigid bodies of the contact library: shapes (plane, sphere, box, capsule, cylinder), mass and inertia
// from geometry and density, quaternion orientation, world-frame velocities.
// Reference: standard rigid-body mass properties (e.g. Featherstone, Rigid Body Dynamics Algorithms, 2008).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <stdexcept>
#include <string>

namespace suite::contact {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// Errors in a scene or a body description (bad size, density, unknown type, ...): one-line message.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class ShapeType { Plane = 0, Sphere = 1, Box = 2, Capsule = 3, Cylinder = 4 };
const char* shapeName(ShapeType t);
// Throws SceneError("unknown body type 'x' (plane, sphere, box, capsule, cylinder)").
ShapeType shapeFromName(const std::string& name);

// Geometry in the body frame. Capsule and cylinder axes are the local z axis; a plane is the body's
// local z = 0 plane with normal +z (body frame), i.e. world normal R e_z through the body position.
struct Shape {
  ShapeType type = ShapeType::Sphere;
  double radius = 0.0;      // sphere, capsule, cylinder
  double half_length = 0.0; // capsule, cylinder: half the axis segment
  Vec3 half = Vec3::Zero(); // box half extents
};

struct Body {
  std::string name;
  Shape shape;
  bool is_static = false;
  double mass = 0.0, inv_mass = 0.0;
  Vec3 inertia = Vec3::Zero();             // principal moments (body frame)
  Vec3 inv_inertia = Vec3::Zero();         // 0 for static bodies
  Vec3 x = Vec3::Zero();                   // centre of mass (world)
  Quat q = Quat::Identity();               // orientation body -> world
  Vec3 v = Vec3::Zero(), w = Vec3::Zero(); // linear and angular velocity (world)
  // Collision filter (MJCF contype / conaffinity): bodies a and b collide when (contype_a & conaffinity_b) or
  // (contype_b & conaffinity_a) is non-zero.
  unsigned contype = 1, conaffinity = 1;

  Mat3 R() const { return q.toRotationMatrix(); }
  Mat3 invInertiaWorld() const;
  Mat3 inertiaWorld() const;
  // Plane: world normal and offset d with n.x = d on the plane.
  Vec3 planeNormal() const { return R().col(2); }
  double planeOffset() const { return planeNormal().dot(x); }
  // Capsule/cylinder: world axis unit vector.
  Vec3 axis() const { return R().col(2); }
  // Kinetic energy 0.5 m v^2 + 0.5 w^T I w.
  double kineticEnergy() const;
  // Bounding radius around x (infinite for planes).
  double boundingRadius() const;
};

// Checks sizes (> 0, finite) and density/mass (> 0) and fills mass, inertia. Static bodies (and all
// planes) get infinite mass (inv_mass = 0). mass > 0 overrides the density. Throws SceneError.
Body makeBody(const std::string& name, const Shape& shape, double density, double mass, const Vec3& x,
              const Quat& q, bool is_static);

// One step of the pose with velocities v, w: x += dt v, q <- exp(dt w / 2) q (normalised).
void advancePose(Body* b, const Vec3& v, const Vec3& w, double dt);

// The dynamic state of a body as kStateSize numbers (checkpoints): x (3), q (x, y, z, w), v (3), w (3).
constexpr int kStateSize = 13;
void packState(const Body& b, double* r);
void unpackState(const double* r, Body* b);

} // namespace suite::contact
