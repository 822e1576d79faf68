// Ideal-gas state of the 1D Euler equations: conserved <-> primitive variables, physical flux, sound speed.
// Reference: Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed. (2009), eqs.
// (3.1)-(3.3).
#pragma once

#include <array>
#include <cmath>

namespace suite::euler {

using Vec3 = std::array<double, 3>; // conserved (rho, rho u, E) or any 3-vector
using Mat3 = std::array<double, 9>; // row-major 3x3

struct Prim {
  double rho, u, p;
};

inline Vec3 toCons(const Prim& w, double gamma) {
  return {w.rho, w.rho * w.u, w.p / (gamma - 1.0) + 0.5 * w.rho * w.u * w.u};
}
inline Prim toPrim(const Vec3& q, double gamma) {
  const double u = q[1] / q[0];
  return {q[0], u, (gamma - 1.0) * (q[2] - 0.5 * q[1] * u)};
}
inline double pressure(const Vec3& q, double gamma) {
  return (gamma - 1.0) * (q[2] - 0.5 * q[1] * q[1] / q[0]);
}
inline Vec3 physicalFlux(const Vec3& q, double gamma) {
  const double u = q[1] / q[0], p = pressure(q, gamma);
  return {q[1], q[1] * u + p, (q[2] + p) * u};
}
inline double soundSpeed(double rho, double p, double gamma) {
  return std::sqrt(gamma * p / rho);
}
// Largest characteristic speed |u| + c of a conserved state (NaN-propagating).
inline double maxWaveSpeed(const Vec3& q, double gamma) {
  const double u = q[1] / q[0];
  return std::abs(u) + std::sqrt(std::abs(gamma * pressure(q, gamma) / q[0]));
}

} // namespace suite::euler
