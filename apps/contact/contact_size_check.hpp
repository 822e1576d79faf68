// The contact app's sizes, checked before the scene and its dense contact problems are allocated
// (core/resource_checks.hpp): integer options within PetscInt; bodies, contacts and LCP rows within PetscInt;
// and the memory estimate (dense Delassus matrix, LCP matrix and solver workspace, the recorded frames and
// steps) against the node's limit.
#pragma once

#include "contact_options.hpp"

#include <vector>

namespace contact_app {

// Bodies (ground and walls included) and the contacts expected when they rest on each other; those of the
// largest island where the scene's islands are known (pile_grid: one pile; 0: unknown, the whole scene's).
struct SceneSize {
  double bodies = 0, contacts = 0, island_contacts = 0;
};
// A generated scene's, from its size options (bodies -1 for -scene file: known once read).
SceneSize sceneSize(const SceneParams& s);
// A built scene's, from its bodies' shapes.
SceneSize sceneSize(const std::vector<Body>& bodies);
// Collective. The integer options (PETSc wraps values beyond PetscInt silently).
PetscErrorCode checkIntegerOptions(MPI_Comm comm);
// Collective. The run's sizes for a scene of that size.
PetscErrorCode checkContactSizes(MPI_Comm comm, const AppOptions& o, const SceneSize& size);

} // namespace contact_app
