// Conventions the MJCF reader (mjcf.cpp) and writer (mjcf_write.cpp) share: the sign between MJCF's joint
// coordinates and joint.hpp's, the deepest body nesting tinyxml2 reads, the motor's servo band, and the number
// format. Internal to lib/contact.
#pragma once

#include <tinyxml2.h>

#include <cstdio>
#include <string>

namespace suite::contact::mjcf {

// MJCF's joint coordinate (hinge angle, slide travel and their speeds) is the child's (our a's) motion relative
// to its parent (b); joint.hpp's limits are b's motion relative to a: the opposite sign.
constexpr double kJointSign = -1.0;
// Writer: kv of the velocity actuators, max_force / kMotorSpeedBand: MuJoCo's servo saturates at max_force
// beyond this speed error (rad/s, m/s), close to our hard motor with a bounded force.
constexpr double kMotorSpeedBand = 1e-3;
// The deepest element nesting tinyxml2 parses is TINYXML2_MAX_ELEMENT_DEPTH - 2; a body at depth d (a child of
// <worldbody>: 1) has its <geom> at d + 3.
constexpr int kMaxBodyDepth = TINYXML2_MAX_ELEMENT_DEPTH - 2 - 3;

// A number as MJCF text that reads back to the same double (%.17g).
inline std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

} // namespace suite::contact::mjcf
