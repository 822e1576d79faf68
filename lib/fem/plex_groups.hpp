// Groups of a DMPlex mesh: the labels that name a set of faces (a surface: supports, tractions) or of cells (a
// volume). A Gmsh physical group is a label named after the group whose one value is the group's tag
// (plex_mesh_file.hpp); the generated beam's groups "clamped" and "tip" have the value 1 (plex_beam.hpp). A
// group is given by name or by tag; -bc_fixed, -traction and the default clamp look their groups up here.
#pragma once

#include <petscdmplex.h>

#include <string>
#include <vector>

namespace suite::fem {

struct PlexGroup {
  std::string name; // the label's name
  PetscInt value = 1;
  int dim = -1; // 2: faces, 3: cells (the highest depth of its points over the ranks)
};

// Collective. The group `spec` (a label's name, or a tag: the one group with that value) of dimension dim
// (2 or 3). Errors name `option`, the group and the groups the mesh has (with their tags and dimensions) when
// there is no such group, when a tag names several, and when the group has another dimension.
PetscErrorCode findGroup(DM dm, const std::string& spec, int dim, const char* option, PlexGroup* g);
// Collective. Every group of the mesh with its value and dimension (the values and depths reduced over the
// ranks); findGroupIn looks `spec` up in such a list (the same errors as findGroup; collective: every rank
// holds the same list).
PetscErrorCode listGroups(DM dm, std::vector<PlexGroup>* groups);
PetscErrorCode findGroupIn(MPI_Comm comm, const std::vector<PlexGroup>& groups, const std::string& spec,
                           int dim, const char* option, PlexGroup* g);
// Collective. True when the mesh has a group named `name` (a label other than DMPlex's own).
PetscErrorCode hasGroup(DM dm, const std::string& name, bool* has);
// Collective. A new group `name` (value 1): the boundary faces whose vertices all lie within tol of x = x0.
PetscErrorCode markPlaneFaces(DM dm, const char* name, double x0, double tol);
// The local faces (height 1) of a group.
PetscErrorCode groupFaces(DM dm, const PlexGroup& g, std::vector<PetscInt>* faces);
// The largest x coordinate of the mesh (collective).
PetscErrorCode meshMaxX(DM dm, double* xmax);

} // namespace suite::fem
