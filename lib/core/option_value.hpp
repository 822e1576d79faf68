// Numeric, boolean and free-text PETSc options in one call between PetscOptionsBegin and PetscOptionsEnd: the
// current value is the default shown by -help. Options with a fixed set of values: core/named_choice.hpp.
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscInt* value, PetscBool* set = nullptr) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt(name, text, "", *value, value, set));
  PetscFunctionReturn(0);
}

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscReal* value, PetscBool* set = nullptr) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal(name, text, "", *value, value, set));
  PetscFunctionReturn(0);
}

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscBool* value, PetscBool* set = nullptr) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool(name, text, "", *value, value, set));
  PetscFunctionReturn(0);
}

// A string without a fixed set of values (a path, a plane), read into a std::string.
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
