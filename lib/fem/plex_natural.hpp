// The natural node numbering of a distributed DMPlex beam (plex_beam.hpp): node (i, j, k) of the structured
// grid is i + (nx + 1) (j + (ny + 1) k), the numbering of makeBeam (mesh.hpp) and of the replicated path's
// output. A scatter between the DM's global vectors (owned, unconstrained DOFs, partition-dependent) and a
// "natural" vector of 3 DOFs per node in that numbering, split over the ranks in contiguous blocks of nodes,
// makes output and checkpoints independent of the partition: a checkpoint written at P ranks restarts at Q.
// The node of a vertex is recovered from its coordinates (exact on the generated grid).
#pragma once

#include "fem/mesh.hpp"

#include <petscdmplex.h>

namespace suite::fem {

class PlexNaturalOrder {
public:
  PlexNaturalOrder() = default;
  PlexNaturalOrder(const PlexNaturalOrder&) = delete;
  PlexNaturalOrder& operator=(const PlexNaturalOrder&) = delete;
  ~PlexNaturalOrder();

  // Collective. dm: the beam of createPlexBeam with its displacement field and clamp set up.
  PetscErrorCode setup(DM dm, const BeamSpec& spec);
  PetscErrorCode createNatural(Vec* natural) const;
  // natural <- plex (the clamped DOFs, absent from plex vectors, are 0); plex <- natural.
  PetscErrorCode toNatural(Vec plex, Vec natural) const;
  PetscErrorCode fromNatural(Vec natural, Vec plex) const;
  // The natural node of a point of the grid.
  long long node(const PetscReal x[3]) const;
  // The coordinates of natural node n.
  void coordinates(long long n, double x[3]) const;
  long long nodes() const { return nodes_; }
  // This rank's block of natural nodes: row0 .. row0 + rows - 1.
  long long row0() const { return row0_; }
  long long rows() const { return rows_; }

private:
  BeamSpec spec_;
  double h_[3] = {1, 1, 1};
  long long nodes_ = 0, row0_ = 0, rows_ = 0;
  VecScatter scatter_ = nullptr;
  Vec template_ = nullptr; // a natural vector (layout of createNatural)
};

} // namespace suite::fem
