// Linear isotropic elasticity: eps = sym(F - I), W = lambda/2 tr(eps)^2 + mu eps:eps, P = sigma(eps)
// (small strain, not rotation invariant). Reference: Hughes, The Finite Element Method (1987), ch. 2.
#include "fem/material.hpp"

namespace suite::fem {
namespace {
class LinearMaterial final : public Material {
public:
  explicit LinearMaterial(Lame l) : Material(l), C_(isotropicTangent(l)) {}
  const char* name() const override { return "linear"; }
  bool isLinear() const override { return true; }
  void addElementTangent(const Mat3&, const double* g, int nen, double w, double* ke) const override {
    addStVKElementTangent(Mat3::Identity(), Mat3::Zero(), lame_, g, nen, w, ke);
  }
  void evaluate(const Mat3& F, double* W, Mat3* P, Tangent* A) const override {
    const Mat3 eps = 0.5 * (F + F.transpose()) - Mat3::Identity();
    const double tr = eps.trace();
    *P = lame_.lambda * tr * Mat3::Identity() + 2 * lame_.mu * eps;
    *W = 0.5 * lame_.lambda * tr * tr + lame_.mu * eps.squaredNorm();
    if (A) *A = C_;
  }

private:
  Tangent C_;
};
} // namespace

std::unique_ptr<Material> makeLinearMaterial(Lame l) {
  return std::make_unique<LinearMaterial>(l);
}

} // namespace suite::fem
