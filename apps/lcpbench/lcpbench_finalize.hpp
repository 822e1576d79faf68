// lcpbench's end of a run. Interrupted (stop signal, -max_walltime): OUT.partial is closed and stays,
// with a message saying how to resume. Complete: OUT.partial is copied to OUT.tmp, the per-solver statistics
// (histograms, summary attributes) and the run's attributes are written to the copy, /batch complete = 1, and
// OUT.tmp is renamed to OUT (atomic) before OUT.partial is removed; then the summary table and the checks
// of the outcome (invalid input, -strict) on every rank.
#pragma once

#include "lcpbench_batch.hpp"
#include "lcpbench_dealer.hpp"
#include "lcpbench_options.hpp"
#include "lcpbench_store.hpp"

#include "core/run_context.hpp"

#include <string>

namespace lcpbench_app {

// What the run did, for the final messages.
struct RunSummary {
  std::string partial;  // OUT.partial
  long long ndone0 = 0; // problems done before this run
  DealOutcome deal;
};

// Collective: the dealing stopped before every problem was done.
PetscErrorCode finishInterrupted(const suite::RunContext& ctx, const Batch& b, const RunSummary& r,
                                 Store* store);

// Collective: every problem is done.
PetscErrorCode finishComplete(const suite::RunContext& ctx, const Options& o, const Batch& b,
                              const RunSummary& r, Store* store);

} // namespace lcpbench_app
