// Roe-averaged eigensystem of the 1D Euler equations (Roe 1981; Toro 2009 sec. 11.2).
#include "euler/characteristic.hpp"

#include <cmath>

namespace suite::euler {

Eigensystem roeEigensystem(const Vec3& qa, const Vec3& qb, double gamma) {
  const double ra = std::sqrt(qa[0]), rb = std::sqrt(qb[0]);
  const double ua = qa[1] / qa[0], ub = qb[1] / qb[0];
  const double Ha = (qa[2] + pressure(qa, gamma)) / qa[0], Hb = (qb[2] + pressure(qb, gamma)) / qb[0];
  const double w = 1.0 / (ra + rb);
  const double u = (ra * ua + rb * ub) * w, H = (ra * Ha + rb * Hb) * w;
  const double c2 = std::max((gamma - 1.0) * (H - 0.5 * u * u), 1e-300);
  const double c = std::sqrt(c2);
  Eigensystem e;
  e.u = u;
  e.c = c;
  e.R = {1.0, 1.0, 1.0, u - c, u, u + c, H - u * c, 0.5 * u * u, H + u * c};
  const double b1 = (gamma - 1.0) / c2, b2 = 0.5 * b1 * u * u;
  e.L = {0.5 * (b2 + u / c), -0.5 * (b1 * u + 1.0 / c), 0.5 * b1, 1.0 - b2, b1 * u, -b1,
         0.5 * (b2 - u / c), -0.5 * (b1 * u - 1.0 / c), 0.5 * b1};
  return e;
}

} // namespace suite::euler
