// Newmark time stepping (Newmark 1959; average acceleration beta = 1/4, gamma = 1/2 by default) of
// M a + f_int(u) = f_ext on a distributed DMPlex (plex_elasticity.hpp): the state u, v, a and every work vector
// are distributed Vecs of the DM's global section; each step solves R(u_{n+1}) = f_tip with SNES (Newton; the
// inertia M (c u - b) of plex_elasticity.hpp with c = 1/(beta dt^2)), then
//   a_{n+1} = c (u_{n+1} - u_n) - v_n / (beta dt) - (1/(2 beta) - 1) a_n,
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}),
// the same equations as fem::Newmark (newmark.hpp) on the replicated path (R: plex_elasticity.hpp). The initial acceleration solves
// M a_0 = f_ext - f_int(u_0) (u_0 = 0). Linear solves: KSP (default CG + GAMG with the rigid-body near-null
// space, relative tolerance 1e-10; -ksp_type, -pc_type, -snes_* as usual). Surface loads on groups
// (plex_groups.hpp): a dead traction t per area, or a total force F spread uniformly over the group's area
// (t = F / area: -tip_load); consistent nodal loads t area / 3 per vertex of each face, as beam_loads.hpp.
#pragma once

#include "fem/plex_elasticity.hpp"

#include <petscsnes.h>

namespace suite::fem {

struct PlexSurfaceLoad {
  PlexGroup group; // a surface
  double value[3] = {0, 0, 0};
  bool total = false; // value: the total force over the group (else a traction, force per area)
};

struct PlexStepStats {
  PetscInt newton_iterations = 0, linear_iterations = 0;
  double residual = 0;
};

class PlexNewmark {
public:
  PlexNewmark() = default;
  PlexNewmark(const PlexNewmark&) = delete;
  PlexNewmark& operator=(const PlexNewmark&) = delete;
  ~PlexNewmark();

  // Sets up the field, the supports (p.fixed) and the loads on dm, and the SNES. Collective.
  PetscErrorCode setup(DM dm, const PlexElasticParams& p, const std::vector<PlexSurfaceLoad>& loads,
                       double beta, double gamma, double newton_rtol, double newton_atol,
                       PetscInt newton_max_it);
  // a_0 from M a_0 = f_ext (u = v = 0).
  PetscErrorCode initialize();
  // One step of dt. Errors (step time and SNES reason) when Newton diverges.
  PetscErrorCode step(double dt, PlexStepStats* st);
  // Static equilibrium f_int(u) = f_ext (one load step).
  PetscErrorCode solveStatic(PlexStepStats* st);
  // Mean of component comp (times sign) of u over the vertices of a group's faces (each counted once).
  PetscErrorCode groupMean(const PlexGroup& g, int comp, double sign, double* mean) const;
  // Kinetic energy of v and strain energy at u (the last residual evaluation: the step's converged iterate).
  PetscErrorCode energies(double* kinetic, double* strain) const;
  Vec displacement() const { return u_; }
  Vec velocity() const { return v_; }
  Vec acceleration() const { return a_; }
  double time() const { return t_; }
  // After a restart has filled u, v, a: the time of that state.
  void setTime(double t) { t_ = t; }

private:
  PetscErrorCode surfaceLoads(const std::vector<PlexSurfaceLoad>& loads);
  PetscErrorCode setInertia(Vec b_global);
  PetscErrorCode solve(double mass, double stiffness, Vec x, PlexStepStats* st);

  DM dm_ = nullptr;
  PlexElasticity el_;
  SNES snes_ = nullptr;
  Vec u_ = nullptr, v_ = nullptr, a_ = nullptr, f_ = nullptr, b_ = nullptr, un_ = nullptr;
  Vec b_local_ = nullptr; // b as a local vector (with the clamped DOFs, 0)
  double beta_ = 0.25, gamma_ = 0.5, t_ = 0;
};

} // namespace suite::fem
