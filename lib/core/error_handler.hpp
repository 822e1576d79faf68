// Error reporting policy of the suite: one message per job, non-zero exit on every rank, no hang.
// - An error raised on a communicator that spans all ranks (the usual PetscCheck(cond, comm, ...) with a
//   condition identical on all ranks) is printed once, by rank 0, and returned up the stack on every rank.
// - An error raised on a sub-communicator (PETSC_COMM_SELF) in a multi-rank job can only have been hit by
//   some ranks: it is printed by the rank that hit it and the job is aborted (MPI_Abort), so the other
//   ranks never wait in the next collective.
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {
PetscErrorCode pushSuiteErrorHandler();

// Collective. For failures caught as text on some ranks only (e.g. an exception from a sub-communicator's
// work): afterwards every rank holds the message of the lowest rank that had one (empty if none did), so the
// caller can raise one error on comm with the real reason, whichever rank prints it.
PetscErrorCode agreeOnFailure(MPI_Comm comm, std::string* message);
} // namespace suite
