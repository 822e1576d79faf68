// Hyperelastic material interface (total-Lagrangian: first Piola-Kirchhoff stress P(F) and its derivative
// A = dP/dF) and the registry of materials by name (one file each: linear, stvk, corotational).
#pragma once

#include "core/named_choice.hpp"

#include <petscsys.h>

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace suite::fem {

using Mat3 = Eigen::Matrix3d;
using Tangent = Eigen::Matrix<double, 9, 9>; // A(3*i+J, 3*k+L) = dP_iJ / dF_kL

struct Lame {
  double lambda = 0, mu = 0;
};
// Errors (naming the options) unless E > 0 and -1 < nu < 0.5.
PetscErrorCode lameFromYoung(MPI_Comm comm, double E, double nu, Lame* lame);

class Material {
public:
  explicit Material(Lame l) : lame_(l) {}
  virtual ~Material() = default;
  virtual const char* name() const = 0;
  // Strain energy density W, stress P and (if A != nullptr) the tangent at F.
  virtual void evaluate(const Mat3& F, double* W, Mat3* P, Tangent* A) const = 0;
  // Adds w * K_ab(i,k) = w sum_JL g_aJ A_iJkL g_bL to the upper triangle (p <= q, p = 3a+i, q = 3b+k) of the
  // element matrix ke (nd x nd, nd = 3 nen); g: nen x 3 physical gradients. The default goes through A;
  // linear and StVK override it with closed forms (no 9x9 tangent).
  virtual void addElementTangent(const Mat3& F, const double* g, int nen, double w, double* ke) const;
  // evaluate(F, W, P) and addElementTangent in one call (overridden where they share work, e.g. StVK's S).
  virtual void evaluateWithTangent(const Mat3& F, const double* g, int nen, double w, double* W, Mat3* P,
                                   double* ke) const {
    evaluate(F, W, P, nullptr);
    addElementTangent(F, g, nen, w, ke);
  }
  // True when the tangent is constant (linear): the stiffness need not be reassembled.
  virtual bool isLinear() const { return false; }
  const Lame& lame() const { return lame_; }

protected:
  Lame lame_;
};

std::unique_ptr<Material> makeLinearMaterial(Lame l);
std::unique_ptr<Material> makeStVenantKirchhoff(Lame l);
std::unique_ptr<Material> makeCorotational(Lame l);

// Registry: names and factory. Errors with the list of valid names on an unknown name.
std::vector<std::string> materialNames();
std::vector<suite::Choice> materialChoices(); // with each material's one-line help (-help lists them)
PetscErrorCode createMaterial(MPI_Comm comm, const std::string& name, Lame l, std::unique_ptr<Material>* out);

// Closed-form element tangent of StVK-like laws: K_ab(i,k) = d_ik g_a.S g_b + lambda (F g_a)_i (F g_b)_k
//   + mu (F F^T)_ik g_a.g_b + mu (F g_b)_i (F g_a)_k (S = 0, F = I gives small-strain linear elasticity).
void addStVKElementTangent(const Mat3& F, const Mat3& S, Lame l, const double* g, int nen, double w,
                           double* ke);

// Small-strain isotropic tangent C_iJkL = lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk) in the 9x9 layout.
Tangent isotropicTangent(Lame l);

} // namespace suite::fem
