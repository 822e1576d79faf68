// The natural node numbering of a distributed DMPlex beam (see plex_natural.hpp).
#include "fem/plex_natural.hpp"

#include "fem/plex_beam.hpp"

#include <cmath>
#include <vector>

namespace suite::fem {

PlexNaturalOrder::~PlexNaturalOrder() {
  VecScatterDestroy(&scatter_);
  VecDestroy(&template_);
}

long long PlexNaturalOrder::node(const PetscReal x[3]) const {
  const int nx = spec_.cells[0], ny = spec_.cells[1];
  const long long i = std::llround(x[0] / h_[0]), j = std::llround(x[1] / h_[1]),
                  k = std::llround(x[2] / h_[2]);
  return i + (long long)(nx + 1) * (j + (long long)(ny + 1) * k);
}

void PlexNaturalOrder::coordinates(long long n, double x[3]) const {
  const long long nx1 = spec_.cells[0] + 1, ny1 = spec_.cells[1] + 1;
  x[0] = (double)(n % nx1) * h_[0];
  x[1] = (double)((n / nx1) % ny1) * h_[1];
  x[2] = (double)(n / (nx1 * ny1)) * h_[2];
}

PetscErrorCode PlexNaturalOrder::setup(DM dm, const BeamSpec& spec) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  int rank, size;
  Vec g;
  PetscFunctionBeginUser;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  spec_ = spec;
  h_[0] = spec.length / spec.cells[0], h_[1] = spec.size[0] / spec.cells[1],
  h_[2] = spec.size[1] / spec.cells[2];
  nodes_ = (long long)(spec.cells[0] + 1) * (spec.cells[1] + 1) * (spec.cells[2] + 1);
  row0_ = nodes_ * rank / size;
  rows_ = nodes_ * (rank + 1) / size - row0_;
  PetscCall(VecCreateMPI(comm, (PetscInt)(3 * rows_), (PetscInt)(3 * nodes_), &template_));
  // From each owned, unconstrained DOF of the DM's global vector to its natural DOF.
  std::vector<FreeVertex> fv;
  std::vector<PetscInt> from, to;
  PetscCall(ownedFreeVertices(dm, &fv));
  for (const FreeVertex& v : fv) {
    const long long n = node(v.x);
    for (int c = 0; c < 3; ++c) from.push_back(v.goff + c), to.push_back((PetscInt)(3 * n + c));
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
