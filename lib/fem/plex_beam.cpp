// The beam as a distributed DMPlex (see plex_beam.hpp).
#include "fem/plex_beam.hpp"

#include "fem/plex_groups.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace suite::fem {

namespace {

// This rank's slab: hexahedra c0 .. c1-1 and vertex planes p0 .. p1-1 along x (the last rank owns plane nx).
struct Slab {
  int c0, c1, p0, p1;
};

Slab slabOf(int nx, int rank, int size) {
  const int c0 = (int)((long long)nx * rank / size), c1 = (int)((long long)nx * (rank + 1) / size);
  return {c0, c1, c0, rank == size - 1 ? nx + 1 : c1};
}

// Global vertex number of grid point (i, j, k): plane by plane along x, so that a slab's planes are one block.
struct VertexNumbering {
  int ny, nz;
  PetscInt operator()(int i, int j, int k) const {
    return (PetscInt)i * (ny + 1) * (nz + 1) + j + (PetscInt)(ny + 1) * k;
  }
};

void slabVertices(const BeamSpec& s, const Slab& sl, std::vector<PetscReal>* xyz) {
  const int ny = s.cells[1], nz = s.cells[2];
  const double h[3] = {s.length / s.cells[0], s.size[0] / ny, s.size[1] / nz};
  for (int i = sl.p0; i < sl.p1; ++i)
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j) {
        xyz->push_back(i * h[0]);
        xyz->push_back(j * h[1]);
        xyz->push_back(k * h[2]);
      }
}

// The 6 tets of each hexahedron of the slab, as makeBeam orders and orients them, then with two vertices
// swapped: DMPlex's reference tetrahedron has the opposite orientation (its first face's normal points inward).
void slabTets(const BeamSpec& s, const Slab& sl, std::vector<PetscInt>* cells) {
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int ny = s.cells[1], nz = s.cells[2];
  const double h[3] = {s.length / s.cells[0], s.size[0] / ny, s.size[1] / nz};
  const VertexNumbering id{ny, nz};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = sl.c0; i < sl.c1; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          PetscInt t[4];
          std::array<double, 3> x[4];
          t[0] = id(c[0], c[1], c[2]);
          x[0] = {c[0] * h[0], c[1] * h[1], c[2] * h[2]};
          for (int q = 0; q < 3; ++q) {
            ++c[p[q]];
            t[q + 1] = id(c[0], c[1], c[2]);
            x[q + 1] = {c[0] * h[0], c[1] * h[1], c[2] * h[2]};
          }
          if (tetSignedVolume(x[0], x[1], x[2], x[3]) < 0) std::swap(t[2], t[3]);
          std::swap(t[1], t[2]); // DMPlex orientation
          cells->insert(cells->end(), t, t + 4);
        }
}

} // namespace

PetscErrorCode distributePlex(DM* dm, PetscSF* migration) {
  PetscPartitioner part;
  DM dist = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERPTSCOTCH));
  PetscCall(PetscPartitionerSetFromOptions(part));
  PetscCall(DMPlexDistribute(*dm, 0, migration, &dist));
  if (dist) {
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkRankCapCount(MPI_Comm comm, long long count, long long rank_cap, const char* what,
                                 const char* when) {
  long long most = 0;
  PetscFunctionBeginUser;
  if (rank_cap <= 0) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Allreduce(&count, &most, 1, MPI_LONG_LONG, MPI_MAX, comm));
  PetscCheck(most <= rank_cap, comm, PETSC_ERR_MEM, "a rank holds %lld %s %s, above -plex_rank_cap %lld",
             most, what, when, rank_cap);
  PetscFunctionReturn(0);
}

PetscErrorCode checkRankCap(DM dm, long long rank_cap, const char* when) {
  PetscInt p0, p1;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &p0, &p1));
  PetscCall(checkRankCapCount(PetscObjectComm((PetscObject)dm), (long long)(p1 - p0), rank_cap, "mesh points",
                              when));
  PetscFunctionReturn(0);
}

PetscErrorCode createPlexBeam(MPI_Comm comm, const BeamSpec& spec, long long rank_cap, DM* dm) {
  int rank = 0, size = 1;
  PetscFunctionBeginUser;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  PetscCheck(
      spec.cells[0] >= size, comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-beam_cells: %d hexahedra along x for %d ranks: the distributed beam needs at least one per rank",
      spec.cells[0], size);
  const Slab sl = slabOf(spec.cells[0], rank, size);
  const long long plane = (long long)(spec.cells[1] + 1) * (spec.cells[2] + 1);
  const long long slab_points =
      6LL * (sl.c1 - sl.c0) * spec.cells[1] * spec.cells[2] + plane * (sl.p1 - sl.p0);
  PetscCall(checkRankCapCount(comm, slab_points, rank_cap, "cells and vertices",
                              "in its slab of the generated beam"));
  std::vector<PetscReal> xyz;
  std::vector<PetscInt> cells;
  slabVertices(spec, sl, &xyz);
  slabTets(spec, sl, &cells);
  const PetscInt ncell = (PetscInt)(cells.size() / 4), nvert = (PetscInt)(xyz.size() / 3);
  PetscSF sf = nullptr;
  PetscCall(DMPlexCreateFromCellListParallelPetsc(comm, 3, ncell, nvert, PETSC_DECIDE, 4, PETSC_TRUE,
                                                  cells.data(), 3, xyz.data(), &sf, nullptr, dm));
  PetscCall(PetscSFDestroy(&sf));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "beam"));
  PetscCall(checkRankCap(*dm, rank_cap, "before distribution"));
  if (size > 1) PetscCall(distributePlex(dm, nullptr));
  PetscCall(checkRankCap(*dm, rank_cap, "after distribution"));
  PetscCall(markPlaneFaces(*dm, "clamped", 0.0, 1e-9 * spec.length));
  PetscCall(markPlaneFaces(*dm, "tip", spec.length, 1e-9 * spec.length));
  PetscFunctionReturn(0);
}

PetscErrorCode ownedFreeVertices(DM dm, std::vector<FreeVertex>* out) {
  PetscSection gs, cs;
  Vec coords;
  const PetscScalar* cx;
  PetscInt v0, v1;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(VecGetArrayRead(coords, &cx));
  out->clear();
  for (PetscInt v = v0; v < v1; ++v) {
    PetscInt goff, dof, cdof, off;
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    PetscCall(PetscSectionGetDof(gs, v, &dof));
    PetscCall(PetscSectionGetConstraintDof(gs, v, &cdof));
    if (goff < 0 || dof - cdof != 3) continue; // a ghost, or clamped
    PetscCall(PetscSectionGetOffset(cs, v, &off));
    out->push_back({goff, {PetscRealPart(cx[off]), PetscRealPart(cx[off + 1]), PetscRealPart(cx[off + 2])}});
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscFunctionReturn(0);
}

PetscErrorCode plexGlobalSizes(DM dm, long long* vertices, long long* cells) {
  IS numbering;
  PetscInt v0, v1, c0, c1, nv;
  const PetscInt* idx;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(DMPlexGetVertexNumbering(dm, &numbering));
  PetscCall(ISGetLocalSize(numbering, &nv));
  PetscCall(ISGetIndices(numbering, &idx));
  long long local[2] = {0, (long long)(c1 - c0)};
  for (PetscInt i = 0; i < nv; ++i) local[0] += idx[i] >= 0;
  PetscCall(ISRestoreIndices(numbering, &idx));
  long long global[2];
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_LONG_LONG, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  *vertices = global[0];
  *cells = global[1];
  PetscFunctionReturn(0);
}

} // namespace suite::fem
