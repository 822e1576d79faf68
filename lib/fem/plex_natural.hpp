// The natural node numbering of a distributed DMPlex: the numbering the mesh came with, independent of the
// partition. The generated beam (plex_beam.hpp): node (i, j, k) of the structured grid is
// i + (nx + 1) (j + (ny + 1) k), the numbering of makeBeam (mesh.hpp) and of the replicated path's output,
// recovered from the coordinates (exact on the generated grid). A mesh file (plex_mesh_file.hpp): the file's
// node order. A scatter between the DM's global vectors (owned, unconstrained DOFs, partition-dependent) and a
// "natural" vector of 3 DOFs per node in that numbering, split over the ranks in contiguous blocks of nodes,
// makes output and checkpoints independent of the partition: a checkpoint written at P ranks restarts at Q.
#pragma once

#include "fem/mesh.hpp"

#include <petscdmplex.h>

#include <vector>

namespace suite::fem {

// The natural node of each local vertex of the generated beam (index v - vStart), from its coordinates.
PetscErrorCode beamVertexNodes(DM dm, const BeamSpec& spec, std::vector<PetscInt>* vertex_node);

class PlexNaturalOrder {
public:
  PlexNaturalOrder() = default;
  PlexNaturalOrder(const PlexNaturalOrder&) = delete;
  PlexNaturalOrder& operator=(const PlexNaturalOrder&) = delete;
  ~PlexNaturalOrder();

  // Collective. dm with its displacement field and supports set up; nodes: the natural node count;
  // vertex_node[v - vStart]: the natural node of each local vertex.
  PetscErrorCode setup(DM dm, long long nodes, const std::vector<PetscInt>& vertex_node);
  // Collective. The numbering alone (vertexNode, coordinates, the blocks), before the DM has a section;
  // setup() does this first.
  PetscErrorCode setupLayout(DM dm, long long nodes, const std::vector<PetscInt>& vertex_node);
  PetscErrorCode createNatural(Vec* natural) const;
  // natural <- plex (the constrained DOFs, absent from plex vectors, are 0); plex <- natural.
  PetscErrorCode toNatural(Vec plex, Vec natural) const;
  PetscErrorCode fromNatural(Vec natural, Vec plex) const;
  // Collective: natural[3 node + component] <- values[i] for the prescribed DOFs (local vertices[i] and
  // components[i]; a vertex several ranks hold gets the same value from each).
  PetscErrorCode setHeld(Vec natural, const std::vector<PetscInt>& vertices,
                         const std::vector<int>& components, const std::vector<double>& values) const;
  // The natural node of local vertex v.
  PetscInt vertexNode(PetscInt v) const { return vertex_node_[(size_t)(v - v0_)]; }
  // Collective: the coordinates of this rank's block of natural nodes (3 per node).
  PetscErrorCode coordinates(std::vector<double>* xyz) const;
  long long nodes() const { return nodes_; }
  // This rank's block of natural nodes: row0 .. row0 + rows - 1.
  long long row0() const { return row0_; }
  long long rows() const { return rows_; }

private:
  DM dm_ = nullptr; // not owned
  std::vector<PetscInt> vertex_node_;
  PetscInt v0_ = 0;
  long long nodes_ = 0, row0_ = 0, rows_ = 0;
  VecScatter scatter_ = nullptr;
  Vec template_ = nullptr; // a natural vector (layout of createNatural)
};

} // namespace suite::fem
