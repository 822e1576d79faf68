// The contact app's run: setup, time stepping with the chosen friction model and LCP solver, output.
#pragma once

#include "core/run_context.hpp"

namespace contact_app {
PetscErrorCode run(suite::RunContext& ctx);
} // namespace contact_app
