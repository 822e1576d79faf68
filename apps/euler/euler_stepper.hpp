// What the 1D and the 2D/3D Euler runs share: the PETSc TS they step with (SSP-RK3 registered as "ssprk3", RK4,
// or implicit beuler/cn/bdf2 through Jacobian-free Newton-Krylov with step retries), the TS callbacks that
// forward to a run object, the process CPU clock, and the XDMF sidecar's file names.
#pragma once

#include <petscts.h>

#include <string>

namespace euler_app {

struct StepperSettings {
  std::string time;        // ssprk3, rk4, beuler, cn, bdf2
  double t_final = 0.0;    // TSSetMaxTime
  PetscInt max_steps = -1; // -1: no limit, 0: no step
  double dt = 0.0;         // first time step
};

bool isImplicit(const std::string& time);
bool isKnownTimeScheme(const std::string& time);
extern const char* const kTimeSchemes; // "ssprk3, rk4, beuler, cn, bdf2"

// Creates *ts on da with the run's RHS and pre/post-step hooks; the run object is the TS application context.
PetscErrorCode createStepper(MPI_Comm comm, DM da, const StepperSettings& s, TSRHSFunction rhs, void* run,
                             PetscErrorCode (*pre)(TS), PetscErrorCode (*post)(TS), TS* ts);

// TS callbacks forwarding to Run::rhs / preStep / postStep.
template <class Run> PetscErrorCode rhsCallback(TS, PetscReal t, Vec U, Vec F, void* ctx) {
  return static_cast<Run*>(ctx)->rhs(t, U, F);
}
template <class Run> PetscErrorCode preStepCallback(TS ts) {
  void* ctx;
  PetscFunctionBeginUser;
  PetscCall(TSGetApplicationContext(ts, &ctx));
  PetscCall(static_cast<Run*>(ctx)->preStep());
  PetscFunctionReturn(0);
}
template <class Run> PetscErrorCode postStepCallback(TS ts) {
  void* ctx;
  PetscFunctionBeginUser;
  PetscCall(TSGetApplicationContext(ts, &ctx));
  PetscCall(static_cast<Run*>(ctx)->postStep());
  PetscFunctionReturn(0);
}

double cpuSeconds(); // this process's CPU time: the clock to trust on a loaded machine

// out.h5 -> out.xmf (beside it); the HDF5 name as the sidecar refers to it (relative: its file name).
std::string xdmfPathFor(const std::string& h5_path);
std::string fileNameOf(const std::string& path);

} // namespace euler_app
