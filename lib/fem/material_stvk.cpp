// St. Venant-Kirchhoff: E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E, P = F S, W = lambda/2 tr(E)^2 + mu
// E:E; consistent tangent dP_iJ/dF_kL = d_ik S_LJ + lambda F_iJ F_kL + mu (F F^T)_ik d_JL + mu F_iL F_kJ.
// Reference: Bonet & Wood, Nonlinear Continuum Mechanics for FEA (2nd ed. 2008), sec. 6.4.1 and 7.4.
#include "fem/material.hpp"

namespace suite::fem {
namespace {
class StVenantKirchhoff final : public Material {
public:
  explicit StVenantKirchhoff(Lame l) : Material(l) {}
  const char* name() const override { return "stvk"; }
  void addElementTangent(const Mat3& F, const double* g, int nen, double w, double* ke) const override {
    const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
    const Mat3 S = lame_.lambda * E.trace() * Mat3::Identity() + 2 * lame_.mu * E;
    addStVKElementTangent(F, S, lame_, g, nen, w, ke);
  }
  void evaluateWithTangent(const Mat3& F, const double* g, int nen, double w, double* W, Mat3* P,
                           double* ke) const override {
    const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
    const double tr = E.trace();
    const Mat3 S = lame_.lambda * tr * Mat3::Identity() + 2 * lame_.mu * E;
    *P = F * S;
    *W = 0.5 * lame_.lambda * tr * tr + lame_.mu * E.squaredNorm();
    addStVKElementTangent(F, S, lame_, g, nen, w, ke);
  }
  void evaluate(const Mat3& F, double* W, Mat3* P, Tangent* A) const override {
    const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
    const double tr = E.trace();
    const Mat3 S = lame_.lambda * tr * Mat3::Identity() + 2 * lame_.mu * E;
    *P = F * S;
    *W = 0.5 * lame_.lambda * tr * tr + lame_.mu * E.squaredNorm();
    if (!A) return;
    const Mat3 B = F * F.transpose();
    const double lam = lame_.lambda, mu = lame_.mu;
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            (*A)(3 * i + J, 3 * k + L) = (i == k ? S(L, J) : 0.0) + lam * F(i, J) * F(k, L) +
                                         (J == L ? mu * B(i, k) : 0.0) + mu * F(i, L) * F(k, J);
  }
};
} // namespace

std::unique_ptr<Material> makeStVenantKirchhoff(Lame l) {
  return std::make_unique<StVenantKirchhoff>(l);
}

} // namespace suite::fem
