// lcpbench's options: one struct with every option's value, read and validated by readOptions (collective:
// every rank takes the same error path). The named choices (-family, -solvers, -fclib_model) are documented
// by -help from the registries of lib/lcp (generator families, solvers) and the FCLib models below.
#pragma once

#include "core/run_context.hpp"
#include "lcp/readers.hpp"

#include <string>
#include <vector>

namespace lcpbench_app {

struct Options {
  // problems
  std::string family = "random_box"; // a generator family of lib/lcp or "file"
  std::vector<std::string> files;    // -file, for family "file"
  std::string fclib_model = "box_friction";
  PetscInt n = 100, count = 500, seed = 1;
  PetscReal cond = 1e4, qrange = 1e2, lower = -1e2, upper = 1e2;
  // solvers
  std::vector<std::string> solvers = {"lemke", "keller",    "cottle_dantzig",  "murty",
                                      "bpp",   "fb_newton", "smoothed_newton", "pgs"};
  PetscInt max_it = 0, block_size = 3;
  PetscReal omega = 1.0, rel_tol = 1e-10;
  PetscBool refine = PETSC_TRUE;
  // the run
  std::string output;
  PetscInt chunk = 0, flush_every = 4096;
  PetscReal flush_seconds = 30.0, delay = 0.0, max_walltime = 0.0;
  PetscBool strict = PETSC_FALSE, resume = PETSC_TRUE;

  bool fromFiles() const { return family == "file"; }
};

// Reads and validates every option. *help_only: -help was given (options printed, nothing to run).
PetscErrorCode readOptions(const suite::RunContext& ctx, Options* o, bool* help_only);

// The reader model of an -fclib_model name (validated by readOptions).
suite::lcp::FclibModel fclibModel(const std::string& name);

} // namespace lcpbench_app
