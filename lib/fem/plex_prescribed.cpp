// Prescribed displacements on a DMPlex (see plex_prescribed.hpp).
#include "fem/plex_prescribed.hpp"

#include <cmath>
#include <string>

namespace suite::fem {

namespace {

PetscErrorCode zeroDisplacement(PetscInt, PetscReal, const PetscReal[], PetscInt nc, PetscScalar* u, void*) {
  for (PetscInt i = 0; i < nc; ++i) u[i] = 0.0;
  return 0;
}

// mark[v - v0] = 1 for the local vertices in the closure of the points of a group's stratum.
PetscErrorCode groupVertices(DM dm, const PlexGroup& g, PetscInt v0, PetscInt v1, std::vector<char>* mark) {
  IS pts = nullptr;
  PetscInt n = 0;
  const PetscInt* p = nullptr;
  PetscFunctionBeginUser;
  mark->assign((size_t)(v1 - v0), 0);
  PetscCall(DMGetStratumIS(dm, g.name.c_str(), g.value, &pts));
  if (!pts) PetscFunctionReturn(0);
  PetscCall(ISGetLocalSize(pts, &n));
  PetscCall(ISGetIndices(pts, &p));
  for (PetscInt i = 0; i < n; ++i)
    if (p[i] >= v0 && p[i] < v1) (*mark)[(size_t)(p[i] - v0)] = 1;
  PetscCall(ISRestoreIndices(pts, &p));
  PetscCall(ISDestroy(&pts));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode heldComponents(PetscSection local, PetscInt point, bool held[3], PetscInt* count) {
  PetscInt cdof;
  const PetscInt* cind = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetConstraintDof(local, point, &cdof));
  if (cdof) PetscCall(PetscSectionGetConstraintIndices(local, point, &cind));
  for (int c = 0; c < 3; ++c) held[c] = false;
  for (PetscInt k = 0; k < cdof; ++k)
    if (cind[k] >= 0 && cind[k] < 3) held[cind[k]] = true;
  if (count) *count = cdof;
  PetscFunctionReturn(0);
}

PetscErrorCode PlexPrescribedDofs::addBoundaries(DM dm, const std::vector<PlexPrescribed>& entries) {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < entries.size(); ++k) {
    const PlexPrescribed& e = entries[k];
    DMLabel label;
    PetscInt comps[3], nc = 0;
    for (PetscInt c = 0; c < 3; ++c)
      if (e.comp[c]) comps[nc++] = c;
    PetscCall(DMGetLabel(dm, e.group.name.c_str(), &label));
    PetscCall(DMPlexLabelComplete(dm, label)); // the faces' edges and vertices: their DOFs are held too
    const std::string name = e.group.name + "#" + std::to_string(k);
    // Nc = 0: every component (a fixed group: the same section as a clamp)
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, name.c_str(), label, 1, &e.group.value, 0, nc == 3 ? 0 : nc,
                            nc == 3 ? nullptr : comps, (void (*)(void))zeroDisplacement, nullptr, nullptr,
                            nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexPrescribedDofs::setup(DM dm, const std::vector<PlexPrescribed>& entries) {
  PetscSection ls;
  PetscInt v0, v1;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  const size_t nv = (size_t)(v1 - v0);
  std::vector<double> value(3 * nv, 0.0);
  std::vector<int> owner(3 * nv, -1); // the entry that holds each component of each vertex
  int clash[3] = {-1, -1, 0};         // two entries holding one DOF at different values
  for (size_t k = 0; k < entries.size(); ++k) {
    std::vector<char> mark;
    PetscCall(groupVertices(dm, entries[k].group, v0, v1, &mark));
    for (size_t v = 0; v < nv; ++v)
      for (int c = 0; c < 3; ++c) {
        if (!mark[v] || !entries[k].comp[c]) continue;
        const size_t i = 3 * v + (size_t)c;
        if (owner[i] >= 0 && value[i] != entries[k].value[c] && clash[0] < 0)
          clash[0] = owner[i], clash[1] = (int)k;
        owner[i] = (int)k, value[i] = entries[k].value[c];
      }
  }
  int worst[2];
  PetscCallMPI(MPI_Allreduce(clash, worst, 2, MPI_INT, MPI_MAX, comm));
  PetscCheck(worst[0] < 0, comm, PETSC_ERR_ARG_INCOMP,
             "-bc_fixed / -bc_displacement: the entries on the groups %s and %s hold a displacement "
             "component of a shared vertex at different values",
             entries[(size_t)worst[0]].group.name.c_str(), entries[(size_t)worst[1]].group.name.c_str());
  off_.clear(), val_.clear(), vertex_.clear(), comp_.clear();
  int flags[2] = {0, 0}; // partial, nonzero
  for (size_t v = 0; v < nv; ++v) {
    PetscInt off, held = 0;
    PetscCall(PetscSectionGetOffset(ls, v0 + (PetscInt)v, &off));
    for (int c = 0; c < 3; ++c) {
      if (owner[3 * v + (size_t)c] < 0) continue;
      ++held;
      off_.push_back(off + c), val_.push_back(value[3 * v + (size_t)c]);
      vertex_.push_back(v0 + (PetscInt)v), comp_.push_back(c);
      flags[1] = flags[1] || value[3 * v + (size_t)c] != 0.0;
    }
    PetscInt cdof;
    PetscCall(PetscSectionGetConstraintDof(ls, v0 + (PetscInt)v, &cdof));
    PetscCheck(cdof == held, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "vertex %d: the section holds %d components, the groups %d", (int)v, (int)cdof, (int)held);
    flags[0] = flags[0] || (held > 0 && held < 3);
  }
  int all[2];
  PetscCallMPI(MPI_Allreduce(flags, all, 2, MPI_INT, MPI_MAX, comm));
  partial_ = all[0] != 0, nonzero_ = all[1] != 0;
  PetscFunctionReturn(0);
}

PetscErrorCode PlexPrescribedDofs::insert(Vec local, double scale) const {
  PetscScalar* x;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(local, &x));
  for (size_t i = 0; i < off_.size(); ++i) x[off_[i]] = scale * val_[i];
  PetscCall(VecRestoreArray(local, &x));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
