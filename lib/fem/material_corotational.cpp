// Corotational linear elasticity: polar decomposition F = R U, eps = U - I, W = lambda/2 tr(eps)^2 + mu
// eps:eps, P = R sigma(eps); tangent approximated by the rotated small-strain tangent R C R^T (the dR term is
// dropped, as in Mueller & Gross, "Interactive virtual materials", GI 2004, and Hauth & Strasser 2004).
#include "fem/material.hpp"

namespace suite::fem {
namespace {
class Corotational final : public Material {
public:
  explicit Corotational(Lame l) : Material(l), C_(isotropicTangent(l)) {}
  const char* name() const override { return "corotational"; }
  void evaluate(const Mat3& F, double* W, Mat3* P, Tangent* A) const override {
    Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 U = svd.matrixU(), V = svd.matrixV();
    Eigen::Vector3d s = svd.singularValues();
    if (U.determinant() * V.determinant() < 0) { // proper rotation; the smallest stretch takes the sign
      U.col(2) *= -1;
      s(2) *= -1;
    }
    const Mat3 R = U * V.transpose();
    const Mat3 eps = V * s.asDiagonal() * V.transpose() - Mat3::Identity();
    const double tr = eps.trace();
    *P = R * (lame_.lambda * tr * Mat3::Identity() + 2 * lame_.mu * eps);
    *W = 0.5 * lame_.lambda * tr * tr + lame_.mu * eps.squaredNorm();
    if (!A) return;
    Tangent Rb = Tangent::Zero(); // (R (x) I): maps index (a,J) -> (i,J) with R_ia
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 3; ++a)
        for (int J = 0; J < 3; ++J) Rb(3 * i + J, 3 * a + J) = R(i, a);
    *A = Rb * C_ * Rb.transpose();
  }

private:
  Tangent C_;
};
} // namespace

std::unique_ptr<Material> makeCorotational(Lame l) {
  return std::make_unique<Corotational>(l);
}

} // namespace suite::fem
