// Euler checkpoint/restart (issue #8): the conserved state as a global nx x 3 array (restartable at another
// rank count), the step and time, and the initial totals of the conservation report. The header's scheme
// tag names problem, scheme, time integrator, gamma and the line options, so a restart with different
// physics or numerics is refused. Single-step integrators (ssprk3, rk4, beuler, cn) restart bitwise; BDF2
// keeps no history in the checkpoint and restarts with its BDF1 start-up step (a difference of the order of
// the local truncation error, reported at restart).
#include "euler_run.hpp"

#include "core/log.hpp"
#include "io/checkpoint.hpp"

#include <cstdio>

namespace euler_app {

std::string EulerRun::checkpointTag() const {
  char tag[256];
  std::snprintf(tag, sizeof tag, "%s:%s:%s:gamma=%.17g:char=%d:llf=%d:pos=%d:thr=%.17g:cfl=%.17g:dt=%.17g",
                opt_.problem.c_str(), opt_.scheme.c_str(), opt_.time.c_str(), problem_.gamma,
                (int)opt_.characteristic, (int)opt_.local_lf, (int)opt_.positivity, opt_.shock_threshold,
                opt_.cfl, opt_.dt);
  return tag;
}

PetscErrorCode EulerRun::checkpointIo(bool write, const std::string& path, PetscInt* step, double* time) {
  PetscScalar* u;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(U_, &u));
  const unsigned long long nx = (unsigned long long)opt_.nx, xs = (unsigned long long)xs_,
                           xm = (unsigned long long)xm_;
  const bool root = ctx_.rank() == 0;
  std::vector<suite::CheckpointField> fields{{"U", {nx, 3}, {xs, 0}, {xm, 3}, u},
                                             {"totals0", {3}, {0}, {root ? 3ULL : 0ULL}, totals0_.data()}};
  suite::CheckpointHeader header{"euler", checkpointTag(), *step, *time, 0.0, {(long long)opt_.nx}};
  PetscErrorCode ierr;
  if (write) {
    ierr = suite::writeCheckpoint(ctx_.comm(), path, header, fields);
  } else {
    suite::CheckpointHeader found;
    ierr = suite::readCheckpoint(ctx_.comm(), path, header, &found, fields);
    *step = (PetscInt)found.step;
    *time = found.time;
  }
  PetscCall(VecRestoreArray(U_, &u));
  PetscCall(ierr);
  if (!write) PetscCallMPI(MPI_Bcast(totals0_.data(), 3, MPI_DOUBLE, 0, ctx_.comm()));
  PetscFunctionReturn(0);
}

CheckpointIo EulerRun::checkpointFile() {
  return [this](bool write, const std::string& path, PetscInt* step, double* time) {
    return checkpointIo(write, path, step, time);
  };
}

PetscErrorCode EulerRun::restartIfRequested() {
  PetscFunctionBeginUser;
  PetscCall(
      restartFromCheckpoint(ctx_, ckpt_, ts_, checkpointFile(), &steps_, &time_,
                            opt_.time == "bdf2" ? " (BDF2 restarts with a BDF1 step: not bitwise)" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::checkpointNow() {
  PetscFunctionBeginUser;
  PetscCall(writeStepCheckpoint(ctx_, ckpt_, steps_, time_, checkpointFile()));
  last_checkpoint_step_ = steps_;
  PetscFunctionReturn(0);
}

} // namespace euler_app
