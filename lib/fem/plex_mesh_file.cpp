// A Gmsh file as a distributed DMPlex (see plex_mesh_file.hpp).
#include "fem/plex_mesh_file.hpp"

#include "core/error_handler.hpp"
#include "fem/mesh.hpp"
#include "fem/plex_beam.hpp"
#include "fem/plex_mesh_h5.hpp"

#include <petscsf.h>

#include <array>
#include <cstring>

namespace suite::fem {

namespace {

// PETSc's first error message, kept instead of printed: the reader runs on rank 0 alone, and its errors become
// one collective error naming the file.
PetscErrorCode captureError(MPI_Comm, int, const char*, const char*, PetscErrorCode n, PetscErrorType p,
                            const char* mess, void* ctx) {
  auto* text = static_cast<std::string*>(ctx);
  if (p == PETSC_ERROR_INITIAL && text->empty()) {
    const char* generic = nullptr;
    PetscErrorMessage(n, &generic, nullptr);
    *text = mess && mess[0] ? mess : (generic ? generic : "unknown error");
  }
  return n;
}

// DMPlexCreateFromFile on `comm` with the errors captured into *error (empty on success).
PetscErrorCode readCaptured(MPI_Comm comm, const std::string& path, DM* dm, std::string* error) {
  PetscFunctionBeginUser;
  error->clear();
  PetscCall(PetscPushErrorHandler(captureError, error));
  const PetscErrorCode ierr = DMPlexCreateFromFile(comm, path.c_str(), "mesh", PETSC_TRUE, dm);
  PetscCall(PetscPopErrorHandler());
  if (ierr && error->empty()) *error = "unknown error";
  if (ierr) *dm = nullptr;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode unsupportedCells(DM dm, std::string* why) {
  PetscInt dim, c0, c1, v0, v1;
  PetscFunctionBeginUser;
  why->clear();
  PetscCall(DMGetDimension(dm, &dim));
  if (dim != 3) {
    *why = "a " + std::to_string(dim) + "-D mesh: the plex path takes 3-D tetrahedral meshes";
    PetscFunctionReturn(0);
  }
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  Vec coords;
  PetscSection cs;
  const PetscScalar* cx;
  PetscInt ncoord;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(VecGetLocalSize(coords, &ncoord));
  if (ncoord != 3 * (v1 - v0)) { // coordinates beyond the vertices': the reader's high-order geometry
    *why = "second-order (10-node) tetrahedra: the plex path takes 4-node P1 tetrahedra (use the replicated "
           "path, -backend replicated, for P2 meshes)";
    PetscFunctionReturn(0);
  }
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt c = c0; c < c1 && why->empty(); ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (ct != DM_POLYTOPE_TETRAHEDRON) {
      *why = "element " + std::to_string(c - c0 + 1) + " is a " + DMPolytopeTypes[ct] +
             ": the plex path takes 4-node tetrahedra";
      break;
    }
    PetscInt n = 0, *pts = nullptr, nv = 0;
    std::array<double, 3> x[4];
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < 2 * n; i += 2) {
      if (pts[i] < v0 || pts[i] >= v1 || nv == 4) continue;
      PetscInt off;
      PetscCall(PetscSectionGetOffset(cs, pts[i], &off));
      x[nv++] = {PetscRealPart(cx[off]), PetscRealPart(cx[off + 1]), PetscRealPart(cx[off + 2])};
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    // The reader orients each cell as DMPlex's reference tetrahedron, whose closure has negative signed
    // volume: a positive one was listed inverted in the file, a zero one is degenerate.
    const double v = -tetSignedVolume(x[0], x[1], x[2], x[3]);
    if (!(v > 0.0))
      *why = "tetrahedron " + std::to_string(c - c0 + 1) + " (in the file's element order) is " +
             (v == 0.0 ? "degenerate (zero volume)" : "inverted (negative volume in the file's node order)");
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscFunctionReturn(0);
}

// The file's node number of each vertex of the distributed mesh, broadcast from the serial mesh (rank 0: its
// vertex order, the file's) along the migration SF.
PetscErrorCode carryVertexNumbers(const std::vector<PetscInt>& before, DM serial, DM dist, PetscSF migration,
                                  std::vector<PetscInt>* node) {
  PetscInt p0, p1, v0, v1, q0, q1, w0, w1;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(serial, &p0, &p1));
  PetscCall(DMPlexGetDepthStratum(serial, 0, &v0, &v1));
  PetscCall(DMPlexGetChart(dist, &q0, &q1));
  PetscCall(DMPlexGetDepthStratum(dist, 0, &w0, &w1));
  PetscCheck(p0 == 0 && q0 == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a DMPlex chart that does not start at 0");
  std::vector<PetscInt> root((size_t)p1, -1), leaf((size_t)q1, -1);
  for (PetscInt v = v0; v < v1; ++v) root[(size_t)v] = before[(size_t)(v - v0)];
  PetscCall(PetscSFBcastBegin(migration, MPIU_INT, root.data(), leaf.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(migration, MPIU_INT, root.data(), leaf.data(), MPI_REPLACE));
  node->assign(leaf.begin() + w0, leaf.begin() + w1);
  PetscFunctionReturn(0);
}

PetscErrorCode createPlexFromFile(MPI_Comm comm, const std::string& path, long long rank_cap,
                                  PlexFileMesh* mesh) {
  int rank = 0, size = 1;
  std::string error;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  auto ends = [&](const char* ext) {
    const size_t n = std::strlen(ext);
    return path.size() > n && path.compare(path.size() - n, n, ext) == 0;
  };
  if (ends(".h5")) {
    PetscCall(createPlexFromH5(comm, path, rank_cap, mesh));
    PetscFunctionReturn(0);
  }
  PetscCheck(ends(".msh"), comm, PETSC_ERR_SUP,
             "-mesh_file %s: -backend plex reads Gmsh .msh files and the suite's .h5 meshes (-mesh_convert; "
             "TetGen input: -backend replicated)",
             path.c_str());
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-dm_plex_gmsh_use_regions", &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, "-dm_plex_gmsh_use_regions", "true"));
  // The reader runs on rank 0 and raises its errors there alone: with more ranks it first reads the file
  // there by itself (errors captured), so that every rank takes the same error path. The cost: one more
  // read of the file on rank 0.
  if (size > 1) {
    DM probe = nullptr;
    if (rank == 0) PetscCall(readCaptured(PETSC_COMM_SELF, path, &probe, &error));
    if (probe) PetscCall(DMDestroy(&probe));
    PetscCall(agreeOnFailure(comm, &error));
  }
  DM dm = nullptr;
  if (error.empty()) PetscCall(readCaptured(comm, path, &dm, &error));
  PetscCall(agreeOnFailure(comm, &error));
  PetscCheck(error.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "-mesh_file %s: PETSc's mesh reader: %s",
             path.c_str(), error.c_str());
  PetscCall(unsupportedCells(dm, &error));
  PetscCall(agreeOnFailure(comm, &error));
  if (!error.empty()) PetscCall(DMDestroy(&dm));
  PetscCheck(error.empty(), comm, PETSC_ERR_SUP, "-mesh_file %s: %s", path.c_str(), error.c_str());
  PetscCall(PetscObjectSetName((PetscObject)dm, "mesh"));
  PetscCall(checkRankCap(dm, rank_cap, "before distribution (rank 0 reads the whole file)"));
  PetscInt v0, v1;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  mesh->nodes = v1 - v0;
  PetscCallMPI(MPI_Bcast(&mesh->nodes, 1, MPI_LONG_LONG, 0, comm));
  if (size == 1) {
    mesh->vertex_node.resize((size_t)(v1 - v0));
    for (PetscInt v = v0; v < v1; ++v) mesh->vertex_node[(size_t)(v - v0)] = v - v0;
  } else {
    DM serial = dm;
    PetscSF migration = nullptr;
    PetscCall(PetscObjectReference((PetscObject)serial));
    PetscCall(distributePlex(&dm, &migration));
    std::vector<PetscInt> order((size_t)(v1 - v0));
    for (PetscInt v = v0; v < v1; ++v) order[(size_t)(v - v0)] = v - v0;
    PetscCall(carryVertexNumbers(order, serial, dm, migration, &mesh->vertex_node));
    PetscCall(PetscSFDestroy(&migration));
    PetscCall(DMDestroy(&serial));
  }
  PetscCall(checkRankCap(dm, rank_cap, "after distribution"));
  mesh->dm = dm;
  PetscFunctionReturn(0);
}

} // namespace suite::fem
