// The Euler app's run for -dim 1|2|3 (see euler_run.hpp): reads -dim and the options, then either documents
// them (-help), measures a scheme's spectrum (-scheme_spectrum, 1D), or sets the run up and steps it through
// the suite's TimeLoop.
#include "euler_run.hpp"

#include "core/option_value.hpp"
#include "euler_target.hpp"

namespace euler_app {

PetscErrorCode EulerRun::solve() {
  PetscFunctionBeginUser;
  suite::TimeLoopSettings s;
  s.app = "euler";
  s.t_final = opt_.t_final;
  s.max_steps = opt_.max_steps;
  s.snapshot_every = opt_.snapshot_every;
  s.max_retries = opt_.max_retries;
  s.output = opt_.output.c_str();
  suite::TimeLoop loop(ctx_, ckpt_, s);
  PetscCall(loop.run(*this));
  PetscFunctionReturn(0);
}

PetscErrorCode runEuler(const suite::RunContext& ctx) {
  PetscInt dim = 1;
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx.comm(), "", "Euler dimension", "");
  PetscCall(
      suite::optionsInt(PetscOptionsObject, "-dim",
                        "Spatial dimension: 1, 2 or 3 (2/3: -nx -ny -nz, DMDA process grid); the problems "
                        "and options listed below are those of this -dim",
                        "", dim, &dim, nullptr));
  PetscOptionsEnd();
  PetscCheck(dim >= 1 && dim <= 3, ctx.comm(), PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -dim %" PetscInt_FMT ": 1, 2 or 3", dim);
  TargetOptions target;
  PetscCall(readTargetOptions(ctx.comm(), (int)dim, &target));
  if (target.on() && !ctx.helpRequested()) {
    PetscCall(runTargetEuler(ctx, (int)dim, target));
    PetscFunctionReturn(0);
  }
  EulerRun run(ctx, (int)dim);
  PetscCall(run.readOptions());
  if (ctx.helpRequested() || run.spectrumOnly()) {
    PetscCall(ctx.checkUnusedOptions());
    if (!ctx.helpRequested()) PetscCall(run.schemeSpectrum());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(ctx.checkUnusedOptions());
  PetscCall(run.solve());
  PetscFunctionReturn(0);
}

} // namespace euler_app
