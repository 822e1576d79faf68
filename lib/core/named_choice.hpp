// Named-choice options (-problem, -scheme, -time, -solvers, -scene, -friction, -ordering, -material, ...):
// declared in one line inside a PetscOptionsBegin/End block, with the registered values documented by -help,
// one per line with its description, generated from the registry that defines them (adding a value adds its
// help line). The value is validated collectively: an unknown name is one error for the whole job naming the
// option, the text and the known values (PetscOptionsEList errors once per rank).
//
//   const std::vector<suite::Choice> kSchemes = {{"enopade6", "6th-order ENO-Pade"}, {"weno5", "WENO5-Z"}};
//   PetscOptionsBegin(comm, "", "Euler options", "");
//   PetscCall(suite::optionsChoice(PetscOptionsObject, "-scheme", "Spatial scheme", kSchemes, &scheme));
//   PetscOptionsEnd();
// A list option (-solvers a,b,c) takes optionsChoiceList: every element must be registered. Values are read
// at any length (core/option_text.hpp); -help shows the value in effect whole (`  -solvers <lemke,bpp>: ...`).
// Each list of values is printed once per -help: a later option whose list mostly repeats it (several options
// sharing one registry) prints one line `(as -lcp_solver, except auto)`, then only the values it adds.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {

struct Choice {
  std::string name;
  std::string help; // one line
};

// Reads option `name` (default: *value on entry) in the current options block; on -help prints `text`, the
// default and every choice with its help line. Collective error on an unknown value.
PetscErrorCode optionsChoice(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                             const std::vector<Choice>& choices, std::string* value,
                             PetscBool* set = nullptr);

// A comma-separated list of choices (order kept, each validated). *values on entry is the default list.
PetscErrorCode optionsChoiceList(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                 const std::vector<Choice>& choices, std::vector<std::string>* values,
                                 PetscBool* set = nullptr);

// The choices of a registry: any range of entries with `name` and `description` members (lib/lcp's
// solverRegistry(), familyRegistry(), ...).
template <class Registry> std::vector<Choice> choicesOf(const Registry& registry) {
  std::vector<Choice> c;
  for (const auto& e : registry) c.push_back({e.name, e.description});
  return c;
}

// "a, b or c" of the choices' names (for messages).
std::string choiceNames(const std::vector<Choice>& choices);

// Collective check that value is one of choices; otherwise one error for the job naming option, text, choices.
PetscErrorCode checkChoice(MPI_Comm comm, const char* option, const std::string& value,
                           const std::vector<Choice>& choices);

} // namespace suite
