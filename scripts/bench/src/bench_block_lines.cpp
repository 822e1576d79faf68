// Benchmark of the batched parallel block-tridiagonal line solve (lib/linalg/substructured_block_lines):
// -nlines lines of -nloc block rows per rank (bs x bs blocks, or scalar rows shared by -bs right-hand sides
// with -scalar), split over the ranks of PETSC_COMM_WORLD along the lines, against the plain serial block
// Thomas of the same rows on one rank (the same solver on MPI_COMM_SELF: the cost floor of a method that
// would own whole lines). Rows: characteristic compact-scheme-like blocks (diagonally dominant, off-diagonal
// blocks up to ~0.45 of the diagonal), deterministic in the global row, so no line falls back.
// Reports, per solve: the minimum over -reps of the slowest rank's wall time, the calling thread's CPU time
// (the machine may be shared), and both per line-row (one block row of one line on one rank). Writes one
// CSV line per run (header + values) to -output.
//
// Sample runs:
//   bench_block_lines -bs 5 -nloc 64 -nlines 4096 -reps 10 -output block_lines_np1.csv
//   mpiexec -n 2 bench_block_lines -bs 5 -nloc 64 -nlines 4096 -reps 10 -output block_lines_np2.csv
#include "core/log.hpp"
#include "core/run_context.hpp"
#include "io/h5_output.hpp"
#include "linalg/substructured_block_lines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

static const char help[] = "Benchmark: batched substructured block-tridiagonal line solves.\n";

namespace {

struct Options {
  PetscInt nlines = 4096, nloc = 64, bs = 5, reps = 10;
  PetscBool periodic = PETSC_FALSE, scalar = PETSC_FALSE;
  char output[PETSC_MAX_PATH_LEN] = "bench_block_lines.csv";
};

PetscErrorCode readOptions(MPI_Comm comm, Options* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Block line-solve benchmark", nullptr);
  PetscCall(
      PetscOptionsInt("-nlines", "Number of independent lines", nullptr, o->nlines, &o->nlines, nullptr));
  PetscCall(
      PetscOptionsInt("-nloc", "Block rows per line on each rank", nullptr, o->nloc, &o->nloc, nullptr));
  PetscCall(PetscOptionsInt("-bs", "Block size (1..5); with -scalar: right-hand sides", nullptr, o->bs,
                            &o->bs, nullptr));
  PetscCall(PetscOptionsInt("-reps", "Timed repetitions", nullptr, o->reps, &o->reps, nullptr));
  PetscCall(PetscOptionsBool("-periodic", "Periodic lines", nullptr, o->periodic, &o->periodic, nullptr));
  PetscCall(PetscOptionsBool("-scalar", "Scalar rows shared by -bs right-hand sides", nullptr, o->scalar,
                             &o->scalar, nullptr));
  PetscCall(PetscOptionsString("-output", "CSV output file", nullptr, o->output, o->output, sizeof o->output,
                               nullptr));
  PetscOptionsEnd();
  PetscCheck(o->nlines >= 1 && o->reps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-nlines and -reps must be >= 1");
  PetscCheck(o->nloc >= 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-nloc %d: must be >= 2", (int)o->nloc);
  PetscCheck(o->bs >= 1 && (o->scalar || o->bs <= 5), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-bs %d: must be in 1..5 (any >= 1 with -scalar)", (int)o->bs);
  PetscFunctionReturn(0);
}

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// Block row (line, global row): B = I + small, A and C = 0.2..0.45 I + small; d smooth.
void fillRow(int bs, long long line, long long row, double* A, double* B, double* C, double* d) {
  for (int a = 0; a < bs; ++a) {
    for (int b = 0; b < bs; ++b) {
      const double s = std::sin(0.37 * row + 1.3 * line + 0.7 * a + 0.3 * b);
      const bool diag = a == b;
      B[a * bs + b] = diag ? 1.0 + 0.05 * s : 0.03 * s;
      A[a * bs + b] = diag ? 0.3 + 0.15 * s : 0.02 * s;
      C[a * bs + b] = diag ? 0.3 - 0.1 * s : 0.02 * s;
    }
    d[a] = std::cos(0.11 * row - 0.7 * line + a);
  }
}

PetscErrorCode run(suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  Options o;
  PetscCall(readOptions(ctx.comm(), &o));
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) PetscFunctionReturn(0);
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output, "output"));
  const int P = ctx.size(), r = ctx.rank(), n = (int)o.nloc, L = (int)o.nlines;
  const int bs = o.scalar ? 1 : (int)o.bs, nrhs = o.scalar ? (int)o.bs : 1, bb = bs * bs;
  const long long first = (long long)n * r;
  std::vector<double> A((size_t)L * n * bb), B(A.size()), C(A.size()), d((size_t)L * n * bs * nrhs), abc;
  std::vector<double> rowd(bs);
  for (int l = 0; l < L; ++l)
    for (int i = 0; i < n; ++i) {
      const size_t k = (size_t)l * n + i;
      for (int c = 0; c < nrhs; ++c) {
        fillRow(bs, l + 7 * c, first + i, &A[k * bb], &B[k * bb], &C[k * bb], rowd.data());
        for (int a = 0; a < bs; ++a) d[(k * bs + a) * nrhs + c] = rowd[a];
      }
    }
  if (o.scalar) {
    abc.resize((size_t)3 * L * n);
    for (size_t k = 0; k < (size_t)L * n; ++k)
      abc[3 * k] = A[k], abc[3 * k + 1] = B[k], abc[3 * k + 2] = C[k];
  }
  const int count = (o.periodic || r + 1 < P) ? n + 1 : n;
  std::vector<double> x((size_t)L * count * bs * nrhs);
  auto solve = [&](suite::linalg::SubstructuredBlockLines& s, MPI_Comm comm, bool periodic, long long f,
                   int cnt) {
    if (o.scalar)
      s.solveScalar(comm, L, n, abc.data(), nrhs, d.data(), periodic, f, cnt, x.data());
    else
      s.solve(comm, bs, L, n, A.data(), B.data(), C.data(), d.data(), periodic, f, cnt, x.data());
  };
  auto timeIt = [&](suite::linalg::SubstructuredBlockLines& s, MPI_Comm comm, bool periodic, long long f,
                    int cnt, double* wall, double* cpu) -> PetscErrorCode {
    PetscFunctionBeginUser;
    *wall = *cpu = 1e300;
    solve(s, comm, periodic, f, cnt); // warm-up (work arrays)
    for (PetscInt k = 0; k < o.reps; ++k) {
      PetscCallMPI(MPI_Barrier(ctx.comm()));
      const double t0 = MPI_Wtime(), c0 = threadCpu();
      solve(s, comm, periodic, f, cnt);
      double t[2] = {MPI_Wtime() - t0, threadCpu() - c0};
      PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, t, 2, MPI_DOUBLE, MPI_MAX, ctx.comm()));
      *wall = std::min(*wall, t[0]);
      *cpu = std::min(*cpu, t[1]);
    }
    PetscFunctionReturn(0);
  };
  suite::linalg::SubstructuredBlockLines par, ser;
  double wall = 0, cpu = 0, swall = 0, scpu = 0;
  PetscCall(timeIt(par, ctx.comm(), o.periodic, first, count, &wall, &cpu));
  const long long fallbacks = par.stats().fallbacks;
  // Reference: plain serial block Thomas of this rank's rows (open lines on MPI_COMM_SELF).
  PetscCall(timeIt(ser, MPI_COMM_SELF, false, 0, n, &swall, &scpu));
  const double rows = (double)L * n; // line-rows per rank
  const long long doubles_gathered = (long long)L * (2 * bs * nrhs + 4 * bb + 1);
  PetscCall(suite::logInfo(ctx.comm(), false,
                           "%s lines: %d lines x %d %s rows per rank (bs %d, nrhs %d) on %d rank(s): "
                           "%.3e s/solve wall, %.3e s CPU; per line-row %.1f ns wall, %.1f ns CPU; "
                           "serial block Thomas of the same rows %.1f ns CPU per line-row (%.2fx); "
                           "fallback lines %lld; messages per solve: 1 Allgather (%lld doubles per rank) "
                           "+ 1 Allreduce (%d doubles)",
                           o.periodic ? "periodic" : "open", L, n, o.scalar ? "scalar" : "block", bs, nrhs, P,
                           wall, cpu, wall / rows * 1e9, cpu / rows * 1e9, scpu / rows * 1e9, cpu / scpu,
                           fallbacks, doubles_gathered, 2 * L));
  if (r == 0) {
    FILE* f = std::fopen(o.output, "w");
    PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot open -output %s", o.output);
    std::fprintf(f, "ranks,bs,nrhs,scalar,periodic,nlines,nloc,reps,wall_s_per_solve,cpu_s_per_solve,"
                    "wall_ns_per_line_row,cpu_ns_per_line_row,serial_thomas_cpu_ns_per_line_row,fallbacks\n");
    std::fprintf(f, "%d,%d,%d,%d,%d,%d,%d,%d,%.6e,%.6e,%.3f,%.3f,%.3f,%lld\n", P, bs, nrhs, (int)o.scalar,
                 (int)o.periodic, L, n, (int)o.reps, wall, cpu, wall / rows * 1e9, cpu / rows * 1e9,
                 scpu / rows * 1e9, fallbacks);
    std::fclose(f);
  }
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "bench_block_lines");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(run(ctx));
}
