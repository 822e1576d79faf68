// The Euler run's solid obstacle (lib/euler/solid_body.hpp): the solid cells of this rank's block and of its
// ghosted block (a one-field copy of the grid's DMDA carries the mask to the neighbours' ghost cells), and the
// right-hand side of solid cells held at zero (they keep their initial state).
#include "euler_run.hpp"

#include "core/log.hpp"
#include "euler/solid_body.hpp"

namespace euler_app {

PetscErrorCode EulerRun::setupSolid() {
  DM da1;
  Vec g, l;
  PetscScalar* a;
  const PetscScalar* b;
  PetscFunctionBeginUser;
  solid_.clear(), solid_local_.clear(), solid_cells_ = 0;
  if (!problem_.hasSolid()) PetscFunctionReturn(0);
  PetscCall(suite::euler::solidCells(ctx_.comm(), problem_, opt_.n, s_, m_, &solid_));
  PetscCall(DMDACreateCompatibleDMDA(da_, 1, &da1));
  PetscCall(DMCreateGlobalVector(da1, &g));
  PetscCall(DMCreateLocalVector(da1, &l));
  PetscCall(VecGetArray(g, &a));
  for (PetscInt c = 0; c < localCells(); ++c) {
    a[c] = solid_[c];
    solid_cells_ += solid_[c];
  }
  PetscCall(VecRestoreArray(g, &a));
  PetscCall(VecSet(l, 0.0)); // ghosts outside a bounded domain: fluid (the boundary conditions fill them)
  PetscCall(DMGlobalToLocal(da1, g, INSERT_VALUES, l));
  PetscInt nl;
  PetscCall(VecGetLocalSize(l, &nl));
  PetscCall(VecGetArrayRead(l, &b));
  solid_local_.resize(nl);
  for (PetscInt c = 0; c < nl; ++c) solid_local_[c] = b[c] != 0.0;
  PetscCall(VecRestoreArrayRead(l, &b));
  PetscCall(VecDestroy(&l));
  PetscCall(VecDestroy(&g));
  PetscCall(DMDestroy(&da1));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &solid_cells_, 1, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
  PetscCall(
      suite::logInfo(ctx_.comm(), quiet(), "euler: solid obstacle of %lld cells (%s)", solid_cells_,
                     problem_.solid_mask_file.empty() ? "a formula" : problem_.solid_mask_file.c_str()));
  PetscFunctionReturn(0);
}

void EulerRun::zeroSolidCells(double* f) const {
  if (solid_.empty()) return;
  for (PetscInt c = 0; c < localCells(); ++c)
    if (solid_[c])
      for (int v = 0; v < nv(); ++v) f[c * nv() + v] = 0.0;
}

} // namespace euler_app
