// The one time loop of the suite: every time-dependent app (euler, femdyn, contact) runs its steps through
// TimeLoop::run. The loop owns what is the same for all of them (after Athena++'s and AMReX's queue ergonomics):
//   - step / time / dt bookkeeping: dt from the app's proposal, clipped so that the last step lands on t_final;
//     the run ends at t_final, after max_steps, on a stop request or when a step fails;
//   - bounded retries: a step the app rejects (StepStatus::Retry, state unchanged) is tried again at half dt;
//   - the progress line (core/progress.hpp), stop requests (signals, -max_walltime: RunContext::stopRequested),
//     the checkpoint cadence (io/checkpoint_policy.hpp) and a final checkpoint on a stop or at the end,
//     restart from a checkpoint, the snapshot cadence and the final write.
// The app supplies a TimeStepped object (advance one step, propose dt, save/load state, write a snapshot and the
// final output); observers (StepObserver, e.g. femdyn's haptic probe) see each step without living in the loop.
//
// One step, collectively on every rank:
//   dt = app.proposeDt(step, t), clipped to t_final - t       observers.beforeStep(step, t, dt)
//   app.advance(step, t, dt) -> Done(t_new) | Retry (dt /= 2, at most max_retries times) | Failed(message)
//   step += 1, t = t_new                                      observers.afterStep(step, t, dt)
//   snapshot when step % snapshot_every == 0, progress line, checkpoint when due or stopping
// then the final checkpoint (if enabled and not written at this step) and app.writeFinal(summary). A failed
// step writes the final output of the state before it and then stops the job with the app's message.
#pragma once

#include "core/progress.hpp"
#include "core/run_context.hpp"
#include "io/checkpoint_policy.hpp"

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

namespace suite {

enum class StepStatus { Done, Retry, Failed };

// What app.advance reports. Retry and Failed leave the app's state as it was before the step.
struct StepOutcome {
  StepStatus status = StepStatus::Done;
  double t_new = 0.0;  // Done: the time reached (the app's own arithmetic, e.g. PETSc TS's ptime + dt)
  std::string message; // Retry/Failed: why (logged; a Failed message ends the job's error line)
};

// How the loop ended and what it did; handed to TimeStepped::writeFinal.
struct LoopSummary {
  PetscInt first_step = 0; // the step the loop started from (0, or the restart's step)
  PetscInt steps = 0;      // the last completed step (absolute count)
  double t = 0.0;          // its time
  PetscInt retries = 0;    // steps retried at half dt
  bool restarted = false;
  bool stopped = false;    // a stop request (signal, -max_walltime) ended the run early
  std::string stop_reason; // "signal", "max_walltime" or ""
  bool failed = false;     // a step failed: the output holds the state before it
  std::string failure;     // the app's message
  double wall = 0.0;       // seconds in the loop (wall, MPI_Wtime)
  double cpu = 0.0;        // this process's CPU seconds in the loop
  // of cpu, the first step's (it touches the work arrays for the first time: a few steps' worth)
  double cpu_first = 0.0;
  PetscInt stepsTaken() const { return steps - first_step; }
};

// The app's side of the loop. Every call is collective and returns the same decisions on every rank.
class TimeStepped {
public:
  virtual ~TimeStepped() = default;
  // Before the first step, after a restart if any (restarted: the state came from loadState).
  virtual PetscErrorCode start(PetscInt step, double t, bool restarted) = 0;
  virtual PetscErrorCode proposeDt(PetscInt step, double t, double* dt) = 0;
  virtual PetscErrorCode advance(PetscInt step, double t, double dt, StepOutcome* out) = 0;
  // Checkpoint of the state after `step` at time t (the loop chooses the path; the file is written atomically).
  virtual PetscErrorCode saveState(const std::string& path, PetscInt step, double t) = 0;
  // Reads a checkpoint; *step and *t come from the file.
  virtual PetscErrorCode loadState(const std::string& path, PetscInt* step, double* t) = 0;
  virtual PetscErrorCode writeSnapshot(PetscInt step, double t) = 0;
  virtual PetscErrorCode writeFinal(const LoopSummary& summary) = 0;
};

// Sees every step; may not change the decisions of the loop.
class StepObserver {
public:
  virtual ~StepObserver() = default;
  virtual PetscErrorCode beforeStep(PetscInt step, double t, double dt) {
    (void)step, (void)t, (void)dt;
    return 0;
  }
  virtual PetscErrorCode afterStep(PetscInt step, double t, double dt) = 0;
};

struct TimeLoopSettings {
  const char* app = "";    // log prefix ("euler: checkpoint ...")
  double t_final = 0.0;    // > 0: end at this time (the last dt is clipped to land on it); 0: no time limit
  PetscInt max_steps = -1; // >= 0: end after this step count (absolute, a restart counts from its step)
  PetscInt snapshot_every =
      0;                    // > 0: app.writeSnapshot every that many steps (and at the start of a fresh run)
  PetscInt max_retries = 0; // retries of one step at half dt before the run stops
  double eta_time = 0.0;    // the simulated end time the progress line's ETA uses (0: t_final)
  const char* output =
      ""; // the final output's path: a failed run's error names it ("output up to step N in F")
};

class TimeLoop {
public:
  // policy: the run's checkpoint options (already read with setFromOptions).
  TimeLoop(const RunContext& ctx, CheckpointPolicy& policy, TimeLoopSettings settings)
      : ctx_(ctx), policy_(policy), set_(settings) {}
  void addObserver(StepObserver* o) { observers_.push_back(o); }
  // Runs the whole loop (restart, steps, final checkpoint, app.writeFinal); errors collectively when a step
  // failed, after the final output is written.
  PetscErrorCode run(TimeStepped& app);
  const LoopSummary& summary() const { return sum_; }

private:
  PetscErrorCode restartOrStart(TimeStepped& app);
  bool finished() const;
  PetscErrorCode clippedDt(TimeStepped& app, double* dt) const;
  PetscErrorCode stepWithRetries(TimeStepped& app, double dt, bool* failed);
  PetscErrorCode endOfStep(TimeStepped& app, double dt, bool* stop);
  PetscErrorCode checkpoint(TimeStepped& app);

  const RunContext& ctx_;
  CheckpointPolicy& policy_;
  TimeLoopSettings set_;
  std::vector<StepObserver*> observers_;
  LoopSummary sum_;
  PetscInt last_checkpoint_ = -1;
  std::unique_ptr<Progress> progress_;
};

} // namespace suite
