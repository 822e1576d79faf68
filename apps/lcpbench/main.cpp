// lcpbench: batches of LCP / box LCP / MLCP problems solved by every requested solver of lib/lcp, problems
// dealt to ranks by dynamic load balancing, results (status, iterations, pivots, time, residual per solver
// and problem, plus histograms) in one HDF5 file (Lacoursiere 2003, SIGRAD: iteration-count histograms).
//
// Streaming and resume. Rank 0 owns the results file and never holds the whole table:
//   - OUT.partial (single-process HDF5, lib/io/h5_append.hpp) is created with every per-problem dataset
//     preallocated at its final size and the batch header (/batch attributes: the options that fix results).
//   - Every -flush_every records (or -flush_seconds) the buffered results are written in place and flushed,
//     then their /batch/done flags are set and flushed: no HDF5 metadata changes, so a kill at any moment
//     (SIGKILL included) leaves a readable OUT.partial whose done-flagged entries are complete.
//   - SIGTERM / SIGUSR1 / SIGINT / -max_walltime: dealing stops, outstanding chunks are flushed, exit 0.
//   - Rerunning the command (-resume, default on) continues OUT.partial if the header matches (else an
//     error; -resume 0 discards it): done problems are skipped; /batch/run records the run that solved each.
//   - When all are done: OUT.partial is copied to OUT.tmp, histograms and summaries are computed by one
//     streamed pass and written to the copy, which is renamed to OUT; OUT.partial is removed last (a kill in
//     this phase leaves it complete: the next run only redoes this phase).
//
// Sample runs (tests/sample_runs.py executes each line):
//   mpiexec -n 4 lcpbench -family random_box -n 100 -count 500 -cond 1e4 -qrange 1e2
//       -solvers lemke,keller,cottle_dantzig,murty,bpp,fb_newton,smoothed_newton,pgs -output batch.h5
//   lcpbench -family murty -n 16 -count 1 -solvers lemke -output murty.h5     # 2^16 - 1 Lemke pivots
//   lcpbench -file ../shared/data/lcp/lcp_deudeu.dat,../shared/data/lcp/relay_2x2.dat -output f.h5
//   lcpbench -family random_spd -n 50 -count 100 -solvers bpp,fb_newton -output spd.h5
//   lcpbench -options_file inputs/lcpbench/random_box.yaml
//   lcpbench -family random_box -n 2 -count 100000 -solvers pgs -flush_every 10000 -output stream.h5
//   lcpbench -file ../shared/data/lcp/lcp_deudeu.dat -solvers bpp,lemke -resume 0 -output f2.h5
//   lcpbench -family random_box -n 20 -count 50 -solvers auto,bpp,lemke -output auto.h5   # the portfolio
#include "lcpbench.hpp"

#include "core/comma_list.hpp"
#include "core/log.hpp"
#include "io/h5_output.hpp"

static const char help[] =
    "LCP solver batch benchmark (Lemke, Keller, Cottle-Dantzig, Murty, block pivoting, "
    "Newton, PGS) over MPI.\n";

namespace lcpbench_app {
namespace {

PetscErrorCode runLcpBench(const suite::RunContext& ctx) {
  Options o;
  bool help_only = false;
  Batch b;
  RunState st;
  PetscFunctionBeginUser;
  PetscCall(readOptions(ctx, &o, &help_only));
  if (help_only) PetscFunctionReturn(0);
  PetscCall(makeBatch(ctx.comm(), o, &b));
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output.c_str(), "output"));
  Store store(b);
  PetscCall(startBatchFile(ctx, o, b, &store, &st));
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(),
                           "lcpbench: family %s, %lld problems%s, solvers %s, %d rank(s)", b.family.c_str(),
                           b.count, b.fromFiles() ? "" : (", n = " + std::to_string(o.n)).c_str(),
                           suite::joinCommaList(b.solver_names).c_str(), ctx.size()));
  PetscCall(dealProblems(ctx, o, b, &store, &st));
  PetscCall(finishRun(ctx, o, b, st, &store));
  PetscFunctionReturn(0);
}

} // namespace
} // namespace lcpbench_app

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "lcpbench");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(lcpbench_app::runLcpBench(ctx));
}
