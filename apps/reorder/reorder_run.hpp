// The reorder run: read the matrix, time each requested ordering, table on stdout, HDF5 groups per ordering.
#pragma once

#include "core/run_context.hpp"

namespace reorder_app {
PetscErrorCode runReorder(const suite::RunContext& ctx);
} // namespace reorder_app
