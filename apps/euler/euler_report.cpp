// The end of an Euler run (TimeLoop's writeFinal): the conservation report, the run statistics (speed, shock
// rows, limited faces, line solves, implicit Newton failures), the errors (-error) and the final output.
#include "euler_run.hpp"

#include "core/log.hpp"

#include <algorithm>
#include <cmath>

namespace euler_app {

PetscErrorCode EulerRun::reportConservation() {
  std::vector<double> tot;
  PetscFunctionBeginUser;
  PetscCall(totals(U_, &tot));
  const char* names[5] = {"mass", "momentum_x", "momentum_y", "momentum_z", "energy"};
  for (int c = 0; c < nv(); ++c) {
    const char* name = c == nv() - 1 ? "energy" : dim() == 1 && c == 1 ? "momentum" : names[c];
    const double scale = std::max(std::abs(totals0_[c]), 1e-300);
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(), "conservation %s: initial %.15e final %.15e rel_change %.3e",
                             name, totals0_[c], tot[c], std::abs(tot[c] - totals0_[c]) / scale));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::reportStatistics(const suite::LoopSummary& sum) {
  PetscFunctionBeginUser;
  const suite::euler::LineStats st = dim() == 1 ? sweep3_->stats() : dim() == 2 ? sweep4_->stats() : sweep5_->stats();
  const long long solves = dim() == 1 ? sweep3_->lineSolves() : dim() == 2 ? sweep4_->lineSolves() : sweep5_->lineSolves();
  const long long lines = dim() == 1 ? sweep3_->linesSolved() : dim() == 2 ? sweep4_->linesSolved() : sweep5_->linesSolved();
  const long long fallbacks =
      dim() == 1 ? sweep3_->lineFallbacks() : dim() == 2 ? sweep4_->lineFallbacks() : sweep5_->lineFallbacks();
  const double cells = (double)opt_.n[0] * opt_.n[1] * opt_.n[2] * sum.steps, rate = cells / wall_solve_;
  if (dim() == 1) // the line is solved redundantly: rank 0's counts are the run's
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "euler: %" PetscInt_FMT " steps to t = %.6g in %.3f s (%.3e cell-steps/s, %.3e per "
                             "rank; rank 0 CPU %.3f s); shock rows %lld, limited faces %lld, line solves %lld "
                             "(exact fallbacks %lld)",
                             sum.steps, sum.t, wall_solve_, rate, rate / ctx_.size(), cpu_solve_, st.shock_rows,
                             st.limited_faces, solves, fallbacks));
  else { // shock rows, limited faces and fallbacks summed over the ranks; the solve calls and lines are rank 0's
    long long sums[3] = {st.shock_rows, st.limited_faces, fallbacks};
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "euler: %" PetscInt_FMT " steps to t = %.6g in %.3f s (%.3e cell-steps/s, %.3e per "
                             "rank; rank 0 CPU %.3f s); shock rows %lld, limited faces %lld; rank 0: %lld batched "
                             "line solves of %lld lines; exact fallbacks %lld",
                             sum.steps, sum.t, wall_solve_, rate, rate / ctx_.size(), cpu_solve_, sums[0], sums[1],
                             solves, lines, sums[2]));
  }
  if (opt_.implicit) {
    PetscInt failures, rejections;
    PetscCall(TSGetSNESFailures(ts_, &failures));
    PetscCall(TSGetStepRejections(ts_, &rejections));
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "implicit: %" PetscInt_FMT " Newton failures, %" PetscInt_FMT
                             " steps retried at a smaller time step",
                             failures, rejections));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeFinal(const suite::LoopSummary& sum) {
  PetscFunctionBeginUser;
  step_ = sum.steps, time_ = sum.t;
  wall_solve_ = sum.wall, cpu_solve_ = sum.cpu; // this rank's CPU time: the clock to trust on a loaded machine
  PetscCall(reportConservation());
  PetscCall(reportStatistics(sum));
  if (opt_.error) PetscCall(computeErrors());
  PetscCall(writeOutput());
  PetscFunctionReturn(0);
}

} // namespace euler_app
