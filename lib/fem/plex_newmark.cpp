// Newmark on a distributed DMPlex (see plex_newmark.hpp).
#include "fem/plex_newmark.hpp"

#include <cmath>
#include <vector>

namespace suite::fem {

PlexNewmark::~PlexNewmark() {
  Vec* vecs[] = {&u_, &v_, &a_, &f_, &b_, &un_, &b_local_, &w_, &bv_local_, &e_local_};
  for (Vec* v : vecs) VecDestroy(v);
  SNESDestroy(&snes_);
  DMDestroy(&dm_);
}

PetscErrorCode PlexNewmark::setup(DM dm, const PlexElasticParams& p,
                                  const std::vector<PlexSurfaceLoad>& loads, double beta, double gamma,
                                  double newton_rtol, double newton_atol, PetscInt newton_max_it) {
  KSP ksp;
  PC pc;
  SNESLineSearch ls;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectReference((PetscObject)dm));
  dm_ = dm, beta_ = beta, gamma_ = gamma;
  PetscCall(el_.setup(dm_, p));
  Vec* vecs[] = {&u_, &v_, &a_, &f_, &b_, &un_, &w_};
  for (Vec* v : vecs) {
    PetscCall(DMCreateGlobalVector(dm_, v));
    PetscCall(VecZeroEntries(*v));
  }
  PetscCall(PetscObjectSetName((PetscObject)u_, "displacement"));
  PetscCall(DMCreateLocalVector(dm_, &b_local_));
  PetscCall(VecZeroEntries(b_local_));
  el_.setInertiaVector(b_local_);
  damped_ = p.rayleigh_mass != 0.0 || p.rayleigh_stiffness != 0.0;
  if (damped_) {
    PetscCall(DMCreateLocalVector(dm_, &bv_local_));
    PetscCall(VecZeroEntries(bv_local_));
    el_.setDampingVector(bv_local_);
  }
  PetscCall(surfaceLoads(loads));
  PetscCall(SNESCreate(PetscObjectComm((PetscObject)dm_), &snes_));
  PetscCall(SNESSetDM(snes_, dm_));
  PetscCall(el_.attach(snes_));
  hu_.assign(el_.prescribed().size(), 0.0), hv_ = hu_, ha_ = hu_;
  PetscCall(SNESSetTolerances(snes_, newton_atol, newton_rtol, 0.0, newton_max_it, PETSC_DEFAULT));
  PetscCall(SNESGetLineSearch(snes_, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBASIC)); // full Newton steps, as fem::Newmark
  PetscCall(SNESGetKSP(snes_, &ksp));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  // Plain aggregation: with smoothed aggregation (GAMG's default) CG stopped on an indefinite preconditioner on
  // beams of elements of aspect ratio 4 (132k and 1M DOFs: the smoothed-aggregation eigenvalue estimate of the
  // Chebyshev smoothers is too low); plain aggregation converged there in 42 CG iterations per Newton step,
  // -pc_gamg_use_sa_esteig false in 51 (-pc_gamg_agg_nsmooths 1 restores the default).
  PetscCall(PCGAMGSetNSmooths(pc, 0));
  PetscCall(KSPSetTolerances(ksp, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(SNESSetFromOptions(snes_));
  PetscFunctionReturn(0);
}

// f_ = the consistent nodal loads of the surface loads.
PetscErrorCode PlexNewmark::surfaceLoads(const std::vector<PlexSurfaceLoad>& loads) {
  Vec floc;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &floc));
  PetscCall(VecZeroEntries(floc));
  for (const PlexSurfaceLoad& l : loads) {
    std::vector<PetscInt> faces;
    PetscCall(groupFaces(dm_, l.group, &faces));
    std::vector<double> areas(faces.size());
    double area = 0.0, total = 0.0;
    for (size_t i = 0; i < faces.size(); ++i) {
      PetscReal a, centroid[3], normal[3];
      PetscCall(DMPlexComputeCellGeometryFVM(dm_, faces[i], &a, centroid, normal));
      areas[i] = a, area += a;
    }
    PetscCallMPI(MPI_Allreduce(&area, &total, 1, MPI_DOUBLE, MPI_SUM, comm));
    PetscCheck(total > 0.0, comm, PETSC_ERR_ARG_WRONG, "the load on group %s: the group has no area",
               l.group.name.c_str());
    for (size_t i = 0; i < faces.size(); ++i) {
      const double per = l.total ? 3.0 * total : 3.0; // a third of the face's share to each vertex
      PetscScalar vals[9];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) vals[3 * a + c] = l.value[c] * areas[i] / per;
      PetscCall(DMPlexVecSetClosure(dm_, nullptr, floc, faces[i], vals, ADD_VALUES));
    }
  }
  PetscCall(VecZeroEntries(f_));
  PetscCall(DMLocalToGlobal(dm_, floc, ADD_VALUES, f_));
  PetscCall(DMRestoreLocalVector(dm_, &floc));
  PetscFunctionReturn(0);
}

// The inertia vector b (plex_elasticity.hpp) from a global vector.
PetscErrorCode PlexNewmark::setInertia(Vec b_global) {
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(b_local_)); // the clamped DOFs: b = 0 there
  PetscCall(DMGlobalToLocal(dm_, b_global, INSERT_VALUES, b_local_));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::solve(const PlexStepWeights& w, Vec x, PlexStepStats* st) {
  SNESConvergedReason reason;
  PetscFunctionBeginUser;
  el_.setWeights(w);
  PetscCall(SNESSolve(snes_, f_, x));
  PetscCall(SNESGetConvergedReason(snes_, &reason));
  PetscCheck(
      reason > 0, PetscObjectComm((PetscObject)dm_), PETSC_ERR_NOT_CONVERGED,
      "step to time %g: Newton (SNES) did not converge: %s (-snes_converged_reason, -ksp_converged_reason "
      "for details)",
      t_, SNESConvergedReasons[reason]);
  PetscCall(SNESGetIterationNumber(snes_, &st->newton_iterations));
  PetscCall(SNESGetLinearSolveIterations(snes_, &st->linear_iterations));
  PetscReal r;
  PetscCall(SNESGetFunctionNorm(snes_, &r));
  st->residual = r;
  PetscFunctionReturn(0);
}

void PlexNewmark::heldInertia(double c, double dt, std::vector<double>* hb) const {
  hb->resize(hu_.size());
  for (size_t i = 0; i < hu_.size(); ++i)
    (*hb)[i] = c * hu_[i] + hv_[i] / (beta_ * dt) + (1.0 / (2.0 * beta_) - 1.0) * ha_[i];
}

PetscErrorCode PlexNewmark::setHeldEntries(Vec local, const std::vector<double>& values) const {
  PetscScalar* x;
  const auto& off = el_.prescribed().offsets();
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local, &x));
  for (size_t i = 0; i < values.size(); ++i) x[off[i]] = values[i];
  PetscCall(VecRestoreArray(local, &x));
  PetscFunctionReturn(0);
}

// With b = c u_n + v_n / (beta dt) + (1/(2 beta) - 1) a_n (a_{n+1} = c u_{n+1} - b):
//   b_m = (1 - alpha_m) b - alpha_m a_n                          (M a_{n+1-alpha_m} = M ((1 - alpha_m) c u - b_m)),
//   b_v = -((1 - alpha_f)(v_n + dt (1 - gamma) a_n - dt gamma b) + alpha_f v_n)
//                                           (v_{n+1-alpha_f} = (1 - alpha_f) gamma / (beta dt) u - b_v),
//   e = alpha_f u_n                                              (u_{n+1-alpha_f} = (1 - alpha_f) u + e).
PetscErrorCode PlexNewmark::stepVectors(double dt, const std::vector<double>& hb) {
  const bool alpha = am_ != 0.0 || af_ != 0.0;
  const size_t nh = hu_.size();
  std::vector<double> h(nh);
  PetscFunctionBeginUser;
  if (alpha) {
    PetscCall(VecAXPBYPCZ(w_, 1.0 - am_, -am_, 0.0, b_, a_));
    PetscCall(setInertia(w_));
    for (size_t i = 0; i < nh; ++i) h[i] = (1.0 - am_) * hb[i] - am_ * ha_[i];
  } else {
    PetscCall(setInertia(b_));
    h = hb;
  }
  PetscCall(setHeldEntries(b_local_, h));
  if (damped_) {
    const double s = 1.0 - af_;
    PetscCall(VecAXPBYPCZ(w_, -s - af_, -s * dt * (1.0 - gamma_), 0.0, v_, a_));
    PetscCall(VecAXPY(w_, s * dt * gamma_, b_));
    PetscCall(VecZeroEntries(bv_local_));
    PetscCall(DMGlobalToLocal(dm_, w_, INSERT_VALUES, bv_local_));
    for (size_t i = 0; i < nh; ++i)
      h[i] = -(s * (hv_[i] + dt * (1.0 - gamma_) * ha_[i] - dt * gamma_ * hb[i]) + af_ * hv_[i]);
    PetscCall(setHeldEntries(bv_local_, h));
  }
  if (alpha) {
    if (!e_local_) PetscCall(DMCreateLocalVector(dm_, &e_local_));
    PetscCall(VecZeroEntries(e_local_));
    PetscCall(VecCopy(u_, w_));
    PetscCall(VecScale(w_, af_));
    PetscCall(DMGlobalToLocal(dm_, w_, INSERT_VALUES, e_local_));
    for (size_t i = 0; i < nh; ++i) h[i] = af_ * hu_[i];
    PetscCall(setHeldEntries(e_local_, h));
    el_.setEvalOffset(e_local_);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::initialize() {
  PlexStepStats st;
  PetscFunctionBeginUser;
  el_.setPrescribedScale(rampAt(0.0)); // 0: the prescribed DOFs start at rest at 0
  PetscCall(VecZeroEntries(b_));
  PetscCall(setInertia(b_));
  PetscCall(solve(PlexStepWeights{1.0, 0.0, 0.0, 1.0}, a_, &st)); // rho a - rho g = f_tip
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::step(double dt, PlexStepStats* st) {
  const double c = 1.0 / (beta_ * dt * dt);
  PetscFunctionBeginUser;
  // b = c u_n + v_n / (beta dt) + (1/(2 beta) - 1) a_n
  PetscCall(VecAXPBYPCZ(b_, c, 1.0 / (beta_ * dt), 0.0, u_, v_));
  PetscCall(VecAXPY(b_, 1.0 / (2.0 * beta_) - 1.0, a_));
  std::vector<double> hb;
  heldInertia(c, dt, &hb);
  PetscCall(stepVectors(dt, hb));
  PetscCall(VecCopy(u_, un_));
  PetscCall(VecAXPBYPCZ(u_, dt, 0.5 * dt * dt, 1.0, v_, a_)); // predictor u_n + dt v_n + dt^2/2 a_n
  t_ += dt;
  const double r = rampAt(t_);
  el_.setPrescribedScale(r);
  PlexStepWeights w{(1.0 - am_) * c, 1.0, 0.0, 1.0 - af_};
  if (damped_) w.damping = (1.0 - af_) * gamma_ / (beta_ * dt);
  PetscCall(solve(w, u_, st));
  const auto& g1 = el_.prescribed().values();
  for (size_t i = 0; i < hu_.size(); ++i) { // the same recursion as the free DOFs below
    const double g = r * g1[i], a = c * g - hb[i];
    hv_[i] += dt * ((1.0 - gamma_) * ha_[i] + gamma_ * a);
    hu_[i] = g, ha_[i] = a;
  }
  PetscCall(VecAXPY(v_, dt * (1.0 - gamma_), a_));
  PetscCall(VecCopy(b_, a_));
  PetscCall(VecAXPBY(a_, c, -1.0, u_)); // a_{n+1} = c u_{n+1} - b
  PetscCall(VecAXPY(v_, dt * gamma_, a_));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::solveStatic(PlexStepStats* st) {
  PetscFunctionBeginUser;
  el_.setPrescribedScale(1.0);
  hu_ = el_.prescribed().values();
  PetscCall(VecZeroEntries(b_));
  PetscCall(setInertia(b_));
  PetscCall(VecZeroEntries(u_));
  el_.setEvalOffset(nullptr);
  PetscCall(solve(PlexStepWeights{0.0, 1.0, 0.0, 1.0}, u_, st));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::energies(double* kinetic, double* strain) const {
  PetscFunctionBeginUser;
  PetscCall(el_.kineticEnergy(v_, &hv_, kinetic));
  if (am_ != 0.0 || af_ != 0.0)
    PetscCall(el_.strainEnergyAt(u_, hu_, strain)); // the residuals were at t_{n+1-alpha_f}
  else
    PetscCall(el_.strainEnergy(strain));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::groupMean(const PlexGroup& g, int comp, double sign, double* mean) const {
  Vec loc;
  PetscSection ls, gs;
  const PetscScalar* ul;
  PetscInt v0, v1;
  std::vector<PetscInt> faces;
  double local[2] = {0.0, 0.0}, global[2];
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &v0, &v1));
  std::vector<char> on((size_t)(v1 - v0), 0);
  PetscCall(groupFaces(dm_, g, &faces));
  for (PetscInt f : faces) {
    PetscInt n = 0, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm_, f, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < 2 * n; i += 2)
      if (pts[i] >= v0 && pts[i] < v1) on[(size_t)(pts[i] - v0)] = 1;
    PetscCall(DMPlexRestoreTransitiveClosure(dm_, f, PETSC_TRUE, &n, &pts));
  }
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMGlobalToLocal(dm_, u_, INSERT_VALUES, loc));
  {
    PetscScalar* w;
    const auto& off = el_.prescribed().offsets();
    PetscCall(VecGetArray(loc, &w));
    for (size_t i = 0; i < hu_.size(); ++i) w[off[i]] = hu_[i];
    PetscCall(VecRestoreArray(loc, &w));
  }
  PetscCall(DMGetLocalSection(dm_, &ls));
  PetscCall(DMGetGlobalSection(dm_, &gs));
  PetscCall(VecGetArrayRead(loc, &ul));
  for (PetscInt v = v0; v < v1; ++v) {
    PetscInt goff, off;
    if (!on[(size_t)(v - v0)]) continue;
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; // owned by another rank
    PetscCall(PetscSectionGetOffset(ls, v, &off));
    local[0] += sign * PetscRealPart(ul[off + comp]), local[1] += 1.0;
  }
  PetscCall(VecRestoreArrayRead(loc, &ul));
  PetscCall(DMRestoreLocalVector(dm_, &loc));
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  *mean = global[1] > 0 ? global[0] / global[1] : 0.0;
  PetscFunctionReturn(0);
}

} // namespace suite::fem
