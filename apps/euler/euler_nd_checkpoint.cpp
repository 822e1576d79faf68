// 2D/3D Euler checkpoint/restart (issue #8): the conserved state as a global (z, y, x, NV) array, so a
// restart may use another rank count or process grid; the header's tag names problem, dimension, scheme, time
// integrator, gamma and the line options (a restart with other physics or numerics is refused).
#include "euler_nd_run.hpp"

#include "core/log.hpp"
#include "io/checkpoint.hpp"

#include <cstdio>

namespace euler_app {

std::string EulerRunND::checkpointTag() const {
  char tag[320];
  std::snprintf(tag, sizeof tag,
                "%s:dim=%d:axis=%s:%s:%s:gamma=%.17g:char=%d:llf=%d:pos=%d:thr=%.17g:cfl=%.17g:dt=%.17g",
                opt_.problem.c_str(), opt_.dim, opt_.axis.c_str(), opt_.scheme.c_str(), opt_.time.c_str(),
                problem_.gamma, (int)opt_.characteristic, (int)opt_.local_lf, (int)opt_.positivity,
                opt_.shock_threshold, opt_.cfl, opt_.dt);
  return tag;
}

PetscErrorCode EulerRunND::checkpointIo(bool write, const std::string& path, PetscInt* step, double* time) {
  PetscScalar* u;
  PetscFunctionBeginUser;
  suite::Dims dims, start, count;
  blockDims(&dims, &start, &count);
  dims.push_back((unsigned long long)nv());
  start.push_back(0);
  count.push_back((unsigned long long)nv());
  const bool root = ctx_.rank() == 0;
  const unsigned long long ntot = (unsigned long long)nv();
  PetscCall(VecGetArray(U_, &u));
  std::vector<suite::CheckpointField> fields{{"U", dims, start, count, u},
                                             {"totals0", {ntot}, {0}, {root ? ntot : 0ULL}, totals0_.data()}};
  suite::CheckpointHeader header{"euler", checkpointTag(),
                                 *step,   *time,
                                 0.0,     {(long long)opt_.n[0], (long long)opt_.n[1], (long long)opt_.n[2]}};
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
  if (!write) PetscCallMPI(MPI_Bcast(totals0_.data(), nv(), MPI_DOUBLE, 0, ctx_.comm()));
  PetscFunctionReturn(0);
}

CheckpointIo EulerRunND::checkpointFile() {
  return [this](bool write, const std::string& path, PetscInt* step, double* time) {
    return checkpointIo(write, path, step, time);
  };
}

PetscErrorCode EulerRunND::restartIfRequested() {
  PetscFunctionBeginUser;
  PetscCall(restartFromCheckpoint(ctx_, ckpt_, ts_, checkpointFile(), &steps_, &time_, ""));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::checkpointNow() {
  PetscFunctionBeginUser;
  PetscCall(writeStepCheckpoint(ctx_, ckpt_, steps_, time_, checkpointFile()));
  last_checkpoint_step_ = steps_;
  PetscFunctionReturn(0);
}

} // namespace euler_app
