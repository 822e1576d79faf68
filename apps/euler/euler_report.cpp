// The end of an Euler run (TimeLoop's writeFinal): the conservation report, the run statistics (speed, shock
// rows, limited faces, line solves, implicit Newton failures), the errors (-error) and the final output.
#include "euler_run.hpp"

#include "core/log.hpp"
#include "core/run_summary.hpp"
#include "io/xdmf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace euler_app {

PetscErrorCode EulerRun::reportConservation() {
  std::vector<double> tot;
  PetscFunctionBeginUser;
  PetscCall(totals(U_, &tot));
  const char* names[5] = {"mass", "momentum_x", "momentum_y", "momentum_z", "energy"};
  for (int c = 0; c < nv(); ++c) {
    const char* name = c == nv() - 1 ? "energy" : dim() == 1 && c == 1 ? "momentum" : names[c];
    const double change = std::abs(tot[c] - totals0_[c]);
    if (totals0_[c] == 0.0) // no scale to relate the change to (e.g. the momentum of a fluid at rest)
      PetscCall(suite::logInfo(ctx_.comm(), quiet(),
                               "conservation %s: initial %.15e final %.15e abs_change %.3e (initial zero)",
                               name, totals0_[c], tot[c], change));
    else
      PetscCall(suite::logInfo(ctx_.comm(), quiet(),
                               "conservation %s: initial %.15e final %.15e rel_change %.3e", name,
                               totals0_[c], tot[c], change / std::abs(totals0_[c])));
  }
  PetscFunctionReturn(0);
}

namespace {
struct SweepCounts {
  long long counts[4]; // shock rows, limited faces, exact fallbacks of the line solves, component-wise faces
  long long solves, lines;
  long long sensor_rows; // rows the ENO-Pade sensor examined
};
template <int NV> SweepCounts countsOf(const suite::euler::DirectionSweep<NV>& s) {
  return {{s.stats().shock_rows, s.stats().limited_faces, s.lineFallbacks(), s.stats().componentwise_faces},
          s.lineSolves(),
          s.linesSolved(),
          s.stats().sensor_rows};
}
} // namespace

PetscErrorCode EulerRun::reportStatistics(const suite::LoopSummary& sum) {
  PetscFunctionBeginUser;
  SweepCounts c = dim() == 1 ? countsOf(*sweep3_) : dim() == 2 ? countsOf(*sweep4_) : countsOf(*sweep5_);
  // Shock rows and the rows examined, summed over the ranks (each rank examines its own rows) in every dim.
  long long rows[2] = {c.counts[0], c.sensor_rows};
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, rows, 2, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
  PetscCall(suite::logInfo(ctx_.comm(), quiet(),
                           "euler: shock sensor: %lld shock rows of %lld rows examined (fraction %.3e)",
                           rows[0], rows[1], rows[1] > 0 ? (double)rows[0] / (double)rows[1] : 0.0));
  if (dim() == 1) c.counts[0] = rows[0];
  shock_rows_[0] = rows[0], shock_rows_[1] = rows[1]; // for the output's attributes
  // The rate of this run's own steps (a restart continues a history it did not time; none left: no rate).
  const double cells = (double)opt_.n[0] * opt_.n[1] * opt_.n[2] * sum.stepsTaken(),
               rate = sum.stepsTaken() > 0 && wall_solve_ > 0 ? cells / wall_solve_ : 0.0;
  const char* head =
      "euler: %" PetscInt_FMT " steps to t = %.6g in %.3f s (%.3e cell-steps/s, %.3e per rank; "
      "rank 0 CPU %.3f s); steps retried %lld, shock rows %lld, limited faces %lld, component-wise faces "
      "%lld";
  if (dim() == 1) { // the line's counts are rank 0's, but for the shock rows (summed)
    const std::string fmt = std::string(head) + ", line solves %lld (exact fallbacks %lld)";
    PetscCall(suite::logInfo(ctx_.comm(), quiet(), fmt.c_str(), sum.stepsTaken(), sum.t, wall_solve_, rate,
                             rate / ctx_.size(), cpu_solve_, (long long)sum.retries, c.counts[0], c.counts[1],
                             c.counts[3], c.solves, c.counts[2]));
  } else { // shock rows, limited faces, fallbacks and component-wise faces summed over the ranks; the solve calls
           // and lines are rank 0's
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, c.counts, 4, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
    const std::string fmt =
        std::string(head) + "; rank 0: %lld batched line solves of %lld lines; exact fallbacks %lld";
    PetscCall(suite::logInfo(ctx_.comm(), quiet(), fmt.c_str(), sum.stepsTaken(), sum.t, wall_solve_, rate,
                             rate / ctx_.size(), cpu_solve_, (long long)sum.retries, c.counts[0], c.counts[1],
                             c.counts[3], c.solves, c.lines, c.counts[2]));
  }
  if (!opt_.implicit) PetscFunctionReturn(0);
  PetscInt failures, rejections;
  PetscCall(TSGetSNESFailures(ts_, &failures));
  PetscCall(TSGetStepRejections(ts_, &rejections));
  PetscCall(suite::logInfo(ctx_.comm(), quiet(),
                           "implicit: %" PetscInt_FMT " Newton failures, %" PetscInt_FMT
                           " steps retried at half the time step",
                           failures, rejections));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeFinal(const suite::LoopSummary& sum) {
  PetscFunctionBeginUser;
  step_ = sum.steps, time_ = sum.t, retries_ = sum.retries;
  wall_solve_ = sum.wall,
  cpu_solve_ = sum.cpu; // this rank's CPU time: the clock to trust on a loaded machine
  cpu_first_step_ = sum.cpu_first;
  PetscCall(reportConservation());
  PetscCall(reportStatistics(sum));
  if (opt_.error) PetscCall(computeErrors());
  status_ = suite::runStatus(sum);
  PetscCall(writeOutput());
  const std::vector<std::string> written = suite::outputWithSidecar(opt_.output);
  std::string what = suite::stepsText(sum);
  if (sum.stepsTaken() > 0 && sum.wall > 0) {
    char rate[64];
    std::snprintf(rate, sizeof rate, " (%.3e cell-steps/s)",
                  (double)opt_.n[0] * opt_.n[1] * opt_.n[2] * sum.stepsTaken() / sum.wall);
    what += rate;
  }
  PetscCall(suite::logRunSummary(ctx_, status_, what, written));
  PetscFunctionReturn(0);
}

} // namespace euler_app
