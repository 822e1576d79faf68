// Exact Riemann solver for the ideal-gas Euler equations (Toro 2009, ch. 4; vacuum cases sec. 4.6).
#include "euler/exact_riemann.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace suite::euler {

namespace {
bool isVacuum(const Prim& w) {
  return w.rho == 0.0 && w.p == 0.0;
}
bool isGas(const Prim& w) {
  return w.rho > 0 && w.p >= 0 && std::isfinite(w.rho + w.u + w.p);
}
} // namespace

ExactRiemann::ExactRiemann(const Prim& left, const Prim& right, double gamma)
    : L_(left), R_(right), g_(gamma) {
  const bool vacL = isVacuum(left), vacR = isVacuum(right);
  if (!(gamma > 1) || !(vacL || isGas(left)) || !(vacR || isGas(right)) || (vacL && vacR))
    throw std::invalid_argument(
        "ExactRiemann: states need rho > 0 and p >= 0, or rho = p = 0 (vacuum) on one side, and gamma > 1");
  if (!vacL) cL_ = soundSpeed(L_.rho, L_.p, g_);
  if (!vacR) cR_ = soundSpeed(R_.rho, R_.p, g_);
  const double du = R_.u - L_.u;
  if (vacL || vacR || 2.0 * (cL_ + cR_) / (g_ - 1.0) <= du) { // sec. 4.6; generation: (4.40)
    vacuum_ = vacR ? Vacuum::Right : vacL ? Vacuum::Left : Vacuum::Generated;
    const double sL = L_.u + 2.0 * cL_ / (g_ - 1.0), sR = R_.u - 2.0 * cR_ / (g_ - 1.0);
    u_star_ = vacR ? sL : vacL ? sR : 0.5 * (sL + sR);
    return;
  }
  // Two-rarefaction guess (4.46), Newton on f(p) = fL + fR + du (4.44).
  const double z = (g_ - 1.0) / (2.0 * g_);
  double p = std::pow(
      (cL_ + cR_ - 0.5 * (g_ - 1.0) * du) / (cL_ / std::pow(L_.p, z) + cR_ / std::pow(R_.p, z)), 1.0 / z);
  if (!(p > 0) || !std::isfinite(p)) p = std::max(1e-12, 0.5 * (L_.p + R_.p));
  for (int it = 0; it < 200; ++it) {
    double dL, dR;
    const double f = pressureFunction(p, L_, cL_, &dL) + pressureFunction(p, R_, cR_, &dR) + du;
    double pn = p - f / (dL + dR);
    if (pn <= 0) pn = 0.1 * p;
    const double change = 2.0 * std::abs(pn - p) / (pn + p);
    p = pn;
    if (change < 1e-15) break;
  }
  p_star_ = p;
  double dL, dR;
  u_star_ =
      0.5 * (L_.u + R_.u) + 0.5 * (pressureFunction(p, R_, cR_, &dR) - pressureFunction(p, L_, cL_, &dL));
}

double ExactRiemann::pressureFunction(double p, const Prim& w, double c, double* dfdp) const {
  if (p > w.p) { // shock (4.6)
    const double A = 2.0 / ((g_ + 1.0) * w.rho), B = (g_ - 1.0) / (g_ + 1.0) * w.p;
    const double s = std::sqrt(A / (p + B));
    *dfdp = s * (1.0 - 0.5 * (p - w.p) / (B + p));
    return (p - w.p) * s;
  }
  // rarefaction (4.7)
  const double z = (g_ - 1.0) / (2.0 * g_);
  const double pr = std::pow(p / w.p, z);
  *dfdp = 1.0 / (w.rho * c) * std::pow(p / w.p, -(g_ + 1.0) / (2.0 * g_));
  return 2.0 * c / (g_ - 1.0) * (pr - 1.0);
}

Prim ExactRiemann::leftFan(double s) const {
  const double gm = g_ - 1.0, gp = g_ + 1.0;
  const double c = 2.0 / gp * (cL_ + 0.5 * gm * (L_.u - s));
  return {L_.rho * std::pow(c / cL_, 2.0 / gm), 2.0 / gp * (cL_ + 0.5 * gm * L_.u + s),
          L_.p * std::pow(c / cL_, 2.0 * g_ / gm)};
}

Prim ExactRiemann::rightFan(double s) const {
  const double gm = g_ - 1.0, gp = g_ + 1.0;
  const double c = 2.0 / gp * (cR_ - 0.5 * gm * (R_.u - s));
  return {R_.rho * std::pow(c / cR_, 2.0 / gm), 2.0 / gp * (-cR_ + 0.5 * gm * R_.u + s),
          R_.p * std::pow(c / cR_, 2.0 * g_ / gm)};
}

// Right vacuum (4.76)-(4.78): left state, left fan, vacuum beyond the front sL. Left vacuum (4.79)-(4.81):
// the mirror image. Generated vacuum (4.82)-(4.83): both fans with vacuum between the fronts sL < sR.
Prim ExactRiemann::sampleVacuum(double s) const {
  const double gm = g_ - 1.0;
  const double sL = L_.u + 2.0 * cL_ / gm, sR = R_.u - 2.0 * cR_ / gm;
  if (vacuum_ != Vacuum::Left) {
    if (s <= L_.u - cL_) return L_;
    if (s < sL) return leftFan(s);
    if (vacuum_ == Vacuum::Right) return {0.0, sL, 0.0};
  }
  if (vacuum_ != Vacuum::Right) {
    if (s >= R_.u + cR_) return R_;
    if (s > sR) return rightFan(s);
    if (vacuum_ == Vacuum::Left) return {0.0, sR, 0.0};
  }
  return {0.0, 0.5 * (sL + sR), 0.0};
}

Prim ExactRiemann::sample(double s) const {
  if (vacuum_ != Vacuum::None) return sampleVacuum(s);
  const double g = g_, gm = g - 1.0, gp = g + 1.0;
  const double ps = p_star_, us = u_star_;
  if (s <= us) { // left of the contact
    const Prim& w = L_;
    const double c = cL_;
    if (ps > w.p) {
      const double S = w.u - c * std::sqrt(gp / (2 * g) * ps / w.p + gm / (2 * g));
      if (s <= S) return w;
      return {w.rho * (ps / w.p + gm / gp) / (gm / gp * ps / w.p + 1.0), us, ps};
    }
    const double cs = c * std::pow(ps / w.p, gm / (2 * g));
    if (s <= w.u - c) return w;
    if (s >= us - cs) return {w.rho * std::pow(ps / w.p, 1.0 / g), us, ps};
    return leftFan(s);
  }
  const Prim& w = R_;
  const double c = cR_;
  if (ps > w.p) {
    const double S = w.u + c * std::sqrt(gp / (2 * g) * ps / w.p + gm / (2 * g));
    if (s >= S) return w;
    return {w.rho * (ps / w.p + gm / gp) / (gm / gp * ps / w.p + 1.0), us, ps};
  }
  const double cs = c * std::pow(ps / w.p, gm / (2 * g));
  if (s >= w.u + c) return w;
  if (s <= us + cs) return {w.rho * std::pow(ps / w.p, 1.0 / g), us, ps};
  return rightFan(s);
}

} // namespace suite::euler
