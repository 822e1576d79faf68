// Progress line on rank 0 every few seconds of wall time.
#include "core/progress.hpp"

namespace suite {

Progress::Progress(MPI_Comm comm, bool quiet, double interval, double t_final)
    : comm_(comm), quiet_(quiet), interval_(interval), t_final_(t_final) {
  t_start_ = t_last_ = MPI_Wtime();
}

PetscErrorCode Progress::update(PetscInt step, double time, double dt) {
  PetscFunctionBeginUser;
  if (step_start_ < 0) {
    step_start_ = step;
    time_start_ = time;
  }
  if (quiet_) PetscFunctionReturn(0);
  const double now = MPI_Wtime();
  if (now - t_last_ < interval_) PetscFunctionReturn(0);
  t_last_ = now;
  const double elapsed = now - t_start_;
  const double rate = (step - step_start_) / (elapsed > 0 ? elapsed : 1.0);
  double eta = -1.0;
  if (t_final_ > 0.0 && time > time_start_) eta = elapsed * (t_final_ - time) / (time - time_start_);
  if (eta >= 0.0)
    PetscCall(PetscPrintf(comm_, "  step %8d  t = %-12.6g dt = %-11.4g %8.1f steps/s  ETA %.0f s\n",
                          (int)step, time, dt, rate, eta));
  else
    PetscCall(PetscPrintf(comm_, "  step %8d  t = %-12.6g dt = %-11.4g %8.1f steps/s\n", (int)step, time, dt,
                          rate));
  PetscFunctionReturn(0);
}

PetscErrorCode Progress::updateCount(long long done, long long total, const char* what) {
  PetscFunctionBeginUser;
  if (quiet_) PetscFunctionReturn(0);
  const double now = MPI_Wtime();
  if (now - t_last_ < interval_ && done < total) PetscFunctionReturn(0);
  t_last_ = now;
  const double elapsed = now - t_start_;
  const double rate = done / (elapsed > 0 ? elapsed : 1.0);
  const double eta = rate > 0 ? (total - done) / rate : 0.0;
  PetscCall(PetscPrintf(comm_, "  %lld/%lld %s  %.1f/s  ETA %.0f s\n", done, total, what, rate, eta));
  PetscFunctionReturn(0);
}

} // namespace suite
