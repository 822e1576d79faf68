// MUSCL (van Leer limiter) + HLLC (Toro 2009 sec. 10.4).
#include "euler/muscl2.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

Vec3 hllcFlux(const Vec3& qL, const Vec3& qR, double gamma) {
  const Prim wL = toPrim(qL, gamma), wR = toPrim(qR, gamma);
  const double cL = soundSpeed(wL.rho, std::max(wL.p, 0.0), gamma);
  const double cR = soundSpeed(wR.rho, std::max(wR.p, 0.0), gamma);
  const double SL = std::min(wL.u - cL, wR.u - cR), SR = std::max(wL.u + cL, wR.u + cR);
  const Vec3 fL = physicalFlux(qL, gamma), fR = physicalFlux(qR, gamma);
  if (SL >= 0.0) return fL;
  if (SR <= 0.0) return fR;
  const double Sm = (wR.p - wL.p + wL.rho * wL.u * (SL - wL.u) - wR.rho * wR.u * (SR - wR.u)) /
                    (wL.rho * (SL - wL.u) - wR.rho * (SR - wR.u));
  auto star = [&](const Vec3& q, const Prim& w, double S) {
    const double k = w.rho * (S - w.u) / (S - Sm);
    return Vec3{k, k * Sm, k * (q[2] / w.rho + (Sm - w.u) * (Sm + w.p / (w.rho * (S - w.u))))};
  };
  if (Sm >= 0.0) {
    const Vec3 s = star(qL, wL, SL);
    return {fL[0] + SL * (s[0] - qL[0]), fL[1] + SL * (s[1] - qL[1]), fL[2] + SL * (s[2] - qL[2])};
  }
  const Vec3 s = star(qR, wR, SR);
  return {fR[0] + SR * (s[0] - qR[0]), fR[1] + SR * (s[1] - qR[1]), fR[2] + SR * (s[2] - qR[2])};
}

namespace {
inline double vanLeer(double a, double b) {
  return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
}
} // namespace

Vec3 muscl2Flux(const Vec3* q, double gamma) {
  Prim w[4];
  for (int k = 0; k < 4; ++k) w[k] = toPrim(q[k], gamma);
  auto comp = [](const Prim& x, int c) { return c == 0 ? x.rho : (c == 1 ? x.u : x.p); };
  double l[3], r[3];
  for (int c = 0; c < 3; ++c) {
    const double d0 = comp(w[1], c) - comp(w[0], c), d1 = comp(w[2], c) - comp(w[1], c),
                 d2 = comp(w[3], c) - comp(w[2], c);
    l[c] = comp(w[1], c) + 0.5 * vanLeer(d0, d1);
    r[c] = comp(w[2], c) - 0.5 * vanLeer(d1, d2);
  }
  return hllcFlux(toCons({l[0], l[1], l[2]}, gamma), toCons({r[0], r[1], r[2]}, gamma), gamma);
}

} // namespace suite::euler
