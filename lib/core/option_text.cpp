// Option text at any length, -help lines and file lists (see option_text.hpp).
#include "core/option_text.hpp"

#include "core/comma_list.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glob.h>

namespace suite {

PetscErrorCode findOptionText(PetscOptionItems* po, const char* name, std::string* text, bool* found) {
  const char* value = nullptr;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(po->options, po->prefix, name, &value, &set));
  *found = set == PETSC_TRUE;
  *text = set && value ? value : "";
  PetscFunctionReturn(0);
}

PetscErrorCode findOptionText(const char* name, std::string* text, bool* found) {
  const char* value = nullptr;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(nullptr, nullptr, name, &value, &set));
  *found = set == PETSC_TRUE;
  *text = set && value ? value : "";
  PetscFunctionReturn(0);
}

bool printsHelp(const PetscOptionItems* po) {
  return po->printhelp && po->count == 1 && !po->alreadyprinted;
}

PetscErrorCode printOptionHelp(PetscOptionItems* po, const char* name, const std::string& value,
                               const std::string& text) {
  PetscFunctionBeginUser;
  if (!printsHelp(po)) PetscFunctionReturn(0);
  PetscCall((*PetscHelpPrintf)(po->comm, "  -%s%s <%s>: %s\n", po->prefix ? po->prefix : "", name + 1,
                               value.c_str(), text.c_str()));
  PetscFunctionReturn(0);
}

std::string shownValue(const std::string& text) {
  if (text.size() <= 160) return text;
  return text.substr(0, 120) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string realText(double v) {
  char b[64];
  const auto end = std::to_chars(b, b + sizeof b, v).ptr; // shortest exact; fixed unless longer
  std::string s(b, end);
  if (s.find_first_not_of("-0123456789") == std::string::npos) s += ".";
  return s;
}

PetscErrorCode broadcastString(MPI_Comm comm, std::string* s) {
  long long n = static_cast<long long>(s->size());
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, comm));
  s->resize(static_cast<size_t>(n));
  for (long long at = 0; at < n;) { // in pieces below MPI's int count
    const int piece = static_cast<int>(std::min<long long>(n - at, 1LL << 30));
    PetscCallMPI(MPI_Bcast(&(*s)[static_cast<size_t>(at)], piece, MPI_CHAR, 0, comm));
    at += piece;
  }
  PetscFunctionReturn(0);
}

namespace {

bool isPattern(const std::string& s) {
  return s.find_first_of("*?[") != std::string::npos;
}

// One entry (a path or a pattern), relative to dir when dir is not empty and the entry is relative.
std::string addEntry(const std::string& option, const std::string& entry, const std::string& dir,
                     const std::string& where, std::vector<std::string>* files) {
  const std::string path = dir.empty() || entry[0] == '/' ? entry : dir + "/" + entry;
  if (!isPattern(entry)) {
    files->push_back(path);
    return "";
  }
  glob_t g{};
  const int rc = glob(path.c_str(), 0, nullptr, &g);
  std::vector<std::string> matches(g.gl_pathv, g.gl_pathv + (rc == 0 ? g.gl_pathc : 0));
  globfree(&g);
  if (rc == GLOB_NOMATCH || (rc == 0 && matches.empty()))
    return option + where + ": no file matches '" + shownValue(path) + "'";
  if (rc != 0)
    return option + where + ": cannot expand '" + shownValue(path) + "' (glob error " + std::to_string(rc) +
           ")";
  std::sort(matches.begin(), matches.end());
  files->insert(files->end(), matches.begin(), matches.end());
  return "";
}

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::string readListFile(const std::string& option, const std::string& list,
                         std::vector<std::string>* files) {
  if (list.empty()) return option + " '@': no list file named after the @";
  std::ifstream in(list);
  if (!in) return option + " @" + shownValue(list) + ": cannot open the list file";
  const size_t slash = list.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : slash == 0 ? "/" : list.substr(0, slash);
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number) {
    const std::string entry = trimmed(line.substr(0, line.find('#')));
    if (entry.empty()) continue;
    const std::string where = " @" + shownValue(list) + " line " + std::to_string(number);
    if (entry[0] == '@') return option + where + ": '" + shownValue(entry) + "': list files are not nested";
    const std::string why = addEntry(option, entry, dir == "/" ? "" : dir, where, files);
    if (!why.empty()) return why;
  }
  if (in.bad()) return option + " @" + shownValue(list) + ": read error";
  return "";
}

} // namespace

std::string expandFileList(const std::string& option, const std::string& text,
                           std::vector<std::string>* files) {
  files->clear();
  for (const std::string& entry : splitCommaList(text)) {
    const std::string why = entry[0] == '@' ? readListFile(option, entry.substr(1), files)
                                            : addEntry(option, entry, "", "", files);
    if (!why.empty()) return why;
  }
  return "";
}

namespace {
// Rank 0 expands; *why (every rank) is its verdict, *files (every rank) its list.
PetscErrorCode expandOnRankZero(MPI_Comm comm, const std::string& option, const std::string& text,
                                std::vector<std::string>* files, std::string* why) {
  int rank = 0;
  std::string joined;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    *why = expandFileList(option, text, files);
    for (const std::string& f : *files) joined += f + '\0';
  }
  PetscCall(broadcastString(comm, why));
  if (!why->empty()) PetscFunctionReturn(0);
  PetscCall(broadcastString(comm, &joined));
  files->clear();
  for (size_t a = 0; a < joined.size();) {
    const size_t end = joined.find('\0', a);
    files->push_back(joined.substr(a, end - a));
    a = end + 1;
  }
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode expandFileList(MPI_Comm comm, const std::string& option, const std::string& text,
                              std::vector<std::string>* files) {
  std::string why;
  PetscFunctionBeginUser;
  PetscCall(expandOnRankZero(comm, option, text, files, &why));
  PetscCheck(why.empty(), comm, PETSC_ERR_FILE_OPEN, "%s", why.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode failInOptionsBlock(PetscOptionItems* po, PetscErrorCode code, const std::string& message) {
  const MPI_Comm comm = po->comm;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEnd_Private(po));
  SETERRQ(comm, code, "%s", message.c_str());
}

PetscErrorCode optionsFileList(PetscOptionItems* po, const char* name, const char* text,
                               std::vector<std::string>* files, PetscBool* set) {
  std::string value, why;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(po, name, &value, &found));
  std::string s;
  for (const std::string& f : *files) s += (s.empty() ? "" : ",") + f;
  PetscCall(printOptionHelp(po, name, found ? value : s, text));
  if (set) *set = found ? PETSC_TRUE : PETSC_FALSE;
  if (!found) PetscFunctionReturn(0);
  if (value.find_first_not_of(", \t") ==
      std::string::npos) // "-file" followed by another option, or "-file ''"
    PetscCall(failInOptionsBlock(po, PETSC_ERR_ARG_WRONG, std::string(name) + " is given without a file"));
  std::vector<std::string> expanded;
  PetscCall(expandOnRankZero(po->comm, name, value, &expanded, &why));
  if (!why.empty()) PetscCall(failInOptionsBlock(po, PETSC_ERR_FILE_OPEN, why));
  *files = expanded;
  PetscFunctionReturn(0);
}

} // namespace suite
