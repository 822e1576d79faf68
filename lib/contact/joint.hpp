// Joints of the contact library: holonomic constraints Phi(q) = 0 between two bodies, or a body and the world,
// in maximal coordinates (each body keeps its 6 velocities; a joint adds constraint rows G v = 0). Types and
// their rows: ball (3: the anchors coincide), hinge (5: ball + the axes parallel), slider (5: the relative
// orientation fixed + the anchor offset along the axis only), fixed (6: ball + orientation), distance (1: the
// anchors at a fixed distance). Every row is the time derivative of a scalar Phi_k(q), so that G is the exact
// Jacobian of Phi and the position projection (joint_system.hpp) converges quadratically:
//   point rows   Phi = e_k . (p_a - p_b), p = x + R r (anchor);
//   axis rows    Phi = (R_a u) . (R_b w) for body-fixed unit vectors u, w orthogonal at assembly;
//   slider rows  Phi = (R_a u) . (p_b - p_a) for u orthogonal to the slide axis;
//   distance     Phi = |p_a - p_b| - L.
// Reference: maximal-coordinate constraint rows as in Erleben, "Velocity-based shock propagation for multibody
// dynamics animation", ACM TOG 26 (2007), and Lacoursiere, PhD thesis, Umea 2007 (ch. 5).
#pragma once

#include "contact/body.hpp"

#include <string>
#include <vector>

namespace suite::contact {

enum class JointType { Ball = 0, Hinge = 1, Slider = 2, Fixed = 3, Distance = 4 };
const char* jointName(JointType t);
// Throws SceneError("unknown joint type 'x' (ball, hinge, slider, fixed, distance)").
JointType jointFromName(const std::string& name);
// Constraint rows of a joint of this type: 3, 5, 5, 6, 1.
int jointRowCount(JointType t);

struct Joint {
  std::string name;
  JointType type = JointType::Ball;
  int a = -1; // body index (dynamic)
  int b = -1; // body index, or -1: the world
  // Anchor: in a's body frame; in b's body frame (the world point when b = -1).
  Vec3 ra = Vec3::Zero(), rb = Vec3::Zero();
  // Orthonormal frames, column 2 the joint axis (hinge, slider): in a's body frame, and in b's (the world
  // frame when b = -1); equal in the world at assembly.
  Mat3 fa = Mat3::Identity(), fb = Mat3::Identity();
  double length = 0.0; // distance joint: the anchors' distance
  // Limit (hinge: the angle of b relative to a about the axis, rad; slider: the travel of b relative to a along
  // the axis, m; both zero at assembly): a unilateral row that acts only when reached.
  bool limited = false;
  double lower = 0.0, upper = 0.0;
  // Velocity motor (hinge, slider): drives the relative speed about / along the axis to target_speed (rad/s,
  // m/s) with a force (torque) bounded by max_force (N, N m; > 0): a box row.
  bool motor = false;
  double target_speed = 0.0, max_force = 0.0;
};

// A joint assembled at the bodies' current poses: anchor and axis in the world (axis: hinge and slider; any
// non-zero vector, normalised). Distance joints: anchor_b is the second anchor (world), length = |anchor_b -
// anchor| (> 0). Throws SceneError (bad body index, a static or same body, zero axis, zero length).
Joint makeJoint(const std::string& name, JointType type, const std::vector<Body>& bodies, int a, int b,
                const Vec3& anchor, const Vec3& axis, const Vec3& anchor_b = Vec3::Zero());

// One constraint row: Phi_k and its Jacobian, G_k v = ja . (v_a, w_a) + jb . (v_b, w_b) (jb unused when the
// joint's b is the world).
struct JointRow {
  double phi = 0.0;
  Eigen::Matrix<double, 6, 1> ja, jb;
};
// The rows of joint j at the bodies' poses, appended to rows.
void jointRows(const Joint& j, const std::vector<Body>& bodies, std::vector<JointRow>* rows);

// The coordinate of a hinge or slider joint (phi) and its rate row (d phi / dt = ja . (v_a, w_a) + jb . (v_b,
// w_b)): hinge, the angle of b's frame relative to a's about a's axis, atan2 of the frames' first columns, in
// (-pi, pi]; slider, the travel u . (p_b - p_a) along a's axis u. Both zero at assembly (makeJoint).
JointRow jointCoordinate(const Joint& j, const std::vector<Body>& bodies);

} // namespace suite::contact
