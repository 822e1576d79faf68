// Options of the contact app: scene, stepper and output settings read through PetscOptionsBegin/End
// (so -help documents them), validated with one clear message per bad value.
#pragma once

#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <petscsys.h>

#include <string>

namespace contact_app {

using namespace suite::contact;

// The options given on the command line that a model file's settings would otherwise set (-scene mjcf).
struct ModelOverrides {
  bool dt = false, gravity = false, mu = false;
};

struct AppOptions {
  SceneParams scene;
  ModelOverrides given;
  StepperOptions step;
  PetscInt steps = 200, output_every = 10, dump_max = 1000;
  PetscReal overlap_tol = 1e-3;
  std::string output, dump; // dump: -dump_problems prefix ("": none)
  std::string write_mjcf;   // -write_mjcf: the model written as MJCF, no steps
  bool phase_times = false; // -contact_phase_times: each rank's time per phase at the end
};

PetscErrorCode readOptions(MPI_Comm comm, AppOptions* o);

} // namespace contact_app
