// The Euler run's PETSc TS (see euler_stepper.hpp).
#include "euler_stepper.hpp"

namespace euler_app {

const std::vector<suite::Choice>& timeIntegrators() {
  static const std::vector<suite::Choice> list = {
      {"ssprk3", "3-stage SSP Runge-Kutta (Shu & Osher 1988), explicit"},
      {"rk4", "classical 4th-order Runge-Kutta, explicit"},
      {"beuler", "backward Euler, implicit (JFNK; Newton failures retried at a smaller step)"},
      {"cn", "Crank-Nicolson, implicit (JFNK)"},
      {"bdf2", "2nd-order BDF, implicit (JFNK; a restart begins with a BDF1 step)"},
  };
  return list;
}

bool isImplicit(const std::string& time) {
  return time == "beuler" || time == "cn" || time == "bdf2";
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
// stencil choice is not differentiable, so Newton can stall at a shock) rejects the step and TSStep retries it
// at a smaller time step; the next step starts again from the CFL step.
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

PetscErrorCode createStepper(MPI_Comm comm, DM da, Vec U, const StepperSettings& s, TSRHSFunction rhs,
                             void* ctx, TS* ts) {
  PetscFunctionBeginUser;
  PetscCall(registerSspRk3());
  PetscCall(TSCreate(comm, ts));
  PetscCall(TSSetDM(*ts, da));
  PetscCall(TSSetProblemType(*ts, TS_NONLINEAR));
  PetscCall(TSSetRHSFunction(*ts, nullptr, rhs, ctx));
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
  PetscCall(TSSetExactFinalTime(*ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetTimeStep(*ts, s.dt));
  PetscCall(TSSetFromOptions(*ts));
  if (isImplicit(s.time)) {
    SNES snes;
    PetscCall(TSGetSNES(*ts, &snes));
    PetscCall(SNESSetFromOptions(snes));
  }
  // What TSSolve did before its first step: the solution vector and the setup.
  PetscCall(TSSetSolution(*ts, U));
  PetscCall(TSSetUp(*ts));
  PetscFunctionReturn(0);
}

} // namespace euler_app
