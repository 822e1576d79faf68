// Numeric and boolean options with their text checked collectively before PETSc converts it (see
// option_value.hpp).
#include "core/option_value.hpp"

#include "core/option_text.hpp"

#include <algorithm>
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

// The first refused entry of a (comma-separated, if list) value, as a message; "" if all are accepted. A list
// holds at most capacity entries.
std::string valueProblem(const char* name, const std::string& text, Kind kind, bool list,
                         long long capacity) {
  const char* what = kind == Kind::integer ? "an integer" : kind == Kind::flag ? "a flag" : "a number";
  if (text.empty()) {
    if (kind == Kind::flag) return ""; // a flag alone means true
    return std::string(name) + ": no value given (" + what + (list ? " list" : "") + " is required)";
  }
  const std::string shown = std::string(name) + " '" + shownValue(text) + "': ";
  if (list) {
    const long long entries = 1 + static_cast<long long>(std::count(text.begin(), text.end(), ','));
    if (entries > capacity)
      return shown + "at most " + std::to_string(capacity) + " value" + (capacity == 1 ? "" : "s") +
             " (given " + std::to_string(entries) + ")";
  }
  size_t start = 0;
  while (true) {
    const size_t comma = list ? text.find(',', start) : std::string::npos;
    const std::string entry =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string why = entryProblem(entry, kind);
    if (!why.empty()) return shown + (list ? "entry '" + shownValue(entry) + "' is " : "") + why;
    if (comma == std::string::npos) return "";
    start = comma + 1;
  }
}

// Collective (every rank reads the same options): the block is closed first (an error inside
// PetscOptionsBegin/End leaks its strings), then one error for the job.
PetscErrorCode checkValue(PetscOptionItems* po, const char* name, Kind kind, bool list = false,
                          long long capacity = 1) {
  std::string text;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(po, name, &text, &found));
  if (!found) PetscFunctionReturn(0);
  const std::string why = valueProblem(name, text, kind, list, capacity);
  if (!why.empty()) PetscCall(failInOptionsBlock(po, PETSC_ERR_ARG_WRONG, why));
  PetscFunctionReturn(0);
}

// PETSc's reader f() with its own -help line left out (the suite prints its own).
template <class F> PetscErrorCode withoutHelp(PetscOptionItems* po, F f) {
  const PetscBool help = po->printhelp;
  po->printhelp = PETSC_FALSE;
  const PetscErrorCode ierr = f();
  po->printhelp = help;
  return ierr;
}

std::string intText(PetscInt v) {
  return std::to_string(static_cast<long long>(v));
}

template <class T, class Text> std::string listText(const T* v, PetscInt n, Text text) {
  std::string s;
  for (PetscInt i = 0; i < n; ++i) s += (i ? "," : "") + text(v[i]);
  return s;
}

} // namespace

PetscErrorCode optionsReal(PetscOptionItems* po, const char* name, const char* text, const char*,
                           PetscReal dflt, PetscReal* value, PetscBool* set, Real accept) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, accept == Real::or_inf ? Kind::real_or_inf : Kind::real));
  PetscCall(withoutHelp(po, [&] { return PetscOptionsReal_Private(po, name, text, "", dflt, value, set); }));
  PetscCall(printOptionHelp(po, name, realText(*value), text));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsInt(PetscOptionItems* po, const char* name, const char* text, const char*,
                          PetscInt dflt, PetscInt* value, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::integer));
  PetscCall(withoutHelp(po, [&] {
    return PetscOptionsInt_Private(po, name, text, "", dflt, value, set, PETSC_MIN_INT, PETSC_MAX_INT);
  }));
  PetscCall(printOptionHelp(po, name, intText(*value), text));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsBool(PetscOptionItems* po, const char* name, const char* text, const char*,
                           PetscBool dflt, PetscBool* value, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::flag));
  PetscCall(withoutHelp(po, [&] { return PetscOptionsBool_Private(po, name, text, "", dflt, value, set); }));
  PetscCall(printOptionHelp(po, name, *value ? "true" : "false", text));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsRealArray(PetscOptionItems* po, const char* name, const char* text, const char*,
                                PetscReal* values, PetscInt* n, PetscBool* set) {
  const PetscInt capacity = *n;
  PetscBool given = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::real, true, capacity));
  PetscCall(
      withoutHelp(po, [&] { return PetscOptionsRealArray_Private(po, name, text, "", values, n, &given); }));
  PetscCall(printOptionHelp(po, name, listText(values, given ? *n : capacity, realText), text));
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode optionsIntArray(PetscOptionItems* po, const char* name, const char* text, const char*,
                               PetscInt* values, PetscInt* n, PetscBool* set) {
  const PetscInt capacity = *n;
  PetscBool given = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(checkValue(po, name, Kind::integer, true, capacity));
  PetscCall(
      withoutHelp(po, [&] { return PetscOptionsIntArray_Private(po, name, text, "", values, n, &given); }));
  PetscCall(printOptionHelp(po, name, listText(values, given ? *n : capacity, intText), text));
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode optionsString(PetscOptionItems* po, const char* name, const char* text, std::string* value,
                             PetscBool* set) {
  std::string given;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(po, name, &given, &found));
  // "-output" followed by another option (or -output ""): a forgotten value, never a silent default
  if (found && given.empty())
    PetscCall(failInOptionsBlock(po, PETSC_ERR_ARG_WRONG, std::string(name) + " is given without a value"));
  if (found) *value = given;
  if (set) *set = found ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(printOptionHelp(po, name, *value, text));
  PetscFunctionReturn(0);
}

} // namespace suite
