// The natural node numbering of a distributed DMPlex (see plex_natural.hpp).
#include "fem/plex_natural.hpp"

#include "fem/plex_beam.hpp"
#include "fem/plex_prescribed.hpp"

#include <cmath>
#include <vector>

namespace suite::fem {

namespace {

// owned[v - v0]: whether this rank owns local vertex v (it is not a leaf of the point SF).
PetscErrorCode ownedVertices(DM dm, PetscInt v0, PetscInt v1, std::vector<char>* owned) {
  PetscSF sf;
  PetscInt nleaves;
  const PetscInt* ilocal;
  PetscFunctionBeginUser;
  owned->assign((size_t)(v1 - v0), 1);
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &ilocal, nullptr));
  for (PetscInt i = 0; i < nleaves; ++i) {
    const PetscInt p = ilocal ? ilocal[i] : i;
    if (p >= v0 && p < v1) (*owned)[(size_t)(p - v0)] = 0;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode beamVertexNodes(DM dm, const BeamSpec& spec, std::vector<PetscInt>* vertex_node) {
  Vec coords;
  PetscSection cs;
  const PetscScalar* cx;
  PetscInt v0, v1;
  PetscFunctionBeginUser;
  const double h[3] = {spec.length / spec.cells[0], spec.size[0] / spec.cells[1],
                       spec.size[1] / spec.cells[2]};
  const long long nx1 = spec.cells[0] + 1, ny1 = spec.cells[1] + 1;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(VecGetArrayRead(coords, &cx));
  vertex_node->resize((size_t)(v1 - v0));
  for (PetscInt v = v0; v < v1; ++v) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(cs, v, &off));
    long long ijk[3];
    for (int d = 0; d < 3; ++d) ijk[d] = std::llround(PetscRealPart(cx[off + d]) / h[d]);
    (*vertex_node)[(size_t)(v - v0)] = (PetscInt)(ijk[0] + nx1 * (ijk[1] + ny1 * ijk[2]));
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscFunctionReturn(0);
}

PlexNaturalOrder::~PlexNaturalOrder() {
  VecScatterDestroy(&scatter_);
  VecDestroy(&template_);
}

PetscErrorCode PlexNaturalOrder::setupLayout(DM dm, long long nodes,
                                             const std::vector<PetscInt>& vertex_node) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  int rank, size;
  PetscInt v1;
  PetscFunctionBeginUser;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  dm_ = dm, vertex_node_ = vertex_node, nodes_ = nodes;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0_, &v1));
  PetscCheck((size_t)(v1 - v0_) == vertex_node.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "a natural node for each of the %d local vertices expected, %d given", (int)(v1 - v0_),
             (int)vertex_node.size());
  row0_ = nodes_ * rank / size;
  rows_ = nodes_ * (rank + 1) / size - row0_;
  PetscCall(VecDestroy(&template_));
  PetscCall(VecCreateMPI(comm, (PetscInt)(3 * rows_), (PetscInt)(3 * nodes_), &template_));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::setup(DM dm, long long nodes, const std::vector<PetscInt>& vertex_node) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  Vec g;
  PetscInt v1;
  PetscFunctionBeginUser;
  PetscCall(setupLayout(dm, nodes, vertex_node));
  PetscCall(DMPlexGetDepthStratum(dm, 0, nullptr, &v1));
  // From each owned, unconstrained DOF of the DM's global vector to its natural DOF.
  PetscSection ls, gs;
  std::vector<PetscInt> from, to;
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetGlobalSection(dm, &gs));
  for (PetscInt v = v0_; v < v1; ++v) {
    PetscInt goff;
    bool held[3];
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; // a ghost
    PetscCall(heldComponents(ls, v, held));
    PetscInt free = 0;
    for (int c = 0; c < 3; ++c)
      if (!held[c]) from.push_back(goff + free++), to.push_back((PetscInt)(3 * vertexNode(v) + c));
  }
  IS isf, ist;
  PetscCall(ISCreateGeneral(comm, (PetscInt)from.size(), from.data(), PETSC_COPY_VALUES, &isf));
  PetscCall(ISCreateGeneral(comm, (PetscInt)to.size(), to.data(), PETSC_COPY_VALUES, &ist));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(VecScatterCreate(g, isf, template_, ist, &scatter_));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(ISDestroy(&isf));
  PetscCall(ISDestroy(&ist));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::coordinates(std::vector<double>* xyz) const {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  Vec coords, mine, nat;
  PetscSection cs;
  const PetscScalar* cx;
  PetscInt v1;
  std::vector<char> owned;
  std::vector<PetscInt> to;
  std::vector<PetscScalar> vals;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm_, 0, nullptr, &v1));
  PetscCall(ownedVertices(dm_, v0_, v1, &owned));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &cs));
  PetscCall(VecGetArrayRead(coords, &cx));
  for (PetscInt v = v0_; v < v1; ++v) {
    if (!owned[(size_t)(v - v0_)]) continue;
    PetscInt off;
    PetscCall(PetscSectionGetOffset(cs, v, &off));
    for (int d = 0; d < 3; ++d) to.push_back((PetscInt)(3 * vertexNode(v) + d)), vals.push_back(cx[off + d]);
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscCall(VecCreateMPIWithArray(comm, 1, (PetscInt)vals.size(), PETSC_DECIDE, vals.data(), &mine));
  PetscCall(createNatural(&nat));
  PetscInt r0;
  PetscCall(VecGetOwnershipRange(mine, &r0, nullptr));
  IS isf, ist;
  VecScatter sc;
  PetscCall(ISCreateStride(comm, (PetscInt)vals.size(), r0, 1, &isf));
  PetscCall(ISCreateGeneral(comm, (PetscInt)to.size(), to.data(), PETSC_COPY_VALUES, &ist));
  PetscCall(VecScatterCreate(mine, isf, nat, ist, &sc));
  PetscCall(VecScatterBegin(sc, mine, nat, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, mine, nat, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* x;
  PetscCall(VecGetArrayRead(nat, &x));
  xyz->resize((size_t)(3 * rows_));
  for (size_t i = 0; i < xyz->size(); ++i) (*xyz)[i] = PetscRealPart(x[i]);
  PetscCall(VecRestoreArrayRead(nat, &x));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&isf));
  PetscCall(ISDestroy(&ist));
  PetscCall(VecDestroy(&nat));
  PetscCall(VecDestroy(&mine));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::setHeld(Vec natural, const std::vector<PetscInt>& vertices,
                                         const std::vector<int>& components,
                                         const std::vector<double>& values) const {
  PetscFunctionBeginUser;
  std::vector<PetscInt> idx(vertices.size());
  std::vector<PetscScalar> val(values.begin(), values.end());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = 3 * vertexNode(vertices[i]) + components[i];
  PetscCall(VecSetValues(natural, (PetscInt)idx.size(), idx.data(), val.data(), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(natural));
  PetscCall(VecAssemblyEnd(natural));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::createNatural(Vec* natural) const {
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(template_, natural));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::toNatural(Vec plex, Vec natural) const {
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(natural));
  PetscCall(VecScatterBegin(scatter_, plex, natural, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, plex, natural, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexNaturalOrder::fromNatural(Vec natural, Vec plex) const {
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(scatter_, natural, plex, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(scatter_, natural, plex, INSERT_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
