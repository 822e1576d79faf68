// Groups of a DMPlex mesh by name or tag (see plex_groups.hpp).
#include "fem/plex_groups.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace suite::fem {

namespace {

bool internalLabel(const std::string& n) {
  static const char* own[] = {"depth",     "celltype",    "Cell Sets", "Face Sets",
                              "Edge Sets", "Vertex Sets", "marker"};
  return std::any_of(std::begin(own), std::end(own), [&](const char* o) { return n == o; });
}

} // namespace

PetscErrorCode listGroups(DM dm, std::vector<PlexGroup>* groups) {
  PetscInt nl;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  groups->clear();
  PetscCall(DMGetNumLabels(dm, &nl));
  std::vector<std::string> names;
  for (PetscInt i = 0; i < nl; ++i) {
    const char* name;
    PetscCall(DMGetLabelName(dm, i, &name));
    if (!internalLabel(name)) names.push_back(name);
  }
  std::sort(names.begin(), names.end()); // the same order on every rank: the reductions below pair up
  for (const std::string& nm : names) {
    const char* name = nm.c_str();
    DMLabel label;
    IS values;
    PetscInt nv;
    const PetscInt* v;
    PetscCall(DMGetLabel(dm, name, &label));
    PetscCall(DMLabelGetValueIS(label, &values));
    PetscCall(ISGetLocalSize(values, &nv));
    PetscCall(ISGetIndices(values, &v));
    // lo, -hi of the values; the highest depth of the points
    PetscInt mine[3] = {std::numeric_limits<PetscInt>::max(), std::numeric_limits<PetscInt>::max(), -1};
    for (PetscInt k = 0; k < nv; ++k) {
      mine[0] = std::min(mine[0], v[k]), mine[1] = std::min(mine[1], -v[k]);
      IS pts;
      PetscInt np;
      const PetscInt* p;
      PetscCall(DMLabelGetStratumIS(label, v[k], &pts));
      if (!pts) continue;
      PetscCall(ISGetLocalSize(pts, &np));
      PetscCall(ISGetIndices(pts, &p));
      for (PetscInt j = 0; j < np; ++j) {
        PetscInt d;
        PetscCall(DMPlexGetPointDepth(dm, p[j], &d));
        mine[2] = std::max(mine[2], d);
      }
      PetscCall(ISRestoreIndices(pts, &p));
      PetscCall(ISDestroy(&pts));
    }
    PetscCall(ISRestoreIndices(values, &v));
    PetscCall(ISDestroy(&values));
    PetscInt all[3];
    mine[2] = -mine[2];
    PetscCallMPI(MPI_Allreduce(mine, all, 3, MPIU_INT, MPI_MIN, comm));
    PlexGroup g;
    g.name = name, g.value = all[0], g.dim = (int)-all[2];
    // a label with several values (not a Gmsh group) stands for its lowest value
    groups->push_back(g);
  }
  PetscFunctionReturn(0);
}

namespace {

std::string describe(const std::vector<PlexGroup>& groups) {
  if (groups.empty()) return "the mesh has no groups (Gmsh physical groups)";
  std::string s = "the mesh's groups:";
  for (const auto& g : groups)
    s += " " + g.name + " (tag " + std::to_string(g.value) + ", " +
         (g.dim == 3   ? "volume"
          : g.dim == 2 ? "surface"
          : g.dim < 0  ? "empty"
                       : "dimension " + std::to_string(g.dim)) +
         ")";
  return s;
}

bool parseTag(const std::string& s, PetscInt* tag) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0') return false;
  *tag = (PetscInt)v;
  return true;
}

} // namespace

PetscErrorCode findGroup(DM dm, const std::string& spec, int dim, const char* option, PlexGroup* g) {
  std::vector<PlexGroup> groups;
  PetscFunctionBeginUser;
  PetscCall(listGroups(dm, &groups));
  PetscCall(findGroupIn(PetscObjectComm((PetscObject)dm), groups, spec, dim, option, g));
  PetscFunctionReturn(0);
}

PetscErrorCode findGroupIn(MPI_Comm comm, const std::vector<PlexGroup>& groups, const std::string& spec,
                           int dim, const char* option, PlexGroup* g) {
  PetscFunctionBeginUser;
  std::vector<PlexGroup> hits;
  PetscInt tag;
  for (const auto& c : groups)
    if (c.name == spec) hits.push_back(c);
  if (hits.empty() && parseTag(spec, &tag))
    for (const auto& c : groups)
      if (c.value == tag && c.dim == dim) hits.push_back(c);
  const std::string known = describe(groups);
  PetscCheck(!hits.empty(), comm, PETSC_ERR_ARG_WRONG, "%s: no group %s of dimension %d; %s", option,
             spec.c_str(), dim, known.c_str());
  PetscCheck(hits.size() == 1, comm, PETSC_ERR_ARG_WRONG, "%s: tag %s names several groups; %s", option,
             spec.c_str(), known.c_str());
  PetscCheck(hits[0].dim == dim, comm, PETSC_ERR_ARG_WRONG, "%s: group %s is a %s, not a %s (%s)", option,
             spec.c_str(),
             hits[0].dim == 3   ? "volume"
             : hits[0].dim == 2 ? "surface"
                                : "set of lower dimension",
             dim == 3 ? "volume" : "surface", known.c_str());
  *g = hits[0];
  PetscFunctionReturn(0);
}

PetscErrorCode hasGroup(DM dm, const std::string& name, bool* has) {
  PetscBool h = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(DMHasLabel(dm, name.c_str(), &h));
  *has = h && !internalLabel(name);
  PetscFunctionReturn(0);
}

PetscErrorCode meshMaxX(DM dm, double* xmax) {
  Vec coords;
  PetscInt n;
  const PetscScalar* cx;
  double mine = -std::numeric_limits<double>::infinity();
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(VecGetLocalSize(coords, &n));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt i = 0; i < n; i += 3) mine = std::max(mine, (double)PetscRealPart(cx[i]));
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscCallMPI(MPI_Allreduce(&mine, xmax, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

// The boundary faces (one cell in their support; with no overlap a face between two ranks' cells has one
// local cell too, but its vertices never all lie on an outer plane of a convex end) on the plane.
PetscErrorCode markPlaneFaces(DM dm, const char* name, double x0, double tol) {
  DMLabel label;
  PetscInt f0, f1, v0, v1;
  Vec coords;
  PetscSection cs;
  const PetscScalar* cx;
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, name));
  PetscCall(DMGetLabel(dm, name, &label));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f0, &f1));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt f = f0; f < f1; ++f) {
    PetscInt ns, n = 0, *pts = nullptr;
    PetscCall(DMPlexGetSupportSize(dm, f, &ns));
    if (ns != 1) continue;
    bool on = true;
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < 2 * n; i += 2)
      if (pts[i] >= v0 && pts[i] < v1) {
        PetscInt off;
        PetscCall(PetscSectionGetOffset(cs, pts[i], &off));
        on = on && std::abs(PetscRealPart(cx[off]) - x0) <= tol;
      }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
    if (on) PetscCall(DMLabelSetValue(label, f, 1));
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscFunctionReturn(0);
}

PetscErrorCode groupFaces(DM dm, const PlexGroup& g, std::vector<PetscInt>* faces) {
  IS pts = nullptr;
  PetscInt n = 0, f0, f1;
  const PetscInt* p = nullptr;
  PetscFunctionBeginUser;
  faces->clear();
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f0, &f1));
  PetscCall(DMGetStratumIS(dm, g.name.c_str(), g.value, &pts));
  if (!pts) PetscFunctionReturn(0);
  PetscCall(ISGetLocalSize(pts, &n));
  PetscCall(ISGetIndices(pts, &p));
  for (PetscInt i = 0; i < n; ++i)
    if (p[i] >= f0 && p[i] < f1) faces->push_back(p[i]);
  PetscCall(ISRestoreIndices(pts, &p));
  PetscCall(ISDestroy(&pts));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
