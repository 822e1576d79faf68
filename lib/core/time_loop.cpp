// The one time loop (see time_loop.hpp).
#include "core/time_loop.hpp"

#include "core/clocks.hpp"
#include "core/log.hpp"
#include "core/progress.hpp"

#include <memory>

namespace suite {

PetscErrorCode TimeLoop::restartOrStart(TimeStepped& app) {
  PetscFunctionBeginUser;
  sum_ = LoopSummary();
  if (policy_.restartRequested()) {
    std::string path;
    PetscCall(policy_.restartPath(&path));
    PetscCall(app.loadState(path, &sum_.steps, &sum_.t));
    PetscCheck(set_.max_steps < 0 || sum_.steps <= set_.max_steps, ctx_.comm(), PETSC_ERR_ARG_OUTOFRANGE,
               "restart %s: checkpoint at step %" PetscInt_FMT " is past the last step %" PetscInt_FMT,
               path.c_str(), sum_.steps, set_.max_steps);
    sum_.restarted = true;
    last_checkpoint_ = sum_.steps;
    PetscCall(logInfo(ctx_.comm(), ctx_.quiet(), "%s: restarted from %s at step %" PetscInt_FMT ", t = %.17g",
                      set_.app, path.c_str(), sum_.steps, sum_.t));
  }
  sum_.first_step = sum_.steps;
  PetscCall(app.start(sum_.steps, sum_.t, sum_.restarted));
  if (set_.snapshot_every > 0 && !sum_.restarted) PetscCall(app.writeSnapshot(sum_.steps, sum_.t));
  PetscFunctionReturn(0);
}

bool TimeLoop::finished() const {
  if (set_.max_steps >= 0 && sum_.steps >= set_.max_steps) return true;
  return set_.t_final > 0.0 && sum_.t >= set_.t_final;
}

// The app's dt, clipped so that the last step lands on t_final.
PetscErrorCode TimeLoop::clippedDt(TimeStepped& app, double* dt) const {
  PetscFunctionBeginUser;
  PetscCall(app.proposeDt(sum_.steps, sum_.t, dt));
  PetscCheck(*dt > 0.0, ctx_.comm(), PETSC_ERR_FP,
             "%s: time step %g is not positive at step %" PetscInt_FMT ", time %g", set_.app, *dt, sum_.steps,
             sum_.t);
  if (set_.t_final > 0.0 && sum_.t + *dt > set_.t_final) *dt = set_.t_final - sum_.t;
  PetscFunctionReturn(0);
}

// One step: advance, and on Retry the same step again at half dt, at most max_retries times.
PetscErrorCode TimeLoop::stepWithRetries(TimeStepped& app, double dt, bool* failed) {
  PetscFunctionBeginUser;
  *failed = false;
  for (PetscInt attempt = 0;; ++attempt) {
    StepOutcome out;
    PetscCall(app.advance(sum_.steps, sum_.t, dt, &out));
    if (out.status == StepStatus::Done) {
      sum_.steps += 1;
      sum_.t = out.t_new;
      break;
    }
    if (out.status == StepStatus::Retry && attempt < set_.max_retries) {
      PetscCall(logInfo(ctx_.comm(), ctx_.quiet(), "%s: step %" PetscInt_FMT " retried at dt = %g (%s)",
                        set_.app, sum_.steps + 1, dt / 2, out.message.c_str()));
      dt /= 2;
      sum_.retries += 1;
      continue;
    }
    *failed = true;
    sum_.failed = true;
    sum_.failure = out.message;
    break;
  }
  if (!*failed)
    for (StepObserver* o : observers_) PetscCall(o->afterStep(sum_.steps, sum_.t, dt));
  PetscFunctionReturn(0);
}

PetscErrorCode TimeLoop::checkpoint(TimeStepped& app) {
  PetscFunctionBeginUser;
  const std::string path = policy_.pathForStep(sum_.steps);
  PetscCall(app.saveState(path, sum_.steps, sum_.t));
  PetscCall(policy_.written(sum_.steps));
  last_checkpoint_ = sum_.steps;
  PetscCall(logInfo(ctx_.comm(), ctx_.quiet(), "%s: checkpoint %s (step %" PetscInt_FMT ", t = %.6g)",
                    set_.app, path.c_str(), sum_.steps, sum_.t));
  PetscFunctionReturn(0);
}

// After a completed step: snapshot, progress line, stop request, checkpoint cadence.
PetscErrorCode TimeLoop::endOfStep(TimeStepped& app, double dt, bool* stop) {
  PetscFunctionBeginUser;
  if (set_.snapshot_every > 0 && sum_.steps % set_.snapshot_every == 0)
    PetscCall(app.writeSnapshot(sum_.steps, sum_.t));
  if (progress_) PetscCall(progress_->update(sum_.steps, sum_.t, dt));
  bool due = false;
  PetscCall(ctx_.stopRequested(stop));
  PetscCall(policy_.due(sum_.steps, &due));
  if ((due || *stop) && policy_.enabled()) PetscCall(checkpoint(app));
  if (*stop) {
    sum_.stopped = true;
    sum_.stop_reason = ctx_.stopReason();
    PetscCall(logInfo(ctx_.comm(), ctx_.quiet(), "%s: stopping at step %" PetscInt_FMT " (%s)", set_.app,
                      sum_.steps, sum_.stop_reason.c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TimeLoop::run(TimeStepped& app) {
  PetscFunctionBeginUser;
  PetscCall(restartOrStart(app));
  progress_ = std::make_unique<Progress>(ctx_.comm(), ctx_.quiet(), ctx_.progressInterval(),
                                         set_.eta_time > 0.0 ? set_.eta_time : set_.t_final);
  const double w0 = MPI_Wtime(), c0 = processCpuSeconds();
  bool stop = false, failed = false, first = true;
  while (!finished() && !stop && !failed) {
    double dt;
    PetscCall(clippedDt(app, &dt));
    for (StepObserver* o : observers_) PetscCall(o->beforeStep(sum_.steps, sum_.t, dt));
    PetscCall(stepWithRetries(app, dt, &failed));
    if (!failed) PetscCall(endOfStep(app, dt, &stop));
    if (first) sum_.cpu_first = processCpuSeconds() - c0, first = false;
  }
  sum_.wall = MPI_Wtime() - w0;
  sum_.cpu = processCpuSeconds() - c0;
  if (policy_.enabled() && !failed && last_checkpoint_ != sum_.steps) PetscCall(checkpoint(app));
  PetscCall(app.writeFinal(sum_));
  if (failed && set_.output[0]) // the final output holds the state after the last completed step
    sum_.failure += " (output up to step " + std::to_string(sum_.steps) + " in " + set_.output + ")";
  PetscCheck(!failed, ctx_.comm(), PETSC_ERR_NOT_CONVERGED, "%s: step %" PetscInt_FMT " failed: %s", set_.app,
             sum_.steps + 1, sum_.failure.c_str());
  PetscFunctionReturn(0);
}

} // namespace suite
