// Checks that turn hostile sizes into one clear message before any time or memory is spent:
//  - integer options beyond the 32-bit PetscInt of Debian's PETSc (PETSc's own parser wraps 3000000000 to a
//    negative number silently),
//  - a run whose estimated memory does not fit in the node's physical memory shared by the ranks on it.
#pragma once

#include <petscsys.h>

namespace suite {

// Collective. If option `name` (e.g. "-nx") was given, its text must be an integer within
// [lo, PETSC_MAX_INT]; otherwise one error naming the option, its text and the range.
PetscErrorCode checkIntOptionRange(MPI_Comm comm, const char* name, long long lo);

// Collective. `value` (the text given for option `name`) must be one of the n `choices`; *index is its position.
// Otherwise one error for the whole job (PetscOptionsEList errors on every rank, one message per rank) naming
// the option, the text and the choices.
PetscErrorCode checkChoice(MPI_Comm comm, const char* name, const char* value, const char* const* choices,
                           int n, PetscInt* index);

// Collective. bytes_this_rank: the caller's estimate of its peak memory. Errors when the ranks sharing a
// node need more than 90% of that node's physical memory, naming the estimate, the node memory and `what`.
PetscErrorCode checkMemoryEstimate(MPI_Comm comm, double bytes_this_rank, const char* what);

} // namespace suite
