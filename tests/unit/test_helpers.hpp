// Small helpers shared by the GoogleTest units.
#pragma once

#include <petscsys.h>

#include <string>
#include <unistd.h>

namespace suite_test {

inline bool fileExists(const std::string& p) {
  return access(p.c_str(), F_OK) == 0;
}

// Runs f with PETSc errors silenced (for expected failures) and returns its error code.
template <typename F> PetscErrorCode quietly(F f) {
  PetscPushErrorHandler(PetscIgnoreErrorHandler, nullptr);
  PetscErrorCode ierr = f();
  PetscPopErrorHandler();
  return ierr;
}

} // namespace suite_test
