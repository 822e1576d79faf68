// Candidates as named option values, and their scoped application to the PETSc options database (see
// candidate.hpp).
#include "model_choice/candidate.hpp"

#include "core/option_text.hpp"

#include <algorithm>

namespace suite::model_choice {

std::string optionsText(const OptionValues& options) {
  std::string s;
  for (const auto& [name, value] : options) s += (s.empty() ? "" : " ") + name + " " + value;
  return s;
}

PetscErrorCode ScopedOptions::remember(const std::string& name) {
  std::string value; // whole, at any length
  bool had = false;
  PetscBool used = PETSC_FALSE;
  PetscFunctionBeginUser;
  for (const Saved& s : saved_)
    if (s.name == name) PetscFunctionReturn(0); // the first value is the one to restore
  // whether it was read before the read below marks it (PetscOptionsUsed takes the name without its '-')
  PetscCall(PetscOptionsUsed(nullptr, name.c_str() + (name[0] == '-'), &used));
  PetscCall(suite::findOptionText(name.c_str(), &value, &had));
  saved_.push_back({name, value, had, used == PETSC_TRUE});
  PetscFunctionReturn(0);
}

PetscErrorCode ScopedOptions::set(const std::string& name, const std::string& value) {
  PetscFunctionBeginUser;
  PetscCall(remember(name));
  PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), value.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode ScopedOptions::unset(const std::string& name) {
  PetscFunctionBeginUser;
  PetscCall(remember(name));
  PetscCall(PetscOptionsClearValue(nullptr, name.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode ScopedOptions::setAll(const OptionValues& options) {
  PetscFunctionBeginUser;
  for (const auto& [name, value] : options) PetscCall(set(name, value));
  PetscFunctionReturn(0);
}

PetscErrorCode ScopedOptions::restore() {
  PetscFunctionBeginUser;
  std::reverse(saved_.begin(), saved_.end());
  for (const Saved& s : saved_) {
    if (s.had)
      PetscCall(PetscOptionsSetValue(nullptr, s.name.c_str(), s.value.empty() ? nullptr : s.value.c_str()));
    else
      PetscCall(PetscOptionsClearValue(nullptr, s.name.c_str()));
    PetscBool present = PETSC_FALSE;
    if (s.had && s.used) PetscCall(PetscOptionsHasName(nullptr, nullptr, s.name.c_str(), &present)); // read
  }
  saved_.clear();
  PetscFunctionReturn(0);
}

} // namespace suite::model_choice
