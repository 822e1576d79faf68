// Newmark on a distributed DMPlex (see plex_newmark.hpp).
#include "fem/plex_newmark.hpp"

#include <cmath>

namespace suite::fem {

PlexNewmark::~PlexNewmark() {
  Vec* vecs[] = {&u_, &v_, &a_, &f_, &b_, &un_, &b_local_};
  for (Vec* v : vecs) VecDestroy(v);
  SNESDestroy(&snes_);
  DMDestroy(&dm_);
}

PetscErrorCode PlexNewmark::setup(DM dm, const PlexElasticParams& p, double tip_load, double beta,
                                  double gamma, double newton_rtol, double newton_atol,
                                  PetscInt newton_max_it) {
  KSP ksp;
  PC pc;
  SNESLineSearch ls;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectReference((PetscObject)dm));
  dm_ = dm, beta_ = beta, gamma_ = gamma;
  PetscCall(el_.setup(dm_, p));
  Vec* vecs[] = {&u_, &v_, &a_, &f_, &b_, &un_};
  for (Vec* v : vecs) {
    PetscCall(DMCreateGlobalVector(dm_, v));
    PetscCall(VecZeroEntries(*v));
  }
  PetscCall(PetscObjectSetName((PetscObject)u_, "displacement"));
  PetscCall(DMCreateLocalVector(dm_, &b_local_));
  PetscCall(VecZeroEntries(b_local_));
  el_.setInertiaVector(b_local_);
  PetscCall(tipLoad(tip_load));
  PetscCall(SNESCreate(PetscObjectComm((PetscObject)dm_), &snes_));
  PetscCall(SNESSetDM(snes_, dm_));
  PetscCall(el_.attach(snes_));
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

// f_ = the consistent nodal loads of a uniform traction of total P along -y on the "tip" faces.
PetscErrorCode PlexNewmark::tipLoad(double P) {
  IS faces = nullptr;
  Vec floc;
  PetscInt n = 0;
  const PetscInt* fs = nullptr;
  double area = 0.0, total = 0.0;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscFunctionBeginUser;
  PetscCall(DMGetStratumIS(dm_, "tip", 1, &faces));
  if (faces) PetscCall(ISGetLocalSize(faces, &n));
  if (faces) PetscCall(ISGetIndices(faces, &fs));
  std::vector<double> areas(n);
  for (PetscInt i = 0; i < n; ++i) {
    PetscReal a, centroid[3], normal[3];
    PetscCall(DMPlexComputeCellGeometryFVM(dm_, fs[i], &a, centroid, normal));
    areas[i] = a, area += a;
  }
  PetscCallMPI(MPI_Allreduce(&area, &total, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscCheck(P == 0.0 || total > 0.0, comm, PETSC_ERR_ARG_WRONG,
             "-tip_load %g: the end plane x = max holds no boundary face", P);
  PetscCall(DMGetLocalVector(dm_, &floc));
  PetscCall(VecZeroEntries(floc));
  for (PetscInt i = 0; i < n && P != 0.0; ++i) {
    const PetscScalar fy = -P * areas[i] / (3.0 * total);
    const PetscScalar vals[9] = {0, fy, 0, 0, fy, 0, 0, fy, 0};
    PetscCall(DMPlexVecSetClosure(dm_, nullptr, floc, fs[i], vals, ADD_VALUES));
  }
  if (faces) PetscCall(ISRestoreIndices(faces, &fs));
  PetscCall(ISDestroy(&faces));
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

PetscErrorCode PlexNewmark::solve(double mass, double stiffness, Vec x, PlexStepStats* st) {
  SNESConvergedReason reason;
  PetscFunctionBeginUser;
  el_.setWeights(PlexStepWeights{mass, stiffness});
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

PetscErrorCode PlexNewmark::initialize() {
  PlexStepStats st;
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(b_));
  PetscCall(setInertia(b_));
  PetscCall(solve(1.0, 0.0, a_, &st)); // rho a - rho g = f_tip
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::step(double dt, PlexStepStats* st) {
  const double c = 1.0 / (beta_ * dt * dt);
  PetscFunctionBeginUser;
  // b = c u_n + v_n / (beta dt) + (1/(2 beta) - 1) a_n
  PetscCall(VecAXPBYPCZ(b_, c, 1.0 / (beta_ * dt), 0.0, u_, v_));
  PetscCall(VecAXPY(b_, 1.0 / (2.0 * beta_) - 1.0, a_));
  PetscCall(setInertia(b_));
  PetscCall(VecCopy(u_, un_));
  PetscCall(VecAXPBYPCZ(u_, dt, 0.5 * dt * dt, 1.0, v_, a_)); // predictor u_n + dt v_n + dt^2/2 a_n
  t_ += dt;
  PetscCall(solve(c, 1.0, u_, st));
  PetscCall(VecAXPY(v_, dt * (1.0 - gamma_), a_));
  PetscCall(VecCopy(b_, a_));
  PetscCall(VecAXPBY(a_, c, -1.0, u_)); // a_{n+1} = c u_{n+1} - b
  PetscCall(VecAXPY(v_, dt * gamma_, a_));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::solveStatic(PlexStepStats* st) {
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(b_));
  PetscCall(setInertia(b_));
  PetscCall(VecZeroEntries(u_));
  PetscCall(solve(0.0, 1.0, u_, st));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::energies(double* kinetic, double* strain) const {
  PetscFunctionBeginUser;
  PetscCall(el_.kineticEnergy(v_, kinetic));
  PetscCall(el_.strainEnergy(strain));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNewmark::planeMean(double x0, int comp, double sign, double* mean) const {
  Vec loc, coords;
  PetscSection ls, gs, cs;
  const PetscScalar *ul, *cx;
  PetscInt v0, v1;
  double local[2] = {0.0, 0.0}, global[2];
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMGlobalToLocal(dm_, u_, INSERT_VALUES, loc));
  PetscCall(DMGetLocalSection(dm_, &ls));
  PetscCall(DMGetGlobalSection(dm_, &gs));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &cs));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &v0, &v1));
  PetscCall(VecGetArrayRead(loc, &ul));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt v = v0; v < v1; ++v) {
    PetscInt goff, off, coff;
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; // owned by another rank
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    if (std::abs(PetscRealPart(cx[coff]) - x0) > 1e-9 * std::max(1.0, std::abs(x0))) continue;
    PetscCall(PetscSectionGetOffset(ls, v, &off));
    local[0] += sign * PetscRealPart(ul[off + comp]), local[1] += 1.0;
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscCall(VecRestoreArrayRead(loc, &ul));
  PetscCall(DMRestoreLocalVector(dm_, &loc));
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  *mean = global[1] > 0 ? global[0] / global[1] : 0.0;
  PetscFunctionReturn(0);
}

} // namespace suite::fem
