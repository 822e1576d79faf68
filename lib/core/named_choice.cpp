// Named-choice options documented from their registry (see named_choice.hpp).
#include "core/named_choice.hpp"

#include <sstream>

namespace suite {

std::string choiceNames(const std::vector<Choice>& choices) {
  std::string list;
  const size_t n = choices.size();
  for (size_t i = 0; i < n; ++i) list += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + choices[i].name;
  return list;
}

PetscErrorCode checkChoice(MPI_Comm comm, const char* option, const std::string& value,
                           const std::vector<Choice>& choices) {
  bool known = false;
  PetscFunctionBeginUser;
  for (const Choice& c : choices) known = known || c.name == value;
  PetscCheck(known, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown %s '%s': %s", option, value.c_str(),
             choiceNames(choices).c_str());
  PetscFunctionReturn(0);
}

namespace {
bool isChoice(const std::string& value, const std::vector<Choice>& choices) {
  for (const Choice& c : choices)
    if (c.name == value) return true;
  return false;
}

// An error raised inside PetscOptionsBegin/End returns past PetscOptionsEnd and leaks the block's strings (LSan
// reports them): the block is closed first, then the collective error is raised.
PetscErrorCode failInBlock(PetscOptionItems* PetscOptionsObject, const char* name, const std::string& value,
                           const std::vector<Choice>& choices, const char* list_text) {
  const MPI_Comm comm = PetscOptionsObject->comm;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEnd_Private(PetscOptionsObject));
  PetscCheck(list_text == nullptr, comm, PETSC_ERR_ARG_WRONG, "%s '%s': empty entry in the list", name,
             list_text);
  PetscCall(checkChoice(comm, name, value, choices));
  PetscFunctionReturn(0);
}

// Under -help: one line per registered value, below the option's own line.
PetscErrorCode printChoices(PetscOptionItems* PetscOptionsObject, const std::vector<Choice>& choices) {
  PetscFunctionBeginUser;
  if (!PetscOptionsObject->printhelp) PetscFunctionReturn(0);
  size_t width = 0;
  for (const Choice& c : choices) width = std::max(width, c.name.size());
  for (const Choice& c : choices)
    PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "      %-*s  %s\n", (int)width, c.name.c_str(),
                                 c.help.c_str()));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode optionsChoice(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                             const std::vector<Choice>& choices, std::string* value, PetscBool* set) {
  char buf[PETSC_MAX_PATH_LEN];
  PetscBool given = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buf, value->c_str(), sizeof buf));
  const std::string help = std::string(text) + "; one of:";
  PetscCall(
      PetscOptionsString_Private(PetscOptionsObject, name, help.c_str(), "", buf, buf, sizeof buf, &given));
  PetscCall(printChoices(PetscOptionsObject, choices));
  *value = buf;
  if (set) *set = given;
  if (!isChoice(*value, choices)) PetscCall(failInBlock(PetscOptionsObject, name, *value, choices, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsChoiceList(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                 const std::vector<Choice>& choices, std::vector<std::string>* values,
                                 PetscBool* set) {
  std::string joined;
  PetscBool given = PETSC_FALSE;
  PetscFunctionBeginUser;
  for (const std::string& v : *values) joined += (joined.empty() ? "" : ",") + v;
  char buf[PETSC_MAX_PATH_LEN];
  PetscCall(PetscStrncpy(buf, joined.c_str(), sizeof buf));
  const std::string help = std::string(text) + " (comma-separated list); each one of:";
  PetscCall(
      PetscOptionsString_Private(PetscOptionsObject, name, help.c_str(), "", buf, buf, sizeof buf, &given));
  PetscCall(printChoices(PetscOptionsObject, choices));
  if (set) *set = given;
  if (!given) PetscFunctionReturn(0);
  values->clear();
  std::stringstream ss(buf);
  for (std::string item; std::getline(ss, item, ',');) {
    if (item.empty()) PetscCall(failInBlock(PetscOptionsObject, name, item, choices, buf));
    if (!isChoice(item, choices)) PetscCall(failInBlock(PetscOptionsObject, name, item, choices, nullptr));
    values->push_back(item);
  }
  PetscFunctionReturn(0);
}

} // namespace suite
