// Benchmark of the parallel tridiagonal line solve (lib/linalg/substructured_lines): time per solve of
// -nlines lines of -n rows each, split over the ranks, against the serial LAPACK solve of one rank's share
// of whole lines (what a transpose-based method would do), and the messages per solve (1 Allgather).
//
// Sample runs:
//   bench_lines -nlines 4096 -n 256 -reps 20 -output lines_np1.h5
//   mpiexec -n 2 bench_lines -nlines 4096 -n 256 -reps 20 -output lines_np2.h5
#include "core/log.hpp"
#include "core/run_context.hpp"
#include "io/h5_output.hpp"
#include "linalg/lapack.hpp"
#include "linalg/substructured_lines.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

static const char help[] = "Benchmark: substructured parallel tridiagonal line solves.\n";

namespace {

struct Options {
  PetscInt nlines = 4096, n = 256, reps = 20;
  char output[PETSC_MAX_PATH_LEN] = "bench_lines.h5";
};

PetscErrorCode readOptions(MPI_Comm comm, Options* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Line-solve benchmark", nullptr);
  PetscCall(
      PetscOptionsInt("-nlines", "Number of independent lines", nullptr, o->nlines, &o->nlines, nullptr));
  PetscCall(PetscOptionsInt("-n", "Rows per line (global)", nullptr, o->n, &o->n, nullptr));
  PetscCall(PetscOptionsInt("-reps", "Timed repetitions", nullptr, o->reps, &o->reps, nullptr));
  PetscCall(
      PetscOptionsString("-output", "HDF5 output", nullptr, o->output, o->output, sizeof o->output, nullptr));
  PetscOptionsEnd();
  PetscCheck(o->nlines >= 1 && o->reps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-nlines and -reps must be >= 1");
  PetscFunctionReturn(0);
}

// CRWENO-like rows (omega_1 up to 0.7: not diagonally dominant everywhere), deterministic in the global row.
void fillRows(long long line, long long row, double* a, double* b, double* c, double* d) {
  const double t = 0.5 + 0.5 * std::sin(0.37 * row + 1.3 * line);
  *a = 0.3 + 0.4 * t, *b = 1.0, *c = 0.3 * (1 - t), *d = std::cos(0.11 * row - 0.7 * line);
}

PetscErrorCode run(suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  Options o;
  PetscCall(readOptions(ctx.comm(), &o));
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) PetscFunctionReturn(0);
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output, "output"));
  const int P = ctx.size(), r = ctx.rank();
  PetscCheck(o.n >= P, ctx.comm(), PETSC_ERR_ARG_OUTOFRANGE, "-n %d: need at least one row per rank",
             (int)o.n);
  const long long first = (long long)o.n * r / P, m = (long long)o.n * (r + 1) / P - first;
  const size_t sz = (size_t)o.nlines * m;
  std::vector<double> a(sz), b(sz), c(sz), d0(sz), d(sz);
  for (long long l = 0; l < o.nlines; ++l)
    for (long long i = 0; i < m; ++i)
      fillRows(l, first + i, &a[l * m + i], &b[l * m + i], &c[l * m + i], &d0[l * m + i]);
  suite::linalg::SubstructuredLines solver;
  double t_sub = 1e300;
  for (PetscInt k = 0; k < o.reps; ++k) {
    d = d0;
    PetscCallMPI(MPI_Barrier(ctx.comm()));
    const double t0 = MPI_Wtime();
    PetscCall(solver.solve(ctx.comm(), (int)o.nlines, (int)m, a.data(), b.data(), c.data(), d.data(), false));
    double t = MPI_Wtime() - t0, tmax;
    PetscCallMPI(MPI_Allreduce(&t, &tmax, 1, MPI_DOUBLE, MPI_MAX, ctx.comm()));
    t_sub = std::min(t_sub, tmax);
  }
  // Reference: the same number of line-rows solved serially by dgtsv on whole lines (nlines / P lines of n
  // rows).
  const long long lines_per_rank = std::max<long long>(1, o.nlines / P);
  std::vector<double> la(o.n), lb(o.n), lc(o.n), ld(o.n);
  double t_serial = 1e300;
  for (PetscInt k = 0; k < o.reps; ++k) {
    const double t0 = MPI_Wtime();
    for (long long l = 0; l < lines_per_rank; ++l) {
      for (long long i = 0; i < o.n; ++i) fillRows(l, i, &la[i], &lb[i], &lc[i], &ld[i]);
      int n = (int)o.n, one = 1, info = 0;
      dgtsv_(&n, &one, la.data() + 1, lb.data(), lc.data(), ld.data(), &n, &info);
    }
    t_serial = std::min(t_serial, MPI_Wtime() - t0);
  }
  const double rows = (double)o.nlines * o.n;
  PetscCall(suite::logInfo(
      ctx.comm(), false,
      "lines %d x %d rows on %d rank(s): substructured %.3e s/solve (%.1f Mrow/s), "
      "serial whole-line dgtsv of the same share %.3e s (incl. row setup); 1 Allgather of %d "
      "doubles per rank per solve",
      (int)o.nlines, (int)o.n, P, t_sub, rows / t_sub * 1e-6, t_serial, (int)o.nlines * 6 + 1));
  suite::H5Output out;
  PetscCall(out.open(ctx.comm(), o.output));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(out.writeAttribute("/", "nlines", (long long)o.nlines));
  PetscCall(out.writeAttribute("/", "n", (long long)o.n));
  PetscCall(out.writeAttribute("/", "seconds_per_solve", t_sub));
  PetscCall(out.writeAttribute("/", "serial_share_seconds", t_serial));
  PetscCall(out.commit(&ctx));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "bench_lines");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(run(ctx));
}
