// Named-choice options documented from their registry (see named_choice.hpp).
#include "core/named_choice.hpp"

#include "core/comma_list.hpp"
#include "core/option_text.hpp"

#include <algorithm>

namespace suite {

std::string choiceNames(const std::vector<Choice>& choices) {
  std::string list;
  const size_t n = choices.size();
  for (size_t i = 0; i < n; ++i) list += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + choices[i].name;
  return list;
}

namespace {
std::string unknownMessage(const char* option, const std::string& value, const std::vector<Choice>& choices) {
  return std::string("Unknown ") + option + " '" + shownValue(value) + "': " + choiceNames(choices);
}
} // namespace

PetscErrorCode checkChoice(MPI_Comm comm, const char* option, const std::string& value,
                           const std::vector<Choice>& choices) {
  bool known = false;
  PetscFunctionBeginUser;
  for (const Choice& c : choices) known = known || c.name == value;
  PetscCheck(known, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "%s", unknownMessage(option, value, choices).c_str());
  PetscFunctionReturn(0);
}

namespace {
bool isChoice(const std::string& value, const std::vector<Choice>& choices) {
  for (const Choice& c : choices)
    if (c.name == value) return true;
  return false;
}

// The lists -help has printed so far in this process, with the option that printed each.
struct PrintedList {
  std::string option;
  std::vector<Choice> choices;
};
std::vector<PrintedList>& printedLists() {
  static std::vector<PrintedList> lists;
  return lists;
}

const Choice* find(const std::vector<Choice>& choices, const std::string& name) {
  for (const Choice& c : choices)
    if (c.name == name) return &c;
  return nullptr;
}

// An earlier list that this one mostly repeats (same names and descriptions, more shared than left out or
// added), or nullptr.
const PrintedList* repeatedList(const std::vector<Choice>& choices) {
  const PrintedList* best = nullptr;
  size_t best_shared = 0;
  for (const PrintedList& l : printedLists()) {
    size_t shared = 0;
    bool same_text = true;
    for (const Choice& c : choices)
      if (const Choice* e = find(l.choices, c.name)) {
        ++shared;
        same_text = same_text && e->help == c.help;
      }
    const size_t added = choices.size() - shared, left_out = l.choices.size() - shared;
    if (same_text && shared >= 2 && added < shared && left_out < shared && shared > best_shared) {
      best = &l;
      best_shared = shared;
    }
  }
  return best;
}

// Under -help: one line per registered value, below the option's own line. A list that mostly repeats one
// printed before is one line naming that option (and what is left out), then the added values.
PetscErrorCode printChoices(PetscOptionItems* PetscOptionsObject, const char* option,
                            const std::vector<Choice>& choices) {
  PetscFunctionBeginUser;
  if (!printsHelp(PetscOptionsObject)) PetscFunctionReturn(0);
  std::vector<Choice> shown = choices;
  if (const PrintedList* l = repeatedList(choices)) {
    std::vector<std::string> left_out;
    for (const Choice& c : l->choices)
      if (!find(choices, c.name)) left_out.push_back(c.name);
    const std::string except = left_out.empty() ? "" : ", except " + joinCommaList(left_out);
    PetscCall(
        (*PetscHelpPrintf)(PetscOptionsObject->comm, "      (as %s%s)\n", l->option.c_str(), except.c_str()));
    shown.clear();
    for (const Choice& c : choices)
      if (!find(l->choices, c.name)) shown.push_back(c);
  } else {
    printedLists().push_back(
        {std::string(PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "") + option, choices});
  }
  size_t width = 0;
  for (const Choice& c : shown) width = std::max(width, c.name.size());
  for (const Choice& c : shown)
    PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "      %-*s  %s\n", (int)width, c.name.c_str(),
                                 c.help.c_str()));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode optionsChoice(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                             const std::vector<Choice>& choices, std::string* value, PetscBool* set) {
  std::string given;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(PetscOptionsObject, name, &given, &found));
  if (found) *value = given;
  if (set) *set = found ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(printOptionHelp(PetscOptionsObject, name, *value, std::string(text) + "; one of:"));
  PetscCall(printChoices(PetscOptionsObject, name, choices));
  if (!isChoice(*value, choices))
    PetscCall(failInOptionsBlock(PetscOptionsObject, PETSC_ERR_ARG_UNKNOWN_TYPE,
                                 unknownMessage(name, *value, choices)));
  PetscFunctionReturn(0);
}

PetscErrorCode optionsChoiceList(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                                 const std::vector<Choice>& choices, std::vector<std::string>* values,
                                 PetscBool* set) {
  std::string given;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(PetscOptionsObject, name, &given, &found));
  std::string joined;
  for (const std::string& v : *values) joined += (joined.empty() ? "" : ",") + v;
  PetscCall(printOptionHelp(PetscOptionsObject, name, found ? given : joined,
                            std::string(text) + " (comma-separated list); each one of:"));
  PetscCall(printChoices(PetscOptionsObject, name, choices));
  if (set) *set = found ? PETSC_TRUE : PETSC_FALSE;
  if (!found) PetscFunctionReturn(0);
  std::vector<std::string> read; // "" is the empty list; a trailing comma ends the list
  for (size_t start = 0; start < given.size();) {
    const size_t comma = given.find(',', start);
    const std::string item =
        given.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty())
      PetscCall(
          failInOptionsBlock(PetscOptionsObject, PETSC_ERR_ARG_WRONG,
                             std::string(name) + " '" + shownValue(given) + "': empty entry in the list"));
    if (!isChoice(item, choices))
      PetscCall(failInOptionsBlock(PetscOptionsObject, PETSC_ERR_ARG_UNKNOWN_TYPE,
                                   unknownMessage(name, item, choices)));
    read.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  *values = read;
  PetscFunctionReturn(0);
}

} // namespace suite
