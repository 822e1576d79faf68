// lcpbench batch driver: the run in its named parts; see lcpbench_run.hpp and main.cpp.
//
// Streaming and resume (issue #8, batch resilience). Rank 0 deals chunks of problem indices and owns the
// results file; it never holds the whole table:
//   - At start it creates OUT.partial (single-process HDF5, lib/io/h5_append.hpp) with every per-problem
//     dataset preallocated at its final size (count) and the batch header (/batch attributes: family, n,
//     count, seed, cond, q range, bounds, solvers, files, solver options).
//   - Results arrive in chunks; at most -flush_every records (or -flush_seconds of wall time) are buffered,
//     then written in place, the file is flushed, and only then the /batch/done flags of those problems are
//     set and flushed again. Writes never change HDF5 metadata, so a process killed at any moment (SIGKILL
//     included) leaves a readable OUT.partial whose done-flagged entries are complete.
//   - SIGTERM / SIGUSR1 / SIGINT / -max_walltime: dealing stops, outstanding chunks are collected and flushed,
//     exit 0 with a message; OUT.partial stays.
//   - Rerunning the same command (-resume, default on) continues OUT.partial: the header must match (else a
//     clear error: -resume 0 discards it), done problems are skipped, never recomputed; /batch/run records for
//     every problem the run (0, 1, ...) that solved it; at completion /batch attributes solved_per_run and
//     run_wall_seconds sum it up. Attributes are written only at creation and completion (never while
//     problems are flushed), so the header cannot be torn by a kill.
//   - When every problem is done: OUT.partial is copied to OUT.tmp, histograms and summary attributes are
//     computed by one streamed pass over the datasets (blocks of 65536 problems) and written to the copy,
//     /batch complete = 1, OUT.tmp is renamed to OUT and OUT.partial removed. A kill in this phase leaves
//     OUT.partial complete: the next run of the command only redoes this phase.
#include "lcpbench_run.hpp"
#include "lcpbench_batch.hpp"
#include "lcpbench_dealer.hpp"
#include "lcpbench_finalize.hpp"
#include "lcpbench_options.hpp"
#include "lcpbench_resume.hpp"
#include "lcpbench_store.hpp"
#include "lcpbench_util.hpp"

#include "core/log.hpp"
#include "io/h5_output.hpp"

#include <string>

namespace lcpbench_app {

PetscErrorCode runLcpBench(const suite::RunContext& ctx) {
  Options o;
  bool help_only = false;
  Batch b;
  PetscFunctionBeginUser;
  PetscCall(readOptions(ctx, &o, &help_only));
  if (help_only) PetscFunctionReturn(0);
  PetscCall(makeBatch(ctx.comm(), o, &b));
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output.c_str(), "output"));

  RunSummary r;
  r.partial = o.output + ".partial";
  Store store(BatchShape{b.count, b.solver_names}, batchHeader(o, b), b.recordLength());
  ResumePoint rp;
  PetscCall(startBatchFile(ctx, r.partial, o.resume, &store, &rp));
  r.ndone0 = rp.ndone;
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(),
                           "lcpbench: family %s, %lld problems%s, solvers %s, %d rank(s)", b.family.c_str(),
                           b.count, b.fromFiles() ? "" : (", n = " + std::to_string(o.n)).c_str(),
                           join(b.solver_names).c_str(), ctx.size()));

  PetscCall(dealProblems(ctx, b, dealPlan(o, b.count, ctx.size()), rp, &store, &r.deal));
  if (r.deal.stopped != 0 || r.deal.ndone < b.count)
    PetscCall(finishInterrupted(ctx, b, r, &store));
  else
    PetscCall(finishComplete(ctx, o, b, r, &store));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
