// lcpbench batch driver: options, problem source (generator family or files), dynamic load balancing of
// problem indices (rank 0 deals chunks on request, MPI point-to-point; results travel back with the next
// request), results streamed by rank 0 to OUT.partial with periodic flushes (memory bounded, resumable after a
// signal, -max_walltime or a kill; see lcpbench_run.cpp), histograms and summary at completion.
// The parts, one file each: lcpbench_options (options, -help from the registries), lcpbench_batch (problem
// source and solvers), lcpbench_resume (batch header, OUT.partial resumed or created), lcpbench_dealer (load
// balancing, flushes), lcpbench_store (the results file, summary pass), lcpbench_finalize (end of a run).
#pragma once

#include "core/run_context.hpp"

namespace lcpbench_app {
PetscErrorCode runLcpBench(const suite::RunContext& ctx);
} // namespace lcpbench_app
