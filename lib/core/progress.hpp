// Progress line on rank 0 every few seconds of wall time: step, simulated time, dt, step rate, ETA.
#pragma once

#include <petscsys.h>

namespace suite {

class Progress {
public:
  // interval: seconds of wall time between lines; quiet: print nothing. t_final <= 0: no ETA.
  Progress(MPI_Comm comm, bool quiet, double interval, double t_final);
  // Call every step (cheap: reads the clock on rank 0 only and prints when due).
  PetscErrorCode update(PetscInt step, double time, double dt);
  // Generic work counter form, for batches: "done/total items".
  PetscErrorCode updateCount(long long done, long long total, const char* what);

private:
  MPI_Comm comm_;
  bool quiet_;
  double interval_, t_final_, t_start_, t_last_;
  double time_start_ = -1.0;
  PetscInt step_start_ = -1;
};

} // namespace suite
