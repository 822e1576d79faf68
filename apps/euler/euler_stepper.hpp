// What the 1D and the 2D/3D Euler runs share: the PETSc TS they step with (SSP-RK3 registered as "ssprk3", RK4,
// or implicit beuler/cn/bdf2 through Jacobian-free Newton-Krylov with step retries), the TS callbacks that
// forward to a run object, the end-of-step bookkeeping (progress, checkpoints, clean stops), restart, the
// process CPU clock, and the XDMF sidecar's file names.
#pragma once

#include "core/progress.hpp"
#include "core/run_context.hpp"
#include "io/checkpoint_policy.hpp"

#include <petscts.h>

#include <functional>
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

// Reads (write = false) or writes the run's checkpoint at path; on a read, *step and *time come from the file.
using CheckpointIo =
    std::function<PetscErrorCode(bool write, const std::string& path, PetscInt* step, double* time)>;

// Writes the checkpoint of (step, time) at the policy's path for that step and records it.
PetscErrorCode writeStepCheckpoint(const suite::RunContext& ctx, suite::CheckpointPolicy& ckpt, PetscInt step,
                                   double time, const CheckpointIo& io);
// With -restart: reads that checkpoint into the run and moves ts to its step and time (*step, *time); no-op
// otherwise. note: appended to the log line (e.g. why the restart is not bitwise).
PetscErrorCode restartFromCheckpoint(const suite::RunContext& ctx, suite::CheckpointPolicy& ckpt, TS ts,
                                     const CheckpointIo& io, PetscInt* step, double* time, const char* note);
// The end of a step: progress line, checkpoint (checkpoint()) when due or when stopping, and a clean stop of
// ts on a signal or -max_walltime.
PetscErrorCode endOfStep(const suite::RunContext& ctx, TS ts, suite::CheckpointPolicy& ckpt,
                         suite::Progress* progress, PetscInt step, double t,
                         const std::function<PetscErrorCode()>& checkpoint);

double cpuSeconds(); // this process's CPU time: the clock to trust on a loaded machine

// out.h5 -> out.xmf (beside it); the HDF5 name as the sidecar refers to it (relative: its file name).
std::string xdmfPathFor(const std::string& h5_path);
std::string fileNameOf(const std::string& path);

} // namespace euler_app
