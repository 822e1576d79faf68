// Material registry and Lame parameters: lambda = E nu / ((1+nu)(1-2nu)), mu = E / (2(1+nu)).
#include "fem/material.hpp"

namespace suite::fem {

PetscErrorCode lameFromYoung(MPI_Comm comm, double E, double nu, Lame* lame) {
  PetscFunctionBeginUser;
  PetscCheck(E > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Young's modulus -young %g must be > 0", E);
  PetscCheck(nu > -1.0 && nu < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Poisson ratio -poisson %g must satisfy -1 < nu < 0.5 (nu >= 0.5 is incompressible)", nu);
  lame->lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  lame->mu = E / (2 * (1 + nu));
  PetscFunctionReturn(0);
}

Tangent isotropicTangent(Lame l) {
  Tangent C = Tangent::Zero();
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          C(3 * i + J, 3 * k + L) =
              l.lambda * (i == J) * (k == L) + l.mu * ((i == k) * (J == L) + (i == L) * (J == k));
  return C;
}

void Material::addElementTangent(const Mat3& F, const double* g, int nen, double w, double* ke) const {
  Tangent A;
  Mat3 P;
  double W;
  evaluate(F, &W, &P, &A);
  const int nd = 3 * nen;
  Eigen::Matrix<double, 9, 30> AG; // AG(iJ, (b,k)) = sum_L A(iJ, kL) g_bL
  for (int b = 0; b < nen; ++b)
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 9; ++r)
        AG(r, 3 * b + k) =
            A(r, 3 * k) * g[3 * b] + A(r, 3 * k + 1) * g[3 * b + 1] + A(r, 3 * k + 2) * g[3 * b + 2];
  for (int a = 0; a < nen; ++a)
    for (int i = 0; i < 3; ++i) {
      const int p = 3 * a + i;
      for (int q = p; q < nd; ++q)
        ke[p * nd + q] +=
            w * (g[3 * a] * AG(3 * i, q) + g[3 * a + 1] * AG(3 * i + 1, q) + g[3 * a + 2] * AG(3 * i + 2, q));
    }
}

void addStVKElementTangent(const Mat3& F, const Mat3& S, Lame l, const double* g, int nen, double w,
                           double* ke) {
  const int nd = 3 * nen;
  double Fg[10][3], Sg[10][3];
  for (int a = 0; a < nen; ++a)
    for (int i = 0; i < 3; ++i) {
      Fg[a][i] = F(i, 0) * g[3 * a] + F(i, 1) * g[3 * a + 1] + F(i, 2) * g[3 * a + 2];
      Sg[a][i] = S(i, 0) * g[3 * a] + S(i, 1) * g[3 * a + 1] + S(i, 2) * g[3 * a + 2];
    }
  const Mat3 B = F * F.transpose();
  const double lam = w * l.lambda, mu = w * l.mu;
  for (int a = 0; a < nen; ++a) {
    const double* ga = g + 3 * a;
    for (int b = a; b < nen; ++b) {
      const double* gb = g + 3 * b;
      const double gg = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
      const double gsg = w * (ga[0] * Sg[b][0] + ga[1] * Sg[b][1] + ga[2] * Sg[b][2]);
      for (int i = 0; i < 3; ++i)
        for (int k = (a == b ? i : 0); k < 3; ++k)
          ke[(3 * a + i) * nd + 3 * b + k] +=
              (i == k ? gsg : 0.0) + lam * Fg[a][i] * Fg[b][k] + mu * B(i, k) * gg + mu * Fg[b][i] * Fg[a][k];
    }
  }
}

namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Material> (*make)(Lame);
  const char* description; // one line, printed by -help under -material
};
const Entry kMaterials[] = {
    {"linear", makeLinearMaterial, "small-strain linear elasticity (constant tangent)"},
    {"stvk", makeStVenantKirchhoff, "St. Venant-Kirchhoff: Green-Lagrange strain, large rotations"},
    {"corotational", makeCorotational, "corotational linear elasticity (polar rotation per element)"},
};
} // namespace

std::vector<std::string> materialNames() {
  std::vector<std::string> n;
  for (const auto& e : kMaterials) n.emplace_back(e.name);
  return n;
}

std::vector<suite::Choice> materialChoices() {
  return suite::choicesOf(kMaterials);
}

PetscErrorCode createMaterial(MPI_Comm comm, const std::string& name, Lame l,
                              std::unique_ptr<Material>* out) {
  PetscFunctionBeginUser;
  PetscCall(suite::checkChoice(comm, "-material", name, materialChoices()));
  for (const auto& e : kMaterials)
    if (name == e.name) *out = e.make(l);
  PetscFunctionReturn(0);
}

} // namespace suite::fem
