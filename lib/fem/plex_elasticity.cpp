// Pointwise elastodynamics residual and Jacobian for PetscFE on a DMPlex (see plex_elasticity.hpp).
#include "fem/plex_elasticity.hpp"

#include <petscds.h>
#include <petscfe.h>

namespace suite::fem {

namespace {

// Constants of the DS: lambda, mu, rho, c, k, g (3).
enum { kLambda, kMu, kRho, kMass, kStiff, kGravity, kNumConstants = kGravity + 3 };

// The PetscDS pointwise signatures (PETSc 3.18), as macros so that each function reads as its formula.
#define SUITE_PLEX_RESIDUAL_ARGS                                                                             \
  PetscInt, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar u[],                   \
      const PetscScalar[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt[],                 \
      const PetscScalar a[], const PetscScalar[], const PetscScalar[], PetscReal, const PetscReal[],         \
      PetscInt, const PetscScalar c[]
#define SUITE_PLEX_JACOBIAN_ARGS                                                                             \
  PetscInt, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar[],                     \
      const PetscScalar[], const PetscScalar u_x[], const PetscInt[], const PetscInt[], const PetscScalar[], \
      const PetscScalar[], const PetscScalar[], PetscReal, PetscReal, const PetscReal[], PetscInt,           \
      const PetscScalar c[]

// Inertia and body force: rho (c u - b) - rho g.
void f0Inertia(SUITE_PLEX_RESIDUAL_ARGS, PetscScalar f0[]) {
  (void)u_x;
  for (int i = 0; i < 3; ++i)
    f0[i] = c[kRho] * (c[kMass] * u[i] - a[aOff[0] + i]) - c[kRho] * c[kGravity + i];
}

void g0Inertia(SUITE_PLEX_JACOBIAN_ARGS, PetscScalar g0[]) {
  (void)u_x;
  for (int i = 0; i < 9; ++i) g0[i] = 0.0;
  for (int i = 0; i < 3; ++i) g0[4 * i] = c[kRho] * c[kMass];
}

// Small-strain stress k sigma(eps(u)).
void f1Linear(SUITE_PLEX_RESIDUAL_ARGS, PetscScalar f1[]) {
  (void)u, (void)aOff, (void)a;
  const PetscScalar tr = u_x[0] + u_x[4] + u_x[8];
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      f1[3 * i + J] =
          c[kStiff] * (c[kMu] * (u_x[3 * i + J] + u_x[3 * J + i]) + (i == J ? c[kLambda] * tr : 0.0));
}

void g3Linear(SUITE_PLEX_JACOBIAN_ARGS, PetscScalar g3[]) {
  (void)u_x;
  for (int m = 0; m < 81; ++m) g3[m] = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      g3[((3 * i + k) * 3 + i) * 3 + k] += c[kStiff] * c[kLambda]; // lambda d_iJ d_kL
      g3[((3 * i + k) * 3 + k) * 3 + i] += c[kStiff] * c[kMu];     // mu d_iL d_Jk
      g3[((3 * i + i) * 3 + k) * 3 + k] += c[kStiff] * c[kMu];     // mu d_ik d_JL
    }
}

// F = I + grad u and the second Piola-Kirchhoff stress S of St. Venant-Kirchhoff.
void stvkState(const PetscScalar* u_x, const PetscScalar* c, PetscScalar F[9], PetscScalar S[9]) {
  for (int m = 0; m < 9; ++m) F[m] = u_x[m] + (m % 4 == 0 ? 1.0 : 0.0);
  PetscScalar E[9];
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J) {
      PetscScalar s = 0.0;
      for (int k = 0; k < 3; ++k) s += F[3 * k + I] * F[3 * k + J];
      E[3 * I + J] = 0.5 * (s - (I == J ? 1.0 : 0.0));
    }
  const PetscScalar tr = E[0] + E[4] + E[8];
  for (int m = 0; m < 9; ++m) S[m] = 2.0 * c[kMu] * E[m] + (m % 4 == 0 ? c[kLambda] * tr : 0.0);
}

// k P = k F S.
void f1Stvk(SUITE_PLEX_RESIDUAL_ARGS, PetscScalar f1[]) {
  (void)u, (void)aOff, (void)a;
  PetscScalar F[9], S[9];
  stvkState(u_x, c, F, S);
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) {
      PetscScalar p = 0.0;
      for (int K = 0; K < 3; ++K) p += F[3 * i + K] * S[3 * K + J];
      f1[3 * i + J] = c[kStiff] * p;
    }
}

// k (d_ik S_JL + lambda F_iJ F_kL + mu (F F^T)_ik d_JL + mu F_iL F_kJ).
void g3Stvk(SUITE_PLEX_JACOBIAN_ARGS, PetscScalar g3[]) {
  PetscScalar F[9], S[9], FFt[9];
  stvkState(u_x, c, F, S);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      FFt[3 * i + k] = 0.0;
      for (int N = 0; N < 3; ++N) FFt[3 * i + k] += F[3 * i + N] * F[3 * k + N];
    }
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int J = 0; J < 3; ++J)
        for (int L = 0; L < 3; ++L) {
          PetscScalar v = c[kLambda] * F[3 * i + J] * F[3 * k + L] + c[kMu] * F[3 * i + L] * F[3 * k + J];
          if (i == k) v += S[3 * J + L];
          if (J == L) v += c[kMu] * FFt[3 * i + k];
          g3[((3 * i + k) * 3 + J) * 3 + L] = c[kStiff] * v;
        }
}

#undef SUITE_PLEX_RESIDUAL_ARGS
#undef SUITE_PLEX_JACOBIAN_ARGS

PetscErrorCode zeroDisplacement(PetscInt, PetscReal, const PetscReal[], PetscInt nc, PetscScalar* u, void*) {
  for (PetscInt i = 0; i < nc; ++i) u[i] = 0.0;
  return 0;
}

PetscErrorCode rigidBodyModes(DM dm, PetscInt field, PetscInt, MatNullSpace* sp) {
  return DMPlexCreateRigidBody(dm, field, sp);
}

// P1 Lagrange, 3 components, quadrature exact for degree 2 (the consistent mass).
PetscErrorCode addDisplacementField(DM dm) {
  PetscFE fe;
  PetscFunctionBeginUser;
  PetscCall(PetscFECreateLagrange(PetscObjectComm((PetscObject)dm), 3, 3, PETSC_TRUE, 1, 2, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, "displacement"));
  PetscCall(DMSetField(dm, 0, nullptr, (PetscObject)fe));
  PetscCall(DMCreateDS(dm));
  PetscCall(PetscFEDestroy(&fe));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode setPlexStepWeights(DM dm, const PlexElasticParams& p, const PlexStepWeights& w) {
  PetscDS ds;
  PetscScalar c[kNumConstants] = {p.lambda,    p.mu,         p.rho,        w.mass,
                                  w.stiffness, p.gravity[0], p.gravity[1], p.gravity[2]};
  PetscFunctionBeginUser;
  PetscCall(DMGetDS(dm, &ds));
  PetscCall(PetscDSSetConstants(ds, kNumConstants, c));
  PetscFunctionReturn(0);
}

PetscErrorCode setupPlexElasticity(DM dm, const PlexElasticParams& p, DM* aux_dm) {
  PetscDS ds;
  DMLabel clamped;
  const PetscInt one = 1;
  PetscFunctionBeginUser;
  PetscCheck(p.law == "linear" || p.law == "stvk", PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG,
             "the distributed (DMPlex) path has the laws linear and stvk, not %s", p.law.c_str());
  PetscCall(DMClone(dm, aux_dm));
  PetscCall(addDisplacementField(*aux_dm));
  PetscCall(addDisplacementField(dm));
  PetscCall(DMGetDS(dm, &ds));
  const bool linear = p.law == "linear";
  PetscCall(PetscDSSetResidual(ds, 0, f0Inertia, linear ? f1Linear : f1Stvk));
  PetscCall(PetscDSSetJacobian(ds, 0, 0, g0Inertia, nullptr, nullptr, linear ? g3Linear : g3Stvk));
  PetscCall(setPlexStepWeights(dm, p, PlexStepWeights{}));
  PetscCall(DMGetLabel(dm, "clamped", &clamped));
  PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "clamped", clamped, 1, &one, 0, 0, nullptr,
                          (void (*)(void))zeroDisplacement, nullptr, nullptr, nullptr));
  PetscCall(DMSetNearNullSpaceConstructor(dm, 0, rigidBodyModes));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
