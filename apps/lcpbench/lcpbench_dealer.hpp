// lcpbench's dealer: dynamic load balancing of problem indices. Rank 0 deals chunks of not-yet-done indices
// on request (MPI point-to-point) and solves problems itself between requests; workers send the results of
// their previous chunk with the next request. Rank 0 buffers results in the Store and flushes them every
// -flush_every problems or -flush_seconds. A stop (signal on any rank, -max_walltime) ends the dealing:
// outstanding chunks are collected and flushed.
#pragma once

#include "lcpbench_batch.hpp"
#include "lcpbench_resume.hpp"
#include "lcpbench_store.hpp"

#include "core/run_context.hpp"

namespace lcpbench_app {

struct DealPlan {
  long long chunk = 1;       // problems per work request
  long long flush_every = 1; // buffered records that trigger a flush
  double flush_seconds = 30; // ... or seconds since the last flush
  double max_walltime = 0;   // 0: no limit
};

// -chunk, or automatic (0): up to 64 problems, about 8 requests per rank.
DealPlan dealPlan(const Options& o, long long count, int nranks);

struct DealOutcome {
  long long ndone = 0; // every rank: problems done, this run and before
  int stopped = 0;     // 0: no stop, 1: signal, 2: -max_walltime
  double wall = 0;     // seconds spent dealing
};

// Collective: solves every problem not done in rp, results in store (rank 0).
PetscErrorCode dealProblems(const suite::RunContext& ctx, const Batch& b, const DealPlan& plan,
                            const ResumePoint& rp, Store* store, DealOutcome* out);

} // namespace lcpbench_app
