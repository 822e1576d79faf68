// Work that rank 0 does alone (e.g. on a single-process file) with its failure made collective: what rank 0
// throws becomes one error on every rank, so every rank takes the same error path (error_handler.hpp).
#pragma once

#include "core/error_handler.hpp"

#include <petscsys.h>

#include <exception>
#include <string>

namespace suite {

// The message of what f() throws ("" if it returns).
template <class F> std::string messageOf(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// Collective: rank 0 runs f(); if it throws, every rank returns error `code` with text prefix + message.
template <class F> PetscErrorCode onRank0(MPI_Comm comm, PetscErrorCode code, const char* prefix, F&& f) {
  int rank = 0;
  std::string err;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) err = messageOf(f);
  PetscCall(agreeOnFailure(comm, &err));
  PetscCheck(err.empty(), comm, code, "%s%s", prefix, err.c_str());
  PetscFunctionReturn(0);
}

} // namespace suite
