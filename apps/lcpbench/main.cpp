// lcpbench: batches of LCP / box LCP / MLCP problems solved by every requested solver of lib/lcp, problems
// dealt to ranks by dynamic load balancing, results (status, iterations, pivots, time, residual per solver
// and problem, plus histograms) in one HDF5 file (Lacoursiere 2003, SIGRAD: iteration-count histograms).
// Results are streamed to OUT.partial (flushed every -flush_every problems / -flush_seconds) and renamed to
// OUT when the batch is complete; an interrupted batch (signal, -max_walltime, kill) resumes when the same
// command is run again (-resume, default on). See lcpbench_run.cpp for the guarantees.
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
#include "core/run_context.hpp"
#include "lcpbench_run.hpp"

static const char help[] =
    "LCP solver batch benchmark (Lemke, Keller, Cottle-Dantzig, Murty, block pivoting, "
    "Newton, PGS) over MPI.\n";

int main(int argc, char** argv) {
  suite::RunContext ctx(&argc, &argv, help, "lcpbench");
  if (ctx.initError()) return ctx.exitCode(ctx.initError());
  return ctx.exitCode(lcpbench_app::runLcpBench(ctx));
}
