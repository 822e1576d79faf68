// lcpbench batch driver: options, problem source (generator family or files), dynamic load balancing of
// problem indices (rank 0 deals chunks on request, MPI point-to-point; results travel back with the next
// request), HDF5 results and summary.
#pragma once

#include "core/run_context.hpp"

namespace lcpbench_app {
PetscErrorCode runLcpBench(const suite::RunContext& ctx);
} // namespace lcpbench_app
