// The suite's parallel mesh file (see plex_mesh_h5.hpp).
#include "fem/plex_mesh_h5.hpp"

#include "core/error_handler.hpp"
#include "fem/plex_beam.hpp"
#include "fem/plex_groups.hpp"
#include "io/h5_input.hpp"
#include "io/h5_output.hpp"

#include <petscsf.h>

#include <algorithm>
#include <array>
#include <set>

namespace suite::fem {

namespace {

using ull = unsigned long long;
const char* const kFormat = "suite plex mesh 1";

// owned[p - p0]: this rank owns point p (it is not a leaf of the point SF).
PetscErrorCode ownedPoints(DM dm, std::vector<char>* owned) {
  PetscSF sf;
  PetscInt p0, p1, nleaves;
  const PetscInt* ilocal;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &p0, &p1));
  owned->assign((size_t)(p1 - p0), 1);
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &ilocal, nullptr));
  for (PetscInt i = 0; i < nleaves; ++i) (*owned)[(size_t)((ilocal ? ilocal[i] : i) - p0)] = 0;
  PetscFunctionReturn(0);
}

// The vertices of point p (a cell or a face), in closure order.
PetscErrorCode closureVertices(DM dm, PetscInt p, PetscInt v0, PetscInt v1, std::vector<PetscInt>* vert) {
  PetscInt n = 0, *pts = nullptr;
  PetscFunctionBeginUser;
  vert->clear();
  PetscCall(DMPlexGetTransitiveClosure(dm, p, PETSC_TRUE, &n, &pts));
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (pts[i] >= v0 && pts[i] < v1) vert->push_back(pts[i]);
  PetscCall(DMPlexRestoreTransitiveClosure(dm, p, PETSC_TRUE, &n, &pts));
  PetscFunctionReturn(0);
}

// This rank's offset in a distributed list of `count` rows and the global row count.
PetscErrorCode rowBlock(MPI_Comm comm, ull count, ull* start, ull* total) {
  PetscFunctionBeginUser;
  *start = 0;
  PetscCallMPI(MPI_Exscan(&count, start, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  int rank;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) *start = 0;
  PetscCallMPI(MPI_Allreduce(&count, total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

// /groups/<name>: a surface's owned faces as natural node triples, a volume's cells as rows of /mesh/tets.
PetscErrorCode writeGroup(H5Output& out, DM dm, const PlexNaturalOrder& nat, const PlexGroup& g, ull cstart) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt p0, p1, v0, v1, c0, c1;
  std::vector<char> owned;
  IS pts = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &p0, &p1));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(ownedPoints(dm, &owned));
  PetscCall(DMGetStratumIS(dm, g.name.c_str(), g.value, &pts));
  PetscInt n = 0;
  const PetscInt* p = nullptr;
  if (pts) PetscCall(ISGetLocalSize(pts, &n));
  if (pts) PetscCall(ISGetIndices(pts, &p));
  std::vector<long long> rows;
  std::vector<PetscInt> vert;
  for (PetscInt i = 0; i < n; ++i) {
    if (g.dim == 3 && p[i] >= c0 && p[i] < c1) rows.push_back((long long)(cstart + (ull)(p[i] - c0)));
    PetscInt h;
    PetscCall(DMPlexGetPointHeight(dm, p[i], &h));
    if (g.dim != 2 || h != 1 || !owned[(size_t)(p[i] - p0)]) continue;
    PetscCall(closureVertices(dm, p[i], v0, v1, &vert));
    for (PetscInt v : vert) rows.push_back(nat.vertexNode(v));
  }
  if (pts) PetscCall(ISRestoreIndices(pts, &p));
  PetscCall(ISDestroy(&pts));
  const ull width = g.dim == 2 ? 3 : 1, mine = rows.size() / width;
  ull start, total;
  PetscCall(rowBlock(comm, mine, &start, &total));
  const std::string base = "/groups/" + g.name;
  if (g.dim == 2)
    PetscCall(out.writeDistributed(base + "/faces", rows.data(), {total, 3}, {start, 0}, {mine, 3}, ""));
  else
    PetscCall(out.writeDistributed(base + "/cells", rows.data(), {total}, {start}, {mine}, ""));
  PetscCall(out.writeAttribute(base, "tag", (long long)g.value));
  PetscCall(out.writeAttribute(base, "dim", (long long)g.dim));
  PetscFunctionReturn(0);
}

// Labels the local faces (cells) of the file's groups: a face whose natural nodes form one of the group's
// triples, a cell whose row is in the group's list (rows cstart.. are this rank's cells, in order).
PetscErrorCode readGroups(const H5Input& in, DM dm, const std::vector<PetscInt>& node, long long cstart) {
  bool has = false;
  std::vector<std::string> names;
  PetscInt v0, v1, f0, f1, c0, c1;
  PetscFunctionBeginUser;
  PetscCall(in.hasObject("/groups", &has));
  if (!has) PetscFunctionReturn(0);
  PetscCall(in.groupMembers("/groups", &names));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f0, &f1));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  for (const std::string& name : names) {
    const std::string base = "/groups/" + name;
    long long tag = 0, dim = 0;
    std::vector<long long> rows;
    Dims dims;
    PetscCall(in.readAttribute(base, "tag", &tag));
    PetscCall(in.readAttribute(base, "dim", &dim));
    PetscCheck(dim == 2 || dim == 3, PetscObjectComm((PetscObject)dm), PETSC_ERR_FILE_UNEXPECTED,
               "-mesh_file %s: group %s has dimension %lld (2 or 3 expected)", in.path().c_str(),
               name.c_str(), dim);
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(in.readAll(base + (dim == 2 ? "/faces" : "/cells"), &rows, &dims));
    if (dim == 3) {
      for (long long r : rows)
        if (r >= cstart && r < cstart + (c1 - c0))
          PetscCall(DMSetLabelValue(dm, name.c_str(), c0 + (PetscInt)(r - cstart), (PetscInt)tag));
      continue;
    }
    std::set<std::array<long long, 3>> faces;
    for (size_t i = 0; i + 2 < rows.size(); i += 3) {
      std::array<long long, 3> t = {rows[i], rows[i + 1], rows[i + 2]};
      std::sort(t.begin(), t.end());
      faces.insert(t);
    }
    std::vector<PetscInt> vert;
    for (PetscInt f = f0; f < f1; ++f) {
      PetscCall(closureVertices(dm, f, v0, v1, &vert));
      if (vert.size() != 3) continue;
      std::array<long long, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = node[(size_t)(vert[k] - v0)];
      std::sort(t.begin(), t.end());
      if (faces.count(t)) PetscCall(DMSetLabelValue(dm, name.c_str(), f, (PetscInt)tag));
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode writePlexMeshH5(DM dm, const PlexNaturalOrder& nat, const RunContext& ctx,
                               const std::string& path) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  H5Output out;
  std::vector<double> xyz;
  std::vector<PlexGroup> groups;
  PetscInt c0, c1, v0, v1;
  PetscFunctionBeginUser;
  PetscCall(nat.coordinates(&xyz));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  std::vector<long long> tets;
  std::vector<PetscInt> vert;
  for (PetscInt c = c0; c < c1; ++c) {
    PetscCall(closureVertices(dm, c, v0, v1, &vert));
    for (PetscInt v : vert) tets.push_back(nat.vertexNode(v));
  }
  ull cstart, cells;
  PetscCall(rowBlock(comm, (ull)(c1 - c0), &cstart, &cells));
  PetscCall(listGroups(dm, &groups));
  PetscCall(out.open(comm, path));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(out.writeAttribute("/", "format", kFormat));
  PetscCall(out.writeDistributed("/mesh/coordinates", xyz.data(), {(ull)nat.nodes(), 3}, {(ull)nat.row0(), 0},
                                 {(ull)nat.rows(), 3}, "m"));
  PetscCall(
      out.writeDistributed("/mesh/tets", tets.data(), {cells, 4}, {cstart, 0}, {(ull)(c1 - c0), 4}, ""));
  for (const PlexGroup& g : groups)
    if (g.dim == 2 || g.dim == 3) PetscCall(writeGroup(out, dm, nat, g, cstart));
  PetscCall(out.commit(&ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode createPlexFromH5(MPI_Comm comm, const std::string& path, long long rank_cap,
                                PlexFileMesh* mesh) {
  H5Input in;
  std::string format;
  bool has = false;
  Dims dc, dt;
  int rank = 0, size = 1;
  PetscFunctionBeginUser;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  PetscCall(in.open(comm, path));
  PetscCall(in.hasAttribute("/", "format", &has));
  if (has) PetscCall(in.readAttribute("/", "format", &format));
  PetscCheck(format == kFormat, comm, PETSC_ERR_FILE_UNEXPECTED,
             "-mesh_file %s: not a mesh written by -mesh_convert (root attribute format \"%s\" expected)",
             path.c_str(), kFormat);
  PetscCall(in.datasetDims("/mesh/coordinates", &dc));
  PetscCall(in.datasetDims("/mesh/tets", &dt));
  PetscCheck(dc.size() == 2 && dc[1] == 3 && dt.size() == 2 && dt[1] == 4 && dc[0] >= 4 && dt[0] >= 1 &&
                 dc[0] < (ull)PETSC_MAX_INT && dt[0] < (ull)PETSC_MAX_INT / 4,
             comm, PETSC_ERR_FILE_UNEXPECTED,
             "-mesh_file %s: /mesh/coordinates must be {nodes, 3} and /mesh/tets {cells, 4} (nodes >= 4, "
             "32-bit counts)",
             path.c_str());
  PetscCall(in.checkPlausibleSize("/mesh/coordinates", dc, sizeof(double)));
  PetscCall(in.checkPlausibleSize("/mesh/tets", dt, sizeof(int)));
  const ull nv = dc[0], nc = dt[0];
  const ull c_lo = nc * (ull)rank / (ull)size, c_hi = nc * (ull)(rank + 1) / (ull)size;
  const ull v_lo = nv * (ull)rank / (ull)size, v_hi = nv * (ull)(rank + 1) / (ull)size;
  PetscCall(checkRankCapCount(comm, (long long)(c_hi - c_lo + v_hi - v_lo), rank_cap, "cells and vertices",
                              "in its block of the mesh file"));
  std::vector<long long> t(4 * (c_hi - c_lo));
  std::vector<double> x(3 * (v_hi - v_lo));
  PetscCall(in.readBlock("/mesh/tets", {c_lo, 0}, {c_hi - c_lo, 4}, t.data()));
  PetscCall(in.readBlock("/mesh/coordinates", {v_lo, 0}, {v_hi - v_lo, 3}, x.data()));
  long long bad = -1;
  for (size_t i = 0; i < t.size() && bad < 0; ++i)
    if (t[i] < 0 || (ull)t[i] >= nv) bad = (long long)(c_lo + i / 4);
  long long worst;
  PetscCallMPI(MPI_Allreduce(&bad, &worst, 1, MPI_LONG_LONG, MPI_MAX, comm));
  PetscCheck(worst < 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "-mesh_file %s: tetrahedron %lld names a node outside 0..%llu", path.c_str(), worst, nv - 1);
  std::vector<PetscInt> cells(t.begin(), t.end());
  std::vector<PetscReal> coords(x.begin(), x.end());
  PetscSF vsf = nullptr;
  DM dm = nullptr;
  // (PETSc 3.18 crashes when asked for the verticesAdj array: the vertex SF gives the same numbers)
  PetscCall(DMPlexCreateFromCellListParallelPetsc(comm, 3, (PetscInt)(c_hi - c_lo), (PetscInt)(v_hi - v_lo),
                                                  PETSC_DECIDE, 4, PETSC_TRUE, cells.data(), 3, coords.data(),
                                                  &vsf, nullptr, &dm));
  PetscInt v0, v1, nroots;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(PetscSFGetGraph(vsf, &nroots, nullptr, nullptr, nullptr));
  // roots: this rank's block of the file's vertices; leaves: the local vertices (index v - v0)
  std::vector<PetscInt> root((size_t)nroots), node((size_t)(v1 - v0), -1);
  for (PetscInt i = 0; i < nroots; ++i) root[(size_t)i] = (PetscInt)v_lo + i;
  PetscCall(PetscSFBcastBegin(vsf, MPIU_INT, root.data(), node.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(vsf, MPIU_INT, root.data(), node.data(), MPI_REPLACE));
  PetscCall(PetscSFDestroy(&vsf));
  PetscCall(PetscObjectSetName((PetscObject)dm, "mesh"));
  std::string why;
  PetscCall(unsupportedCells(dm, &why));
  PetscCall(agreeOnFailure(comm, &why));
  if (!why.empty()) PetscCall(DMDestroy(&dm));
  PetscCheck(why.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "-mesh_file %s: %s", path.c_str(), why.c_str());
  PetscCall(readGroups(in, dm, node, (long long)c_lo));
  PetscCall(in.close());
  PetscCall(checkRankCap(dm, rank_cap, "before distribution"));
  if (size > 1) {
    DM before = dm;
    PetscSF migration = nullptr;
    PetscCall(PetscObjectReference((PetscObject)before));
    PetscCall(distributePlex(&dm, &migration));
    PetscCall(carryVertexNumbers(node, before, dm, migration, &mesh->vertex_node));
    PetscCall(PetscSFDestroy(&migration));
    PetscCall(DMDestroy(&before));
  } else {
    mesh->vertex_node = node;
  }
  PetscCall(checkRankCap(dm, rank_cap, "after distribution"));
  mesh->dm = dm, mesh->nodes = (long long)nv;
  PetscFunctionReturn(0);
}

} // namespace suite::fem
