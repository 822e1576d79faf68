// Elastodynamics on a DMPlex: the residual and Jacobian of one implicit step, assembled element by element
// over this rank's P1 tetrahedra with the suite's own material laws (material.hpp: linear, StVK, corotational;
// the same laws and element tangents as the replicated path's ElasticModel):
//   R(u) = M (c u - b) + C (c_v u - b_v) + k f_int(c_k u + e) - f_g,   J = c M + c_v C + k c_k K_T(c_k u + e),
// where c, c_v, c_k and the vectors b, b_v, e carry the time integrator (Newmark: c = 1/(beta dt^2),
// b = c u_n + v_n/(beta dt) + (1/(2 beta) - 1) a_n, c_k = 1, e = 0; generalized-alpha and the damping terms:
// plex_newmark.hpp), C = alpha M + beta K_0 is Rayleigh damping (K_0: the linear elastic stiffness with the
// same Lame constants), k switches the stiffness on (1) or off (0: the mass solve of the initial acceleration), M is the consistent P1 mass (rho V (1 + d_ab) / 20 per
// component), f_int the internal force (V P g_a per node, g_a the gradients of the barycentric coordinates),
// f_g the consistent gravity load (rho g V / 4 per node). The DM's PetscSection (a P1 PetscFE field) numbers the
// DOFs; the prescribed displacements (plex_prescribed.hpp: the fixed groups, "clamped" on the beam, rollers and
// driven faces) are essential conditions (removed from the global vectors, written into the local ones at the
// current load factor); the rigid-body modes are the near-null space for algebraic multigrid
// (MatNullSpaceCreateRigidBody, with 3 x 3 blocks; when some vertex has only some components held, the six
// modes on the free DOFs, orthonormalised, and scalar blocks).
// PETSc's pointwise PetscFE assembly was measured at ~1 ms per tetrahedron for this Jacobian (PETSc 3.18,
// 8-point quadrature, the generic element-matrix loop), DMPlexVecGetClosure at ~9 us per cell and
// DMCreateMatrix at 118 s for 132k DOFs: so the geometry and the DOF indices of each cell are computed once
// (prepareCells) and the Jacobian is preallocated from them.
#pragma once

#include "fem/material.hpp"
#include "fem/plex_prescribed.hpp"

#include <petscdmplex.h>
#include <petscsnes.h>

#include <memory>
#include <string>
#include <vector>

namespace suite::fem {

struct PlexElasticParams {
  std::string law = "linear"; // a name of materialChoices()
  Lame lame;
  double rho = 1;
  double gravity[3] = {0, 0, 0};
  double rayleigh_mass = 0, rayleigh_stiffness = 0; // C = alpha M + beta K_0
  std::vector<PlexPrescribed> prescribed;           // supports: components held on groups
};

// Weights of the step's residual.
struct PlexStepWeights {
  double mass = 0;      // c
  double stiffness = 1; // k
  double damping = 0;   // c_v
  double eval = 1;      // c_k
};

class PlexElasticity {
public:
  // The displacement field (P1, 3 components), the supports and the material on dm. Collective.
  PetscErrorCode setup(DM dm, const PlexElasticParams& p);
  // Registers the residual and Jacobian on the DM of snes (DMSNESSetFunctionLocal / JacobianLocal) and gives
  // its Jacobian the rigid-body near-null space.
  PetscErrorCode attach(SNES snes);
  void setWeights(const PlexStepWeights& w) { w_ = w; }
  // The load factor of the prescribed values (their values times this in the local vectors).
  void setPrescribedScale(double s) { scale_ = s; }
  const PlexPrescribedDofs& prescribed() const { return held_; }
  // b as a local vector of the DM (owned by the caller; clamped entries 0).
  void setInertiaVector(Vec b_local) { b_ = b_local; }
  // b_v and e as local vectors (owned by the caller; null: none).
  void setDampingVector(Vec bv_local) { bv_ = bv_local; }
  void setEvalOffset(Vec e_local) { e_ = e_local; }
  // Strain energy of the last residual evaluation, summed over the ranks (collective).
  PetscErrorCode strainEnergy(double* e) const;
  // Strain energy at the global vector u with u_held on the prescribed DOFs (collective; generalized-alpha
  // evaluates its residuals at another point).
  PetscErrorCode strainEnergyAt(Vec u, const std::vector<double>& u_held, double* e) const;
  // The von Mises stress sqrt(3/2 s:s) of the Cauchy stress sigma = P F^T / det F (the linear law: sigma = P)
  // of each local cell at u with u_held on the prescribed DOFs.
  PetscErrorCode vonMises(Vec u, const std::vector<double>& u_held, std::vector<double>* vm) const;
  // Kinetic energy v^T M v / 2 of a global vector v with v_held on the prescribed DOFs (null: 0; consistent
  // mass, element by element; collective).
  PetscErrorCode kineticEnergy(Vec v, const std::vector<double>* v_held, double* e) const;

private:
  // Per local cell: the volume and barycentric gradients (total Lagrangian: fixed), the local-vector offsets
  // and the global indices (-1: fixed) of its 12 DOFs, from the DM's sections. Collective (errors naming a
  // degenerate tetrahedron).
  PetscErrorCode prepareCells();
  // The Jacobian with its nonzero pattern preallocated from the cells' global indices (MATPREALLOCATOR).
  PetscErrorCode createJacobian(Mat* J) const;
  PetscErrorCode rigidBodyModes(MatNullSpace* sp) const;
  PetscErrorCode partialRigidBodyModes(MatNullSpace* sp) const;
  static PetscErrorCode residualLocal(DM dm, Vec x, Vec f, void* ctx);
  static PetscErrorCode jacobianLocal(DM dm, Vec x, Mat J, Mat P, void* ctx);
  PetscErrorCode residual(DM dm, Vec x, Vec f);
  PetscErrorCode jacobian(DM dm, Vec x, Mat J);

  DM dm_ = nullptr; // not owned
  SNES snes_ = nullptr;
  PlexElasticParams p_;
  std::unique_ptr<Material> material_, linear_; // linear_: K_0 of the damping
  PlexStepWeights w_;
  Vec b_ = nullptr, bv_ = nullptr, e_ = nullptr;
  double energy_ = 0, scale_ = 1;
  PlexPrescribedDofs held_;
  std::vector<double> vol_, grad_;   // [cell], [12 cell + 3 a + j]
  std::vector<PetscInt> loc_, glob_; // [12 cell + 3 a + i]
};

} // namespace suite::fem
