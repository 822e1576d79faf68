// Corotational linear elasticity: polar decomposition F = R U, eps = U - I, W = lambda/2 tr(eps)^2 + mu
// eps:eps, P = R sigma(eps); tangent approximated by the rotated small-strain tangent R C R^T (the dR term is
// dropped, as in Mueller & Gross, "Interactive virtual materials", GI 2004, and Hauth & Strasser 2004).
// R by Higham's scaled Newton iteration (Higham, SIAM J. Sci. Stat. Comput. 7 (1986) 1160, sec. 3); for an
// isotropic C the element tangent of R C R^T is the closed form of addStVKElementTangent with F = R, S = 0.
#include "fem/material.hpp"

#include <cmath>

namespace suite::fem {
namespace {

// R of F = R U with det F <= 0 too (the smallest stretch takes the sign), through the SVD.
Mat3 rotationBySvd(const Mat3& F) {
  Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 U = svd.matrixU(), V = svd.matrixV();
  if (U.determinant() * V.determinant() < 0) U.col(2) *= -1;
  return U * V.transpose();
}

// X <- (g X + X^-T / g) / 2 from X = F (det F > 0), X^-T = cof(X) / det X; g = |det X|^(-1/3) (Higham's
// determinant scaling, 1986, eq. 3.4) in the first iteration, g = 1 after. Quadratic: once the update is below
// 1e-8 |X| the next iterate is at round-off, so the loop stops after that update (3-4 iterations at the
// strains of elastic bodies). Squared Frobenius norms: no square roots.
Mat3 polarRotation(const Mat3& F) {
  const double det0 = F.determinant();
  if (!(det0 > 0)) return rotationBySvd(F);
  Mat3 X = F;
  double det = det0;
  for (int it = 0; it < 40; ++it) {
    Mat3 cof; // cofactor matrix: X^-T = cof / det
    cof(0, 0) = X(1, 1) * X(2, 2) - X(1, 2) * X(2, 1);
    cof(0, 1) = X(1, 2) * X(2, 0) - X(1, 0) * X(2, 2);
    cof(0, 2) = X(1, 0) * X(2, 1) - X(1, 1) * X(2, 0);
    cof(1, 0) = X(0, 2) * X(2, 1) - X(0, 1) * X(2, 2);
    cof(1, 1) = X(0, 0) * X(2, 2) - X(0, 2) * X(2, 0);
    cof(1, 2) = X(0, 1) * X(2, 0) - X(0, 0) * X(2, 1);
    cof(2, 0) = X(0, 1) * X(1, 2) - X(0, 2) * X(1, 1);
    cof(2, 1) = X(0, 2) * X(1, 0) - X(0, 0) * X(1, 2);
    cof(2, 2) = X(0, 0) * X(1, 1) - X(0, 1) * X(1, 0);
    if (it > 0) det = X(0, 0) * cof(0, 0) + X(0, 1) * cof(0, 1) + X(0, 2) * cof(0, 2);
    const double g = it == 0 ? 1.0 / std::cbrt(det) : 1.0;
    const Mat3 next = 0.5 * (g * X + cof / (g * det));
    const double update2 = (next - X).squaredNorm(), norm2 = next.squaredNorm();
    X = next;
    if (update2 <= 1e-16 * norm2) break;
  }
  return X;
}

class Corotational final : public Material {
public:
  explicit Corotational(Lame l) : Material(l), C_(isotropicTangent(l)) {}
  const char* name() const override { return "corotational"; }
  void evaluate(const Mat3& F, double* W, Mat3* P, Tangent* A) const override {
    const Mat3 R = polarRotation(F);
    stress(F, R, W, P);
    if (!A) return;
    Tangent Rb = Tangent::Zero(); // (R (x) I): maps index (a,J) -> (i,J) with R_ia
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 3; ++a)
        for (int J = 0; J < 3; ++J) Rb(3 * i + J, 3 * a + J) = R(i, a);
    *A = Rb * C_ * Rb.transpose();
  }
  void addElementTangent(const Mat3& F, const double* g, int nen, double w, double* ke) const override {
    addStVKElementTangent(polarRotation(F), Mat3::Zero(), lame_, g, nen, w, ke);
  }
  void evaluateWithTangent(const Mat3& F, const double* g, int nen, double w, double* W, Mat3* P,
                           double* ke) const override {
    const Mat3 R = polarRotation(F);
    stress(F, R, W, P);
    addStVKElementTangent(R, Mat3::Zero(), lame_, g, nen, w, ke);
  }

private:
  // eps = sym(R^T F) - I (R^T F = U, symmetric up to round-off), P = R sigma(eps), W.
  void stress(const Mat3& F, const Mat3& R, double* W, Mat3* P) const {
    const Mat3 U = R.transpose() * F;
    const Mat3 eps = 0.5 * (U + U.transpose()) - Mat3::Identity();
    const double tr = eps.trace();
    *P = R * (lame_.lambda * tr * Mat3::Identity() + 2 * lame_.mu * eps);
    *W = 0.5 * lame_.lambda * tr * tr + lame_.mu * eps.squaredNorm();
  }
  Tangent C_;
};
} // namespace

std::unique_ptr<Material> makeCorotational(Lame l) {
  return std::make_unique<Corotational>(l);
}

} // namespace suite::fem
