// A PETSc string option without a fixed set of values (a path, a plane), read into a std::string between
// PetscOptionsBegin and PetscOptionsEnd; the current value is the default. Named choices: core/named_choice.hpp.
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {

inline PetscErrorCode optionsString(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                    std::string* value) {
  char buf[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buf, value->c_str(), sizeof buf));
  PetscCall(PetscOptionsString(name, text, "", buf, buf, sizeof buf, nullptr));
  *value = buf;
  PetscFunctionReturn(0);
}

} // namespace suite
