// Elastodynamics on a DMPlex with PetscFE (P1 tetrahedra, 3 components): the pointwise residual and Jacobian
// of one implicit step
//   R(u) = rho (c u - b) + k P(grad u) : grad w - rho g,
// where c and the auxiliary field b carry the inertia of the time integrator (Newmark: c = 1/(beta dt^2),
// b = c u_n + v_n/(beta dt) + (1/(2 beta) - 1) a_n; plex_newmark.hpp), k switches the stiffness on (1) or off
// (0: the mass solve of the initial acceleration), P is the first Piola-Kirchhoff stress of the law: linear
// (small strain, sigma = lambda tr(eps) I + 2 mu eps) or St. Venant-Kirchhoff (P = F S, S = lambda tr(E) I +
// 2 mu E, E = (F^T F - I)/2; tangent A_iJkL = d_ik S_JL + lambda F_iJ F_kL + mu (F F^T)_ik d_JL + mu F_iL F_kJ,
// the closed form of material.hpp). The same laws and consistent mass as the replicated path (ElasticModel),
// integrated exactly (quadrature of degree 2: the P1 mass; strains are constant per tet). Displacements on
// the "clamped" label are zero (essential condition, removed from the global vectors); the rigid-body modes
// are the near-null space of the operator for algebraic multigrid (DMPlexCreateRigidBody).
#pragma once

#include <petscdmplex.h>

#include <string>

namespace suite::fem {

struct PlexElasticParams {
  std::string law = "linear"; // "linear" or "stvk"
  double lambda = 0, mu = 0, rho = 1;
  double gravity[3] = {0, 0, 0};
};

// Constants of the residual that change during a run.
struct PlexStepWeights {
  double mass = 0;      // c
  double stiffness = 1; // k
};

// Sets the displacement field, its DS (residual, Jacobian, constants), the clamp and the near-null space on
// dm, and an auxiliary DM (same discretisation, no constraint) for b in *aux_dm. Collective.
PetscErrorCode setupPlexElasticity(DM dm, const PlexElasticParams& p, DM* aux_dm);
// Updates the constants c and k of the DS of dm.
PetscErrorCode setPlexStepWeights(DM dm, const PlexElasticParams& p, const PlexStepWeights& w);

} // namespace suite::fem
