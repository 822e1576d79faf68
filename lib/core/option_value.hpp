// Numeric and boolean PETSc options in one call between PetscOptionsBegin and PetscOptionsEnd: the current
// value is the default shown by -help. Strings: core/option_string.hpp; named choices: core/named_choice.hpp.
#pragma once

#include <petscsys.h>

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

} // namespace suite
