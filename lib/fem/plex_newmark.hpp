// Newmark time stepping (Newmark 1959; average acceleration beta = 1/4, gamma = 1/2 by default) and
// generalized-alpha (Chung & Hulbert 1993, J. Appl. Mech. 60:371) of M a + C v + f_int(u) = f_ext on a
// distributed DMPlex (plex_elasticity.hpp), C = alpha M + beta K_0 (Rayleigh). The state u, v, a and every
// work vector are distributed Vecs of the DM's global section; each step solves R(u_{n+1}) = f_ext with SNES
// (Newton; R: plex_elasticity.hpp, with c = (1 - alpha_m)/(beta dt^2), c_v = (1 - alpha_f) gamma/(beta dt),
// c_k = 1 - alpha_f and the vectors of stepVectors()), then
//   a_{n+1} = c (u_{n+1} - u_n) - v_n / (beta dt) - (1/(2 beta) - 1) a_n   (c = 1/(beta dt^2)),
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}),
// the same equations as fem::Newmark (newmark.hpp) on the replicated path. The prescribed DOFs
// (plex_prescribed.hpp) follow g(t) = r(t) g_1 (r: a linear ramp over -bc_ramp, or 1 from the first step on)
// with the same recursion, so that their inertia and damping enter the free rows consistently. The initial
// acceleration solves M a_0 = f_ext - f_int(u_0) (u_0 = 0, v_0 = 0). Linear solves: KSP (default CG + GAMG
// with the rigid-body near-null space, relative tolerance 1e-10; -ksp_type, -pc_type, -snes_* as usual).
// Surface loads on groups (plex_groups.hpp): a dead traction t per area, or a total force F spread uniformly
// over the group's area (t = F / area: -tip_load); consistent nodal loads t area / 3 per vertex of each face,
// as beam_loads.hpp.
#pragma once

#include "fem/plex_elasticity.hpp"

#include <petscsnes.h>

#include <algorithm>
#include <vector>

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
  // Generalized-alpha (Chung & Hulbert 1993; fem::generalizedAlpha sets beta and gamma with them): the
  // equilibrium at t_{n+1-alpha_f} with the inertia at a_{n+1-alpha_m}, as fem::Newmark. 0, 0: Newmark.
  void setGeneralizedAlpha(double alpha_m, double alpha_f) { am_ = alpha_m, af_ = alpha_f; }
  // The time over which the prescribed values grow linearly from 0 (0: at full value from the first step).
  void setPrescribedRamp(double t) { ramp_ = t; }
  // One step of dt. Errors (step time and SNES reason) when Newton diverges.
  PetscErrorCode step(double dt, PlexStepStats* st);
  // Static equilibrium f_int(u) = f_ext (one load step).
  PetscErrorCode solveStatic(PlexStepStats* st);
  // Mean of component comp (times sign) of u over the vertices of a group's faces (each counted once).
  PetscErrorCode groupMean(const PlexGroup& g, int comp, double sign, double* mean) const;
  // Kinetic energy of v and strain energy at u (the last residual evaluation: the step's converged iterate).
  PetscErrorCode energies(double* kinetic, double* strain) const;
  Vec displacement() const { return u_; }
  const PlexPrescribedDofs& prescribed() const { return el_.prescribed(); }
  // The prescribed DOFs' current displacements (in the order of prescribed()).
  const std::vector<double>& heldDisplacement() const { return hu_; }
  // The von Mises stress of each local cell at the current displacement (PlexElasticity::vonMises).
  PetscErrorCode vonMises(std::vector<double>* vm) const { return el_.vonMises(u_, hu_, vm); }
  Vec velocity() const { return v_; }
  Vec acceleration() const { return a_; }
  double time() const { return t_; }
  // After a restart has filled u, v, a: the time of that state.
  void setTime(double t) { t_ = t; }

private:
  PetscErrorCode surfaceLoads(const std::vector<PlexSurfaceLoad>& loads);
  PetscErrorCode setInertia(Vec b_global);
  PetscErrorCode solve(const PlexStepWeights& w, Vec x, PlexStepStats* st);
  // The step's vectors b_m (inertia), b_v (damping) and e (evaluation offset), global and local, with their
  // prescribed-DOF entries from the held recursion; hb: the plain Newmark b at the prescribed DOFs.
  PetscErrorCode stepVectors(double dt, const std::vector<double>& hb);

  DM dm_ = nullptr;
  PlexElasticity el_;
  SNES snes_ = nullptr;
  Vec u_ = nullptr, v_ = nullptr, a_ = nullptr, f_ = nullptr, b_ = nullptr, un_ = nullptr;
  Vec b_local_ = nullptr; // b (generalized-alpha: b_m) as a local vector (with the clamped DOFs, 0)
  Vec w_ = nullptr, bv_local_ = nullptr, e_local_ = nullptr; // a work vector; b_v and e as local vectors
  double am_ = 0, af_ = 0;
  bool damped_ = false;
  double beta_ = 0.25, gamma_ = 0.5, t_ = 0, ramp_ = 0;
  std::vector<double> hu_, hv_, ha_; // the prescribed DOFs' displacement, velocity, acceleration
  double rampAt(double t) const { return t <= 0 ? 0.0 : ramp_ > 0 ? std::min(t / ramp_, 1.0) : 1.0; }
  // The plain Newmark b at the prescribed DOFs: c u + v / (beta dt) + (1/(2 beta) - 1) a of their recursion.
  void heldInertia(double c, double dt, std::vector<double>* hb) const;
  // local[offset_i] = values_i at the prescribed DOFs.
  PetscErrorCode setHeldEntries(Vec local, const std::vector<double>& values) const;
};

} // namespace suite::fem
