// Test helper of the contact unit tests: the downhill speed of the box (body 1) of the incline scene, whose
// plane is tilted by theta_deg about y (lib/contact/scenes.cpp).
#pragma once

#include "contact/body.hpp"

#include <cmath>
#include <vector>

namespace suite::contact::test {

inline double downhillSpeed(const std::vector<Body>& b, double theta_deg) {
  const double th = theta_deg * M_PI / 180.0;
  return b[1].v.dot(Vec3(-std::cos(th), 0, -std::sin(th)));
}

} // namespace suite::contact::test
