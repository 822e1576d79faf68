// A candidate model of an accuracy-target run: one full configuration of the program, written as named option
// values (e.g. {-scheme weno5, -time ssprk3}) plus a resolution n (cells along the first axis; the other axes
// scale with it). Candidates that differ only in n form a family: the family shares one observed order of
// convergence and one cost law (see observed_order.hpp, cost_model.hpp). ScopedOptions puts a configuration
// into the PETSc options database for one run and restores what was there afterwards, so that a program
// runs a candidate by reading its options as usual.
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

namespace suite::model_choice {

using OptionValues = std::vector<std::pair<std::string, std::string>>; // {"-scheme", "weno5"}, ...

struct Family {
  std::string name;     // short label, e.g. "weno5"
  OptionValues options; // the configuration without the resolution
};

struct Candidate {
  int family = 0;  // index into the chooser's family list
  long long n = 0; // resolution
};

// "-scheme weno5 -time ssprk3"
std::string optionsText(const OptionValues& options);

// Sets option values for the lifetime of the object (value "" with unset = true: removes the option) and
// restores the previous values (or their absence) on restore() / destruction. An option the program had
// already read stays marked read after the restore (PETSc marks a value set again as unused: a run in a scope
// after the one that read -output would otherwise leave it reported as never used).
class ScopedOptions {
public:
  ScopedOptions() = default;
  ~ScopedOptions() { restore(); }
  ScopedOptions(const ScopedOptions&) = delete;
  ScopedOptions& operator=(const ScopedOptions&) = delete;
  PetscErrorCode set(const std::string& name, const std::string& value);
  PetscErrorCode unset(const std::string& name);
  PetscErrorCode setAll(const OptionValues& options);
  PetscErrorCode restore();

private:
  PetscErrorCode remember(const std::string& name);
  struct Saved {
    std::string name, value;
    bool had;
    bool used; // already read before the scope
  };
  std::vector<Saved> saved_;
};

} // namespace suite::model_choice
