// Options of the contact app: scene, stepper and output settings read through PetscOptionsBegin/End
// (so -help documents them), validated with one clear message per bad value.
#pragma once

#include "contact/scenes.hpp"
#include "contact/stepper.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace contact_app {

using namespace suite::contact;

struct AppOptions {
  SceneParams scene;
  StepperOptions step;
  PetscInt steps = 200, output_every = 10, dump_max = 1000;
  PetscReal overlap_tol = 1e-3;
  char output[PETSC_MAX_PATH_LEN] = "contact.h5";
  char dump[PETSC_MAX_PATH_LEN] = "";
};

PetscErrorCode readOptions(MPI_Comm comm, AppOptions* o);
// The model simplifications this run makes (written to the output and the log).
std::string simplifications(const AppOptions& o, const std::vector<Body>& bodies);

} // namespace contact_app
