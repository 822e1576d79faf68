// Joint limits and motors (joint.hpp) as the inequality rows of the step's joint block, with theta the joint's
// coordinate (hinge angle, slider travel) and J its rate row (jointCoordinate):
//   lower limit   J v + (theta - lower) / dt >= 0  _|_  lambda >= 0   (a unilateral row, acting when reached)
//   upper limit  -J v + (upper - theta) / dt >= 0  _|_  lambda >= 0
//   motor         J v - target  in the normal cone of [-F dt, F dt] at lambda   (a box row, F = max_force)
// (the box MLCP of stepper.hpp with the G block). They are solved exactly by an active-set outer loop around
// the step's equality solve (joint_system.hpp, with the contacts): a guess of the set (each limit off, at its
// lower or its upper bound; each motor free or saturated at +-F dt) makes the active limits and the free motors
// equality rows of the joint system with their bias, the saturated motors fixed impulses; after the solve the
// complementarity conditions are checked on the end velocities and impulses and the violators switched: all at
// once for the first kBlockSwitches solves (block principal pivoting, Judice & Pires, Comput. Oper. Res. 21
// (1994) 587), then the first violator only (Murty's least-index rule, finite for the P-matrix J P J^T of
// independent rows). The checks have a hysteresis of tol (m/s, rad/s) in velocity and tol / (J M^-1 J^T) in
// impulse, so that a limit touched with zero load does not cycle. Each step starts from the previous step's
// set: a mechanism resting on its limit or a saturated motor takes one solve.
// The limit rows are velocity-level (the gap closes at the step's end to first order in dt); the position
// projection (joint_system.hpp) acts on the holonomic rows only.
#pragma once

#include "contact/delassus.hpp"
#include "contact/joint.hpp"

#include <Eigen/Core>

#include <vector>

namespace suite::contact {

// The equality rows and fixed impulses of one guess of the active set.
struct ActuationRows {
  std::vector<JRow> rows;   // the rows' Jacobians with their M^-1 parts
  std::vector<double> bias; // G v + bias = 0
  std::vector<int> joint;   // the row's joint
};

class JointActuation {
public:
  static constexpr int kBlockSwitches = 5;
  // Sizes the set for these joints (every limit off, every motor free) if they changed.
  void reset(const std::vector<Joint>& joints);
  bool empty() const { return idx_.empty(); }
  // The coordinates and rate rows of the step, at the bodies' poses at its start.
  void prepare(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
               const std::vector<Joint>& joints, double dt);
  // The equality rows of the current guess.
  ActuationRows rows() const;
  // The saturated motors' impulses applied: v += M^-1 J^T (+-F dt).
  void applyFixed(std::vector<Vec3>* v, std::vector<Vec3>* w) const;
  // After the solve with rows(): lambda, the impulses of those rows, and the end velocities. True when every
  // condition holds (the impulses of the joints are recorded); false: the guess is switched (attempt counts the
  // solves of this step, from 1).
  bool update(const Eigen::VectorXd& lambda, const std::vector<Vec3>& v, const std::vector<Vec3>& w,
              int attempt);
  // Per joint after an accepted update: the limit's and the motor's impulse (N s, N m s; along the rate row),
  // the coordinate at the step's start, its rate at the step's end.
  double limitImpulse(int joint) const { return limit_impulse_[joint]; }
  double motorImpulse(int joint) const { return motor_impulse_[joint]; }
  double coordinate(int joint) const { return coord_[joint]; }
  double rate(int joint) const { return rate_[joint]; }
  // The Jacobian of joint's rate row (zero rows for joints without limit or motor).
  const JRow& rateRow(int joint) const { return rate_row_[joint]; }

private:
  std::vector<int> idx_;           // the joints with a limit or a motor
  std::vector<Joint> spec_;        // their limits and motors (of every joint, to detect a change)
  std::vector<signed char> limit_; // -1 lower active, 0 off, +1 upper active
  std::vector<signed char> motor_; // 0 free, +-1 saturated at +-F dt
  std::vector<JRow> rate_row_;     // per joint
  std::vector<double> coord_, rate_, mass_, limit_impulse_, motor_impulse_;
  double dt_ = 0.0;
};

// Tolerance of the actuation checks (m/s, rad/s): far below what a step resolves, above the LCP acceptance of
// the contacts it is solved with (1e-8 (1 + |b|)).
constexpr double kActuationTol = 1e-7;

} // namespace suite::contact
