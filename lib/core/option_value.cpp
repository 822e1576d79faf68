// Numeric and boolean options with their text checked collectively before PETSc converts it (see
// option_value.hpp).
#include "core/option_value.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <strings.h>

namespace suite {
namespace {

enum class Kind { integer, real, real_or_inf, flag };

bool isKeyword(const std::string& s) { // PETSc's named values (PETSC_DEFAULT, ...): PETSc converts them
  for (const char* k : {"PETSC_DEFAULT", "DEFAULT", "PETSC_DECIDE", "DECIDE", "PETSC_DETERMINE", "DETERMINE"})
    if (strcasecmp(s.c_str(), k) == 0) return true;
  return false;
}

// Why the text of one entry is refused ("" if it is accepted).
std::string integerProblem(const std::string& s) {
  const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, hex ? 16 : 10);
  if (end == s.c_str() || *end != '\0') return "not an integer";
  if (errno == ERANGE || v < PETSC_MIN_INT || v > PETSC_MAX_INT)
    return "out of range (an integer from " + std::to_string(PETSC_MIN_INT) + " to " +
           std::to_string(PETSC_MAX_INT) + ")";
  return "";
}

std::string realProblem(const std::string& s, bool or_inf) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0') return "not a number";
  if (std::isnan(v) || (std::isinf(v) && !or_inf)) return or_inf ? "not a number" : "not a finite number";
  return "";
}

std::string flagProblem(const std::string& s) {
  for (const char* k : {"true", "false", "yes", "no", "on", "off", "1", "0"})
    if (strcasecmp(s.c_str(), k) == 0) return "";
  return "not a flag (true/false, yes/no, on/off or 1/0)";
}

std::string entryProblem(const std::string& s, Kind kind) {
  if (s.empty()) return "empty value";
  if (kind != Kind::flag && isKeyword(s)) return "";
  switch (kind) {
  case Kind::integer:
    return integerProblem(s);
  case Kind::real:
    return realProblem(s, false);
  case Kind::real_or_inf:
    return realProblem(s, true);
  case Kind::flag:
    return flagProblem(s);
  }
  return "";
}

// The first refused entry of a (comma-separated, if list) value, as a message; "" if all are accepted.
std::string valueProblem(const char* name, const char* value, Kind kind, bool list) {
  const char* what = kind == Kind::integer ? "an integer" : kind == Kind::flag ? "a flag" : "a number";
  if (!value || !value[0]) {
    if (kind == Kind::flag) return ""; // a flag alone means true
    return std::string(name) + ": no value given (" + what + (list ? " list" : "") + " is required)";
  }
  const std::string text = value;
  size_t start = 0;
  while (true) {
    const size_t comma = list ? text.find(',', start) : std::string::npos;
    const std::string entry =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string why = entryProblem(entry, kind);
    if (!why.empty())
      return std::string(name) + " '" + text + "': " + (list ? "entry '" + entry + "' is " : "") + why;
    if (comma == std::string::npos) return "";
    start = comma + 1;
  }
}

// Collective (every rank reads the same options): the block is closed first (an error inside
// PetscOptionsBegin/End leaks its strings), then one error for the job.
PetscErrorCode checkValue(PetscOptionItems* po, const char* name, Kind kind, bool list) {
  const char* value = nullptr;
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(po->options, po->prefix, name, &value, &found));
  if (!found) PetscFunctionReturn(0);
  const std::string why = valueProblem(name, value, kind, list);
  if (why.empty()) PetscFunctionReturn(0);
  const MPI_Comm comm = po->comm;
  PetscCall(PetscOptionsEnd_Private(po));
  SETERRQ(comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
}

} // namespace

PetscErrorCode optionsReal(PetscOptionItems* po, const char* name, const char* text, const char* man,
                           PetscReal dflt, PetscReal* value, PetscBool* set, Real accept) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, accept == Real::or_inf ? Kind::real_or_inf : Kind::real, false));
  PetscCall(PetscOptionsReal_Private(po, name, text, man, dflt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsInt(PetscOptionItems* po, const char* name, const char* text, const char* man,
                          PetscInt dflt, PetscInt* value, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::integer, false));
  PetscCall(PetscOptionsInt_Private(po, name, text, man, dflt, value, set, PETSC_MIN_INT, PETSC_MAX_INT));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsBool(PetscOptionItems* po, const char* name, const char* text, const char* man,
                           PetscBool dflt, PetscBool* value, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::flag, false));
  PetscCall(PetscOptionsBool_Private(po, name, text, man, dflt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsRealArray(PetscOptionItems* po, const char* name, const char* text, const char* man,
                                PetscReal* values, PetscInt* n, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::real, true));
  PetscCall(PetscOptionsRealArray_Private(po, name, text, man, values, n, set));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsIntArray(PetscOptionItems* po, const char* name, const char* text, const char* man,
                               PetscInt* values, PetscInt* n, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::integer, true));
  PetscCall(PetscOptionsIntArray_Private(po, name, text, man, values, n, set));
  PetscFunctionReturn(0);
}

} // namespace suite
