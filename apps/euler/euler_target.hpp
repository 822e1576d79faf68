// The Euler app's accuracy-target mode (-target_error E, -target_walltime S): the candidate families are the
// schemes of -target_schemes with the explicit SSP-RK3 integrator, the resolution n is -nx (2D/3D: -ny, -nz
// keep the aspect ratio of the grid the options give); the model_choice library's chooser runs the pilots and
// the chosen candidate in this process (EulerRun, one at a time, every rank taking the same decisions) and the
// final run's output file gets /model_choice (lib/model_choice/choice_output.hpp).
#pragma once

#include "core/run_context.hpp"

#include <petscsys.h>

#include <string>

namespace euler_app {

struct TargetOptions {
  double error = 0.0, walltime = 0.0, safety = 2.0;
  PetscInt pilot_n = 0, max_n = 0, escalations = 4; // 0: the dimension's default
  std::string schemes = "enopade6,crweno5,weno5,muscl2", cost_model;
  bool on() const { return error > 0.0 || walltime > 0.0; }
};

// Reads and checks the -target_* options and -cost_model (documented under -help).
PetscErrorCode readTargetOptions(MPI_Comm comm, int dim, TargetOptions* t);

// The accuracy-target run: pilots, choice, final run(s), /model_choice, the summary line.
PetscErrorCode runTargetEuler(const suite::RunContext& ctx, int dim, const TargetOptions& t);

} // namespace euler_app
