// Time stepper and helpers shared by the 1D and 2D/3D Euler runs (see euler_stepper.hpp).
#include "euler_stepper.hpp"

#include "core/log.hpp"

#include <ctime>

namespace euler_app {

const char* const kTimeSchemes = "ssprk3, rk4, beuler, cn, bdf2";

bool isImplicit(const std::string& time) {
  return time == "beuler" || time == "cn" || time == "bdf2";
}
bool isKnownTimeScheme(const std::string& time) {
  return time == "ssprk3" || time == "rk4" || isImplicit(time);
}

namespace {
PetscErrorCode registerSspRk3() {
  static bool done = false;
  PetscFunctionBeginUser;
  if (!done) { // Shu & Osher (1988) three-stage SSP-RK3 (Gottlieb & Shu 1998, eq. 4.2) in Butcher form
    const PetscReal A[9] = {0, 0, 0, 1, 0, 0, 0.25, 0.25, 0}, b[3] = {1.0 / 6, 1.0 / 6, 2.0 / 3},
                    c[3] = {0, 1, 0.5};
    PetscCall(TSRKRegister("ssprk3", 3, 3, A, b, c, nullptr, 0, nullptr));
    done = true;
  }
  PetscFunctionReturn(0);
}

// Jacobian-free Newton-Krylov (GMRES, no preconditioner, inexact Newton). A Newton solve that fails (the ENO/WENO
// stencil choice is not differentiable, so Newton can stall at a shock) rejects the step and retries it at half
// the time step; the next step starts again from the CFL step.
PetscErrorCode configureImplicit(TS ts, const std::string& time) {
  SNES snes;
  KSP ksp;
  PC pc;
  PetscFunctionBeginUser;
  if (time == "beuler")
    PetscCall(TSSetType(ts, TSBEULER));
  else if (time == "cn")
    PetscCall(TSSetType(ts, TSCN));
  else {
    PetscCall(TSSetType(ts, TSBDF));
    PetscCall(TSBDFSetOrder(ts, 2));
  }
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESSetUseMatrixFree(snes, PETSC_FALSE, PETSC_TRUE));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCNONE));
  PetscCall(SNESSetTolerances(snes, 1e-10, 1e-6, PETSC_DEFAULT, 30, PETSC_DEFAULT));
  PetscCall(SNESSetMaxLinearSolveFailures(snes, 30)); // inexact Newton: accept unconverged GMRES steps
  PetscCall(KSPSetTolerances(ksp, 1e-3, PETSC_DEFAULT, PETSC_DEFAULT, 100));
  PetscCall(TSSetMaxSNESFailures(ts, -1));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode createStepper(MPI_Comm comm, DM da, const StepperSettings& s, TSRHSFunction rhs, void* run,
                             PetscErrorCode (*pre)(TS), PetscErrorCode (*post)(TS), TS* ts) {
  PetscFunctionBeginUser;
  PetscCall(registerSspRk3());
  PetscCall(TSCreate(comm, ts));
  PetscCall(TSSetDM(*ts, da));
  PetscCall(TSSetProblemType(*ts, TS_NONLINEAR));
  PetscCall(TSSetRHSFunction(*ts, nullptr, rhs, run));
  PetscCall(TSSetApplicationContext(*ts, run));
  if (isImplicit(s.time)) {
    PetscCall(configureImplicit(*ts, s.time));
  } else {
    PetscCall(TSSetType(*ts, TSRK));
    PetscCall(TSRKSetType(*ts, s.time == "rk4" ? TSRK4 : "ssprk3"));
  }
  TSAdapt adapt;
  PetscCall(TSGetAdapt(*ts, &adapt));
  PetscCall(TSAdaptSetType(adapt, TSADAPTNONE));
  PetscCall(TSSetMaxTime(*ts, s.t_final));
  PetscCall(
      TSSetMaxSteps(*ts, s.max_steps >= 0 ? s.max_steps : PETSC_MAX_INT)); // 0: no step (initial output)
  PetscCall(TSSetExactFinalTime(*ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetTimeStep(*ts, s.dt));
  PetscCall(TSSetPreStep(*ts, pre));
  PetscCall(TSSetPostStep(*ts, post));
  PetscCall(TSSetFromOptions(*ts));
  if (isImplicit(s.time)) {
    SNES snes;
    PetscCall(TSGetSNES(*ts, &snes));
    PetscCall(SNESSetFromOptions(snes));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode writeStepCheckpoint(const suite::RunContext& ctx, suite::CheckpointPolicy& ckpt, PetscInt step,
                                   double time, const CheckpointIo& io) {
  PetscFunctionBeginUser;
  const std::string path = ckpt.pathForStep(step);
  PetscInt s = step;
  double t = time;
  PetscCall(io(true, path, &s, &t));
  PetscCall(ckpt.written(step));
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "euler: checkpoint %s (step %" PetscInt_FMT ", t = %.6g)",
                           path.c_str(), step, time));
  PetscFunctionReturn(0);
}

PetscErrorCode restartFromCheckpoint(const suite::RunContext& ctx, suite::CheckpointPolicy& ckpt, TS ts,
                                     const CheckpointIo& io, PetscInt* step, double* time, const char* note) {
  PetscFunctionBeginUser;
  if (!ckpt.restartRequested()) PetscFunctionReturn(0);
  std::string path;
  PetscCall(ckpt.restartPath(&path));
  PetscCall(io(false, path, step, time));
  PetscCall(TSSetStepNumber(ts, *step));
  PetscCall(TSSetTime(ts, *time));
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(),
                           "euler: restarted from %s at step %" PetscInt_FMT ", t = %.17g%s", path.c_str(),
                           *step, *time, note));
  PetscFunctionReturn(0);
}

PetscErrorCode endOfStep(const suite::RunContext& ctx, TS ts, suite::CheckpointPolicy& ckpt,
                         suite::Progress* progress, PetscInt step, double t,
                         const std::function<PetscErrorCode()>& checkpoint) {
  PetscReal dt;
  PetscFunctionBeginUser;
  PetscCall(TSGetTimeStep(ts, &dt));
  if (progress) PetscCall(progress->update(step, t, dt));
  bool stop = false, due = false;
  PetscCall(ctx.stopRequested(&stop));
  PetscCall(ckpt.due(step, &due));
  if ((due || stop) && ckpt.enabled()) PetscCall(checkpoint());
  if (stop) {
    PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "euler: stopping at step %" PetscInt_FMT " (%s)", step,
                             ctx.stopReason().c_str()));
    PetscCall(TSSetConvergedReason(ts, TS_CONVERGED_USER));
  }
  PetscFunctionReturn(0);
}

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

std::string fileNameOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string xdmfPathFor(const std::string& h5_path) {
  std::string xmf = h5_path;
  if (xmf.size() > 3 && xmf.substr(xmf.size() - 3) == ".h5") xmf = xmf.substr(0, xmf.size() - 3);
  return xmf + ".xmf";
}

} // namespace euler_app
