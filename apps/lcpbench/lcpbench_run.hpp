// lcpbench batch driver: options, problem source (generator family or files), dynamic load balancing of
// problem indices (rank 0 deals chunks on request, MPI point-to-point; results travel back with the next
// request), results streamed by rank 0 to OUT.partial with periodic flushes (memory bounded, resumable after a
// signal, -max_walltime or a kill; see lcpbench_run.cpp), histograms and summary at completion.
#pragma once

#include "core/run_context.hpp"

namespace lcpbench_app {
PetscErrorCode runLcpBench(const suite::RunContext& ctx);
} // namespace lcpbench_app
