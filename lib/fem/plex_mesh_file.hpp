// A user's mesh file as a distributed DMPlex: Gmsh .msh (2.2 or 4.1, ASCII or binary) read by PETSc's DMPlex
// reader (DMPlexCreateFromFile) on rank 0, checked, then distributed by the partitioner (PT-Scotch unless
// -petscpartitioner_type says otherwise; DMPlexDistribute, no overlap). Gmsh's physical groups become labels
// named after the groups (-dm_plex_gmsh_use_regions), each with the group's tag as its one value; the groups
// are looked up by name or tag in plex_groups.hpp. The natural node numbering is the file's node order (the
// reader's vertex order on rank 0, carried through the distribution by the migration SF), so output and
// checkpoints do not depend on the partition. P1 (4-node) tetrahedra only.
#pragma once

#include <petscdmplex.h>

#include <string>
#include <vector>

namespace suite::fem {

struct PlexFileMesh {
  DM dm = nullptr;                   // owned by the caller
  long long nodes = 0;               // vertices in the file
  std::vector<PetscInt> vertex_node; // [v - vStart]: the file's node number (from 0) of each local vertex
};

// Collective. Errors (one, naming the file) when the file cannot be read or parsed (PETSc's reader's message
// is quoted), when its cells are not 4-node tetrahedra, when a tetrahedron is degenerate or inverted (signed
// volume <= 0 in the file's node order), and (naming -plex_rank_cap) when rank_cap > 0 and a rank would hold
// more mesh points than rank_cap before or after distribution.
// A path ending in .h5 is read as the suite's parallel mesh file (plex_mesh_h5.hpp).
PetscErrorCode createPlexFromFile(MPI_Comm comm, const std::string& path, long long rank_cap,
                                  PlexFileMesh* mesh);
// Why this rank's part of a mesh is not one the plex path takes ("" when it is): not 3-D, a cell not a 4-node
// tetrahedron, second-order coordinates, a degenerate or inverted tetrahedron (in DMPlex's orientation).
PetscErrorCode unsupportedCells(DM dm, std::string* why);
// The node numbers `before` of the vertices of `serial` (index v - vStart), carried to the vertices of `dist`
// (the DM that DMPlexDistribute made from it) along the migration SF.
PetscErrorCode carryVertexNumbers(const std::vector<PetscInt>& before, DM serial, DM dist, PetscSF migration,
                                  std::vector<PetscInt>* node);

} // namespace suite::fem
