// When to write periodic checkpoints and where to restart from: the policy the time-stepping apps
// (euler, femdyn, contact) share, after Athena++'s and AMReX's queue ergonomics.
//
// Options (own "Checkpoint/restart options" block, documented by -help):
//   -checkpoint_dir DIR     enables checkpoints: files DIR/<app>_<step, 10 digits>.h5 (written atomically
//                           by writeCheckpoint: .tmp + fsync + rename)
//   -checkpoint_every N     every N steps (0 = off)
//   -checkpoint_wall S      every S seconds of wall time (0 = off); decided on rank 0 and broadcast
//   -checkpoint_keep K      keep the newest K checkpoint files (default 2; older ones are removed)
//   -restart FILE|latest    restart from FILE, or from the highest-step checkpoint in -checkpoint_dir
// A stop request (SIGTERM/SIGUSR1/-max_walltime, RunContext::stopRequested) should be followed by a final
// checkpoint when enabled(): the app calls pathForStep(step), writeCheckpoint, then written(step).
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {

class CheckpointPolicy {
public:
  // Registers and reads the options on comm; app names the files ("euler" -> euler_0000000120.h5).
  // Errors (collectively) on a negative interval, -checkpoint_keep < 1, an interval without
  // -checkpoint_dir, or an unwritable directory (created if missing).
  PetscErrorCode setFromOptions(MPI_Comm comm, const std::string& app);

  bool enabled() const { return !dir_.empty(); }
  const std::string& dir() const { return dir_; }
  // Collective: true on all ranks when a checkpoint is due after completing `step`.
  PetscErrorCode due(long long step, bool* yes) const;
  std::string pathForStep(long long step) const;
  // Call after a successful write of step's checkpoint: resets the wall clock, prunes old files (rank 0).
  PetscErrorCode written(long long step);

  bool restartRequested() const { return !restart_.empty(); }
  // The file to restart from: -restart's path, or for "latest" the highest-step DIR/<app>_*.h5 (no .tmp).
  // Collective error if it does not exist.
  PetscErrorCode restartPath(std::string* path) const;

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string app_, dir_, restart_;
  long long every_ = 0;
  double wall_ = 0.0, last_wall_ = 0.0;
  int keep_ = 2;
};

} // namespace suite
