// The structured beam of fem::makeBeam (mesh.hpp: 6 tets per hexahedron, Kuhn/Freudenthal split) as a
// distributed DMPlex, generated in parallel: each rank creates the tets of its slab of hexahedra along x and the
// vertices of its slab of planes (DMPlexCreateFromCellListParallelPetsc), so that no rank ever holds the whole
// mesh; then the mesh is repartitioned by the DM's partitioner (PT-Scotch unless -petscpartitioner_type says
// otherwise) with DMPlexDistribute, without overlap (FE assembly on DMPlex sums the shared vertices' entries).
// Labels (plex_groups.hpp): the groups "clamped" (value 1: the faces on x = 0) and "tip" (value 1: the faces
// on x = length).
#pragma once

#include "fem/mesh.hpp"

#include <petscdmplex.h>
#include <petscsf.h>

#include <vector>

namespace suite::fem {

// Collective. Errors (naming -beam_cells) when the beam has fewer hexahedra along x than there are ranks, and
// (naming -plex_rank_cap) when rank_cap > 0 and a rank would hold more than rank_cap mesh points: its slab's
// cells and vertices (checked before they are allocated), its part of the mesh before and after distribution.
PetscErrorCode createPlexBeam(MPI_Comm comm, const BeamSpec& spec, long long rank_cap, DM* dm);
// Repartitions *dm (PT-Scotch unless -petscpartitioner_type says otherwise), without overlap; *migration (may
// be null) gets the migration SF (roots: the points before, leaves: the points after).
PetscErrorCode distributePlex(DM* dm, PetscSF* migration);
// The largest of the ranks' counts (of `what`) above rank_cap (> 0): a collective error naming `what` and `when`.
PetscErrorCode checkRankCapCount(MPI_Comm comm, long long count, long long rank_cap, const char* what,
                                 const char* when);
// The largest count of mesh points over the ranks above rank_cap (> 0): a collective error naming `when`.
PetscErrorCode checkRankCap(DM dm, long long rank_cap, const char* when);

// The vertices this rank owns whose 3 DOFs are free (not clamped) once the DM has its section: the offset of
// their first DOF in the global vector and their coordinates.
struct FreeVertex {
  PetscInt goff;
  double x[3];
};
PetscErrorCode ownedFreeVertices(DM dm, std::vector<FreeVertex>* out);

// Sum over the ranks of the vertices each owns (the global node count) and of the local cells.
PetscErrorCode plexGlobalSizes(DM dm, long long* vertices, long long* cells);

} // namespace suite::fem
