// Skeleton driver: a minimal time-stepping "app" that exercises every piece of the shared layer the way the
// real apps do (options, unused-option check, output check, progress, field checks, HDF5 + XDMF output,
// checkpoint/restart, collective stop). The MPI tests of lib/ run it at 1 and 2 ranks.
//
// Sample runs (executed by tests/mpi/CMakeLists.txt):
//   skeleton_driver -n 64 -steps 10 -output s.h5
//   mpiexec -n 2 skeleton_driver -n 64 -steps 10 -output s.h5 -checkpoint c.h5
//   skeleton_driver -n 64 -steps 10 -restart c.h5 -output r.h5
//   skeleton_driver -n 64 -inject_nan_step 3 -output s.h5       (stops: non-finite u at step 3)
//   skeleton_driver -n 64 -inject_abort_in_output -output s.h5   (dies in output: s.h5 untouched)
//   mpiexec -n 2 skeleton_driver -inject_local_error_rank 1      (rank 1 fails alone: whole job aborts)
#include "core/field_check.hpp"
#include "core/log.hpp"
#include "core/log_stages.hpp"
#include "core/progress.hpp"
#include "core/run_context.hpp"
#include "io/checkpoint.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <petscdmda.h>

#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <vector>

static const char help[] = "Skeleton driver: advects a sine wave on a periodic 1D DMDA, exercising lib/.\n";

namespace {

struct DriverOptions {
  PetscInt n = 64, steps = 10, inject_nan_step = -1, snapshot_every = 0, inject_local_error_rank = -1;
  PetscReal cfl = 0.5, sleep_per_step = 0.0;
  PetscBool abort_in_output = PETSC_FALSE;
  char output[PETSC_MAX_PATH_LEN] = "skeleton.h5";
  char checkpoint[PETSC_MAX_PATH_LEN] = "";
  char restart[PETSC_MAX_PATH_LEN] = "";
};

PetscErrorCode readOptions(MPI_Comm comm, DriverOptions* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Skeleton driver options", nullptr);
  PetscCall(PetscOptionsInt("-n", "Number of cells", nullptr, o->n, &o->n, nullptr));
  PetscCall(PetscOptionsInt("-steps", "Number of time steps", nullptr, o->steps, &o->steps, nullptr));
  PetscCall(PetscOptionsReal("-cfl", "CFL number (0, 1]", nullptr, o->cfl, &o->cfl, nullptr));
  PetscCall(PetscOptionsInt("-snapshot_every", "Snapshot interval in steps (0 = none)", nullptr,
                            o->snapshot_every, &o->snapshot_every, nullptr));
  PetscCall(PetscOptionsInt("-inject_nan_step", "Test aid: put a NaN into the field at this step", nullptr,
                            o->inject_nan_step, &o->inject_nan_step, nullptr));
  PetscCall(PetscOptionsInt("-inject_local_error_rank", "Test aid: this rank alone raises an error at step 2",
                            nullptr, o->inject_local_error_rank, &o->inject_local_error_rank, nullptr));
  PetscCall(PetscOptionsReal("-sleep_per_step", "Test aid: seconds to sleep per step", nullptr,
                             o->sleep_per_step, &o->sleep_per_step, nullptr));
  PetscCall(PetscOptionsBool("-inject_abort_in_output", "Test aid: abort() after the datasets, before commit",
                             nullptr, o->abort_in_output, &o->abort_in_output, nullptr));
  PetscCall(PetscOptionsString("-output", "HDF5 output file", nullptr, o->output, o->output, sizeof o->output,
                               nullptr));
  PetscCall(PetscOptionsString("-checkpoint", "Checkpoint file written at the end (or at a stop request)",
                               nullptr, o->checkpoint, o->checkpoint, sizeof o->checkpoint, nullptr));
  PetscCall(PetscOptionsString("-restart", "Checkpoint file to restart from", nullptr, o->restart, o->restart,
                               sizeof o->restart, nullptr));
  PetscOptionsEnd();
  PetscCheck(o->n >= 4, comm, PETSC_ERR_ARG_OUTOFRANGE, "-n %d: need at least 4 cells", (int)o->n);
  PetscCheck(o->cfl > 0 && o->cfl <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-cfl %g: must be in (0, 1]",
             (double)o->cfl);
  PetscCheck(o->steps >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-steps %d: must be >= 0", (int)o->steps);
  PetscFunctionReturn(0);
}

// One upwind step of u_t + u_x = 0 (unit speed, periodic).
PetscErrorCode step(DM da, Vec u, Vec ul, double nu) {
  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(da, u, INSERT_VALUES, ul));
  const PetscScalar* a;
  PetscScalar* b;
  PetscInt xs, xm;
  PetscCall(DMDAGetCorners(da, &xs, nullptr, nullptr, &xm, nullptr, nullptr));
  PetscCall(DMDAVecGetArrayRead(da, ul, &a));
  PetscCall(DMDAVecGetArray(da, u, &b));
  for (PetscInt i = xs; i < xs + xm; ++i) b[i] = a[i] - nu * (a[i] - a[i - 1]);
  PetscCall(DMDAVecRestoreArrayRead(da, ul, &a));
  PetscCall(DMDAVecRestoreArray(da, u, &b));
  PetscFunctionReturn(0);
}

PetscErrorCode checkpointFields(DM da, Vec u, PetscScalar** data, std::vector<suite::CheckpointField>* f) {
  PetscFunctionBeginUser;
  PetscInt xs, xm, n;
  PetscCall(DMDAGetCorners(da, &xs, nullptr, nullptr, &xm, nullptr, nullptr));
  PetscCall(DMDAGetInfo(da, nullptr, &n, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                        nullptr, nullptr, nullptr, nullptr));
  PetscCall(VecGetArray(u, data));
  f->push_back({"u", {(unsigned long long)n}, {(unsigned long long)xs}, {(unsigned long long)xm}, *data});
  PetscFunctionReturn(0);
}

PetscErrorCode writeOutput(const suite::RunContext& ctx, const DriverOptions& o, DM da, Vec u, PetscInt steps,
                           double t) {
  PetscFunctionBeginUser;
  PetscInt xs, xm;
  PetscCall(DMDAGetCorners(da, &xs, nullptr, nullptr, &xm, nullptr, nullptr));
  const PetscScalar* a;
  PetscCall(VecGetArrayRead(u, &a));
  std::vector<double> x(xm);
  for (PetscInt i = 0; i < xm; ++i) x[i] = (xs + i + 0.5) / o.n;
  suite::H5Output out;
  PetscCall(out.open(ctx.comm(), o.output));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(out.writeAttribute("/", "steps", (long long)steps));
  PetscCall(out.writeAttribute("/", "time", t));
  const suite::Dims dims{(unsigned long long)o.n}, start{(unsigned long long)xs},
      count{(unsigned long long)xm};
  PetscCall(out.writeDistributed("/final/u", a, dims, start, count, "m/s"));
  PetscCall(out.writeDistributed("/grid/x", x.data(), dims, start, count, "m"));
  PetscCall(VecRestoreArrayRead(u, &a));
  PetscCall(out.flush());
  if (o.abort_in_output) std::abort(); // a job killed while writing: the final name must stay untouched
  PetscCall(out.commit(&ctx));
  suite::XdmfRectGrid grid{{(unsigned long long)o.n + 1}, {0.0}, {1.0 / o.n}};
  PetscCall(suite::writeXdmfRectSeries(ctx.comm(), suite::xdmfPathFor(o.output), suite::fileNameOf(o.output),
                                       grid, {{t, {{"u", "/final/u", true}}}}));
  PetscFunctionReturn(0);
}

PetscErrorCode run(suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  suite::LogStages stages;
  PetscCall(suite::LogStages::get(&stages));
  PetscCall(PetscLogStagePush(stages.setup));
  DriverOptions o;
  PetscCall(readOptions(ctx.comm(), &o));
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) {
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output, "output"));
  DM da;
  PetscCall(DMDACreate1d(ctx.comm(), DM_BOUNDARY_PERIODIC, o.n, 1, 1, nullptr, &da));
  PetscCall(DMSetUp(da));
  Vec u, ul;
  PetscCall(DMCreateGlobalVector(da, &u));
  PetscCall(DMCreateLocalVector(da, &ul));
  PetscInt xs, xm;
  PetscCall(DMDAGetCorners(da, &xs, nullptr, nullptr, &xm, nullptr, nullptr));
  PetscScalar* a;
  PetscCall(VecGetArray(u, &a));
  for (PetscInt i = 0; i < xm; ++i) a[i] = std::sin(2 * M_PI * (xs + i + 0.5) / o.n);
  PetscCall(VecRestoreArray(u, &a));
  const double dt = o.cfl / o.n;
  suite::CheckpointHeader header{"skeleton_driver", "upwind1", 0, 0.0, dt, {o.n}};
  if (o.restart[0]) {
    std::vector<suite::CheckpointField> f;
    PetscCall(checkpointFields(da, u, &a, &f));
    suite::CheckpointHeader found;
    PetscCall(suite::readCheckpoint(ctx.comm(), o.restart, header, &found, f));
    PetscCall(VecRestoreArray(u, &a));
    header.step = found.step;
    header.time = found.time;
    PetscCall(
        suite::logInfo(ctx.comm(), ctx.quiet(), "restarted from %s at step %lld", o.restart, found.step));
  }
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(stages.solve));
  suite::Progress progress(ctx.comm(), ctx.quiet(), ctx.progressInterval(), o.steps * dt);
  PetscInt s = (PetscInt)header.step;
  double t = header.time;
  for (; s < o.steps; ++s) {
    bool stop = false;
    PetscCall(ctx.stopRequested(&stop));
    if (stop) {
      PetscCall(suite::logInfo(ctx.comm(), false, "stop requested (%s) at step %d", ctx.stopReason().c_str(),
                               (int)s));
      break;
    }
    PetscCall(step(da, u, ul, o.cfl));
    t += dt;
    // An error only one rank sees (a local failure): the job must go down at once, not hang.
    PetscCheck(!(s + 1 == 2 && ctx.rank() == o.inject_local_error_rank), PETSC_COMM_SELF, PETSC_ERR_LIB,
               "injected local failure on rank %d at step 2", ctx.rank());
    if (s + 1 == o.inject_nan_step && xs <= o.n / 2 && o.n / 2 < xs + xm) {
      PetscCall(VecGetArray(u, &a));
      a[o.n / 2 - xs] = NAN;
      PetscCall(VecRestoreArray(u, &a));
    }
    const PetscScalar* r;
    PetscCall(VecGetArrayRead(u, &r));
    suite::FieldLocation where{"u", s + 1, t, xs};
    PetscErrorCode ierr = suite::checkFinite(ctx.comm(), r, xm, 1, 0, where);
    PetscCall(VecRestoreArrayRead(u, &r));
    PetscCall(ierr);
    PetscCall(progress.update(s + 1, t, dt));
    if (o.sleep_per_step > 0) usleep((useconds_t)(o.sleep_per_step * 1e6));
  }
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(stages.output));
  if (o.checkpoint[0]) {
    std::vector<suite::CheckpointField> f;
    PetscCall(checkpointFields(da, u, &a, &f));
    header.step = s;
    header.time = t;
    PetscCall(suite::writeCheckpoint(ctx.comm(), o.checkpoint, header, f));
    PetscCall(VecRestoreArray(u, &a));
  }
  PetscCall(writeOutput(ctx, o, da, u, s, t));
  PetscCall(PetscLogStagePop());
  PetscCall(VecDestroy(&ul));
  PetscCall(VecDestroy(&u));
  PetscCall(DMDestroy(&da));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "skeleton_driver");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(run(ctx));
}
