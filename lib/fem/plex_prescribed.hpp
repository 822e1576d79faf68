// Prescribed displacements on a DMPlex: components of the displacement on the closure of a group's faces held
// at given values (a fixed support: all three components, zero; a roller or a symmetry plane: one or two
// components; a driven face: nonzero values, scaled by a load factor in time). The prescribed DOFs are
// essential conditions of the DM's section (DMAddBoundary: removed from the global vectors); this class lists
// them in the local vector and writes their values there, so that the residual, the outputs and the energies
// see the prescribed state.
#pragma once

#include "fem/plex_groups.hpp"

#include <petscdmplex.h>

#include <vector>

namespace suite::fem {

struct PlexPrescribed {
  PlexGroup group;                   // a surface
  bool comp[3] = {true, true, true}; // the components held
  double value[3] = {0, 0, 0};       // their values at full load
};

// held[c]: component c of the point's displacement is prescribed (a constraint of the local section); the count.
PetscErrorCode heldComponents(PetscSection local, PetscInt point, bool held[3], PetscInt* count = nullptr);

class PlexPrescribedDofs {
public:
  // Collective. Completes the groups' labels (their faces' edges and vertices) and adds one essential boundary
  // per entry to dm's discretisation (before its section is made).
  static PetscErrorCode addBoundaries(DM dm, const std::vector<PlexPrescribed>& entries);
  // Collective, once the section exists. Errors naming both groups when two entries hold one DOF at different
  // values.
  PetscErrorCode setup(DM dm, const std::vector<PlexPrescribed>& entries);
  size_t size() const { return off_.size(); }
  // Local-vector offset, full value, local vertex and component of each prescribed DOF.
  const std::vector<PetscInt>& offsets() const { return off_; }
  const std::vector<double>& values() const { return val_; }
  const std::vector<PetscInt>& vertices() const { return vertex_; }
  const std::vector<int>& components() const { return comp_; }
  // Over all ranks: some vertex has one or two of its components held; some value is nonzero.
  bool partial() const { return partial_; }
  bool nonzero() const { return nonzero_; }
  // local[offset] = scale * value for every prescribed DOF.
  PetscErrorCode insert(Vec local, double scale) const;

private:
  std::vector<PetscInt> off_, vertex_;
  std::vector<double> val_;
  std::vector<int> comp_;
  bool partial_ = false, nonzero_ = false;
};

} // namespace suite::fem
