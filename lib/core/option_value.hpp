// Numeric, boolean and free-text PETSc options in one call between PetscOptionsBegin and PetscOptionsEnd: the
// current value is the default shown by -help. Options with a fixed set of values: core/named_choice.hpp.
//
// Every numeric or boolean option of the suite is read here (never with PetscOptionsReal/Int/Bool directly):
// its text is checked first, collectively, so that a bad value is one error for the whole job naming the option
// (PETSc's own conversion errors are raised on PETSC_COMM_SELF, once per rank, and it accepts nan and inf for
// reals and wraps integers beyond 32 bits):
//   - a number option given no value or an empty one ("-nx" last, -nx "") is refused;
//   - an integer must be an integer in PetscInt's range (-nx 2147483648 is refused, not wrapped);
//   - a real must be finite (nan, inf, 1e400 are refused) unless the option accepts infinity (Real::or_inf:
//     then +-inf are accepted, never nan);
//   - a flag must be true/false, yes/no, on/off or 1/0 (no value: true).
// The same rules hold for each entry of a comma-separated array (optionsRealArray, optionsIntArray), and an
// array given more entries than it holds is refused (PETSc would drop the rest without a word).
// -help prints `  -name <value>: text` with the value in effect, arrays in full (option_text.hpp); `man` is not
// printed.
#pragma once

#include <petscsys.h>

#include <string>

namespace suite {

enum class Real { finite, or_inf };

PetscErrorCode optionsReal(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                           const char* man, PetscReal dflt, PetscReal* value, PetscBool* set,
                           Real accept = Real::finite);
PetscErrorCode optionsInt(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                          const char* man, PetscInt dflt, PetscInt* value, PetscBool* set);
PetscErrorCode optionsBool(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                           const char* man, PetscBool dflt, PetscBool* value, PetscBool* set);
// Up to *n values (more is an error); on return *n is the number given (0 if the option is not given, as in
// PETSc).
PetscErrorCode optionsRealArray(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                const char* man, PetscReal* values, PetscInt* n, PetscBool* set);
PetscErrorCode optionsIntArray(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                               const char* man, PetscInt* values, PetscInt* n, PetscBool* set);

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscInt* value, PetscBool* set = nullptr) {
  return optionsInt(PetscOptionsObject, name, text, "", *value, value, set);
}

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscReal* value, PetscBool* set = nullptr, Real accept = Real::finite) {
  return optionsReal(PetscOptionsObject, name, text, "", *value, value, set, accept);
}

inline PetscErrorCode optionsValue(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                   PetscBool* value, PetscBool* set = nullptr) {
  return optionsBool(PetscOptionsObject, name, text, "", *value, value, set);
}

// A string without a fixed set of values (a path, a plane), read whole into a std::string (any length; see
// option_text.hpp). *value on entry is the default; *set (if given): whether the option was given.
PetscErrorCode optionsString(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                             std::string* value, PetscBool* set = nullptr);

} // namespace suite
