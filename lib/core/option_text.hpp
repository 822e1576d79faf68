// The text of PETSc options at any length, their -help lines, and lists of files.
//
// Every string or list option of the suite is read here (never into a fixed buffer with PetscOptionsString,
// PetscOptionsGetString or PetscOptionsStringArray, which cut a value at the buffer's size without a word): the
// text is looked up in the options database (PetscOptionsFindPair) and copied into a std::string whole.
//
// -help: PETSc 3.18 prints a string option as `-name <now X : formerly Y>` and an array by its first entry only.
// The suite's option readers (option_value.hpp, named_choice.hpp, optionsFileList below) print their own line
//   `  -name <value>: text`
// with the value in effect (the given one, else the default) whole, lists comma-separated in full, reals in
// their shortest exact form with a '.' or an exponent (`<0.>`, `<1e-10>`), integers as digits, flags as
// true/false. The line is printed where PETSc prints its own: -help given, the block's first pass, the block's
// title not printed before.
//
// Lists of files (-file a.dat,b.dat): a comma-separated list whose entries are
//   - a path, kept as given (the reader of the file reports a missing one);
//   - a glob pattern (an entry with *, ? or [): expanded with glob(3), the matches sorted; a pattern matching
//     nothing is an error naming it;
//   - @LIST: the entries of the text file LIST, one per line (a path or a glob pattern; commas are part of the
//     name there), `#` starts a comment, blank lines and leading/trailing blanks are ignored; a relative entry is
//     relative to LIST's folder (a list kept beside its files reads the same from any directory); a line starting
//     with @ is refused (lists are not nested).
// Rank 0 expands the list and every rank gets the same files or the same one error (collective).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {

// The text of option `name` (the block's prefix applied) as given, whole: *found is false if it is absent,
// *text "" if it is given without a value. The option is marked used.
PetscErrorCode findOptionText(PetscOptionItems* PetscOptionsObject, const char* name, std::string* text,
                              bool* found);
// The same outside an options block: the global database, no prefix.
PetscErrorCode findOptionText(const char* name, std::string* text, bool* found);

// Whether this pass of the options block prints -help lines (as PETSc decides for its own).
bool printsHelp(const PetscOptionItems* PetscOptionsObject);
// Under printsHelp: the line `  -name <value>: text`.
PetscErrorCode printOptionHelp(PetscOptionItems* PetscOptionsObject, const char* name,
                               const std::string& value, const std::string& text);

// A value as messages show it: whole up to 160 characters, else its first 120 and "... (N characters)".
std::string shownValue(const std::string& text);
// The shortest text that reads back as v (fixed notation unless longer), with a '.' where it would look like
// an integer: 0 -> "0.", 10000 -> "10000.", 1e-10 -> "1e-10", 0.1 -> "0.1", 1e+300, inf.
std::string realText(double v);

// Rank 0's *s on every rank of comm (any length).
PetscErrorCode broadcastString(MPI_Comm comm, std::string* s);

// The files of a file list (see above), on one process: "" or the reason the list is refused. option names the
// option in the messages.
std::string expandFileList(const std::string& option, const std::string& text,
                           std::vector<std::string>* files);
// Collective: rank 0 expands, every rank gets its files or the one error.
PetscErrorCode expandFileList(MPI_Comm comm, const std::string& option, const std::string& text,
                              std::vector<std::string>* files);
// A file-list option in the current options block: *files is the expanded list (left as is when the option is
// not given); -help shows the text as given.
PetscErrorCode optionsFileList(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                               std::vector<std::string>* files, PetscBool* set = nullptr);

// An error raised inside PetscOptionsBegin/End returns past PetscOptionsEnd and leaks the block's strings (LSan
// reports them): the block is closed first, then the collective error `message` is raised on the block's comm.
PetscErrorCode failInOptionsBlock(PetscOptionItems* PetscOptionsObject, PetscErrorCode code,
                                  const std::string& message);

} // namespace suite
