// The contact app's sizes, checked before the scene and its dense contact problems are allocated
// (core/resource_checks.hpp): integer options within PetscInt; bodies, contacts and LCP rows within PetscInt;
// and the memory estimate (dense Delassus matrix, LCP matrix and solver workspace, the recorded frames and
// steps) against the node's limit.
#pragma once

#include "contact_options.hpp"

namespace contact_app {

// Bodies of a generated scene from its size options (-1 for -scene file: known once read).
double sceneBodyCount(const SceneParams& s);
// Collective. The integer options (PETSc wraps values beyond PetscInt silently).
PetscErrorCode checkIntegerOptions(MPI_Comm comm);
// Collective. The run's sizes for `bodies` bodies (the bodies of the scene, ground and walls included).
PetscErrorCode checkContactSizes(MPI_Comm comm, const AppOptions& o, double bodies);

} // namespace contact_app
