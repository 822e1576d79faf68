// Collective checks of field values: a NaN/Inf, or a value below a bound (negative density or pressure),
// stops the run on all ranks with one message naming field, step, time and the global index.
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {

struct FieldLocation {
  const char* field; // e.g. "rho"
  PetscInt step;
  double time;
  PetscInt global_offset;         // global index of data[0] (offset of this rank's slice)
  const double* coords = nullptr; // optional: cell centres of this rank's slice, printed as x=...
};

// Errors (PETSC_ERR_FP) on all ranks if any entry of data[0..n) (stride 'stride', first component
// 'component') is NaN or Inf.
PetscErrorCode checkFinite(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride, PetscInt component,
                           const FieldLocation& where);
// Errors on all ranks if any entry is not finite or is <= floor (floor = 0 for density/pressure).
PetscErrorCode checkAbove(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride, PetscInt component,
                          double floor, const FieldLocation& where);

// The same checks without stopping: *message is what checkFinite / checkAbove would stop with (without the
// trailing ": stopping the run"), or "" when every entry passes. Collective; the same result on every rank.
PetscErrorCode findNonFinite(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride,
                             PetscInt component, const FieldLocation& where, std::string* message);
PetscErrorCode findNotAbove(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride,
                            PetscInt component, double floor, const FieldLocation& where,
                            std::string* message);

} // namespace suite
