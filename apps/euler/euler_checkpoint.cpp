// Euler checkpoint/restart for -dim 1|2|3, the TimeLoop's saveState/loadState: the conserved state
// as one global array ((z,) (y,) x, NV), so a restart may use another rank count or process grid, the initial
// totals of the conservation report, step and time. The header's tag names problem, dimension, axis, scheme,
// time integrator, gamma and the line options, its grid the cell counts: a restart with other physics or
// numerics is refused with one clear message (so is a checkpoint whose tag names no dimension: another
// layout). Single-step integrators restart bitwise; BDF2 keeps no history in the checkpoint and restarts
// with its BDF1 start-up step (a difference of the order of the local truncation error, reported at restart).
#include "euler_run.hpp"

#include "io/checkpoint.hpp"

#include <cstdio>

namespace euler_app {

std::string EulerRun::checkpointTag() const {
  char tag[400];
  std::snprintf(tag, sizeof tag,
                "%s:dim=%d:axis=%s:%s:%s:gamma=%.17g:char=%d:llf=%d:upw=%s:pos=%d:thr=%.17g:ppw=%.17g:cfl=%."
                "17g:dt=%.17g:"
                "filter=%.17g/%.17g",
                opt_.problem.c_str(), dim(), opt_.axis.c_str(), opt_.scheme.c_str(), opt_.time.c_str(),
                problem_.gamma, (int)opt_.characteristic, (int)opt_.local_lf, opt_.upwinding.c_str(),
                (int)opt_.positivity, opt_.shock_threshold, opt_.shock_ppw, opt_.cfl, opt_.dt,
                opt_.filter_alpha, opt_.filter_time);
  return tag;
}

PetscErrorCode EulerRun::checkpointIo(bool write, const std::string& path, PetscInt* step, double* time) {
  PetscScalar* u;
  suite::Dims dims, start, count;
  PetscFunctionBeginUser;
  blockDims(&dims, &start, &count);
  dims.push_back((unsigned long long)nv());
  start.push_back(0);
  count.push_back((unsigned long long)nv());
  const unsigned long long ntot = (unsigned long long)nv();
  PetscCall(VecGetArray(U_, &u));
  std::vector<suite::CheckpointField> fields{
      {"U", dims, start, count, u},
      {"totals0", {ntot}, {0}, {ctx_.rank() == 0 ? ntot : 0ULL}, totals0_.data()}};
  std::vector<long long> grid{opt_.n[0]}; // 1D: {nx}; 2D/3D: {nx, ny, nz} (nz = 1 in 2D)
  if (dim() > 1) grid.push_back(opt_.n[1]), grid.push_back(opt_.n[2]);
  const suite::CheckpointHeader header{"euler", checkpointTag(), *step, *time, 0.0, grid};
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

PetscErrorCode EulerRun::saveState(const std::string& path, PetscInt step, double t) {
  PetscInt s = step;
  double time = t;
  PetscFunctionBeginUser;
  PetscCall(checkpointIo(true, path, &s, &time));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::loadState(const std::string& path, PetscInt* step, double* t) {
  suite::CheckpointHeader h;
  PetscFunctionBeginUser;
  PetscCall(suite::readCheckpointHeader(ctx_.comm(), path, &h));
  PetscCheck(h.app != "euler" || h.scheme.find(":dim=") != std::string::npos, ctx_.comm(),
             PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: the checkpoint's tag '%s' names no dimension (dim=1|2|3): not a checkpoint of this "
             "euler's layout; run the case again",
             path.c_str(), h.scheme.c_str());
  PetscCall(checkpointIo(false, path, step, t));
  PetscCall(TSSetStepNumber(ts_, *step));
  PetscCall(TSSetTime(ts_, *t));
  PetscFunctionReturn(0);
}

} // namespace euler_app
