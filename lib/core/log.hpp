// Rank-0 logging: one line per call, printed once per job (PetscPrintf on the given communicator).
#pragma once

#include <petscsys.h>

namespace suite {
// printf-style; prints on rank 0 of comm unless quiet. Errors never go through here (see PetscCheck).
PetscErrorCode logInfo(MPI_Comm comm, bool quiet, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
} // namespace suite
