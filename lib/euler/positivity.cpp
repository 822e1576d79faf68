// Hu, Adams & Shu (2013) positivity-preserving flux limiter, sec. 3.
#include "euler/positivity.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

Vec3 laxFriedrichsFlux(const Vec3& qa, const Vec3& qb, double alpha, double gamma) {
  const Vec3 fa = physicalFlux(qa, gamma), fb = physicalFlux(qb, gamma);
  return {0.5 * (fa[0] + fb[0] - alpha * (qb[0] - qa[0])), 0.5 * (fa[1] + fb[1] - alpha * (qb[1] - qa[1])),
          0.5 * (fa[2] + fb[2] - alpha * (qb[2] - qa[2]))};
}

namespace {
// One-sided states U_j - 2 lambda h (side 0) and U_{j+1} + 2 lambda h (side 1).
inline Vec3 side(const Vec3& q, const Vec3& h, double s) {
  return {q[0] + s * h[0], q[1] + s * h[1], q[2] + s * h[2]};
}
} // namespace

double limitPositivity(const Vec3& qa, const Vec3& qb, double alpha, double lambda, double gamma, Vec3* h) {
  const Vec3 lf = laxFriedrichsFlux(qa, qb, alpha, gamma);
  const Vec3* q[2] = {&qa, &qb};
  const double s[2] = {-2.0 * lambda, 2.0 * lambda};
  Vec3 lfSide[2] = {side(qa, lf, s[0]), side(qb, lf, s[1])};
  const double eps_rho = std::min(1e-13, std::min(lfSide[0][0], lfSide[1][0]));
  const double eps_p = std::min(1e-13, std::min(pressure(lfSide[0], gamma), pressure(lfSide[1], gamma)));
  double theta = 1.0;
  for (int k = 0; k < 2; ++k) { // density, eq. (3.8)
    const double rh = (*q[k])[0] + s[k] * (*h)[0], rl = lfSide[k][0];
    if (rh < eps_rho) theta = std::min(theta, (rl - eps_rho) / (rl - rh));
  }
  theta = std::clamp(theta, 0.0, 1.0);
  for (int c = 0; c < 3; ++c) (*h)[c] = theta * (*h)[c] + (1.0 - theta) * lf[c];
  double theta_p = 1.0;
  for (int k = 0; k < 2; ++k) { // pressure, eq. (3.11): p is concave, so p(blend) >= blend of p
    const double ph = pressure(side(*q[k], *h, s[k]), gamma), pl = pressure(lfSide[k], gamma);
    if (ph < eps_p) theta_p = std::min(theta_p, (pl - eps_p) / (pl - ph));
  }
  theta_p = std::clamp(theta_p, 0.0, 1.0);
  if (theta_p < 1.0)
    for (int c = 0; c < 3; ++c) (*h)[c] = theta_p * (*h)[c] + (1.0 - theta_p) * lf[c];
  return theta * theta_p;
}

} // namespace suite::euler
