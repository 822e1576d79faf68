// The suite's parallel mesh file: a distributed DMPlex of P1 tetrahedra with its groups, written once from any
// mesh the plex path reads (femdyn -mesh_convert) and read back at any rank count with each rank reading one
// block of cells and one block of vertices (parallel HDF5), built into a DMPlex from those blocks
// (DMPlexCreateFromCellListParallelPetsc, as the generated beam) and repartitioned: no rank reads the whole
// mesh. PETSc 3.18's own DMPlex HDF5 format is read in parallel too, but DMPlexTopologyLoad builds the mesh on
// rank 0 (measured: every point on rank 0 at 2, 3 and 4 ranks), so it does not serve meshes too large for one
// rank. Layout (natural node numbers: the numbering the mesh was read with):
//   root attribute format = "suite plex mesh 1";
//   /mesh/coordinates {nodes, 3} (m), /mesh/tets {cells, 4} (natural node numbers, in DMPlex's orientation);
//   /groups/<name>/faces {n, 3} (the natural nodes of each face of a surface group) or /groups/<name>/cells
//   {n} (rows of /mesh/tets of a volume group), each with the attributes tag and dim.
// A rank reads every group's faces (a surface: O(N^(2/3)) entries) and labels the faces of its cells.
#pragma once

#include "fem/plex_mesh_file.hpp"
#include "fem/plex_natural.hpp"

#include <string>

namespace suite {
class RunContext;
} // namespace suite

namespace suite::fem {

// Collective. dm: a distributed mesh with its natural numbering (nat: setupLayout at least) and groups.
PetscErrorCode writePlexMeshH5(DM dm, const PlexNaturalOrder& nat, const RunContext& ctx,
                               const std::string& path);
// Collective. Errors naming the file when it is not such a file, when a cell names a node out of range, when
// a cell is degenerate or inverted, and (-plex_rank_cap) when a rank would hold more than rank_cap points.
PetscErrorCode createPlexFromH5(MPI_Comm comm, const std::string& path, long long rank_cap,
                                PlexFileMesh* mesh);

} // namespace suite::fem
