// Options files (run decks) are checked before PETSc reads them. PETSc 3.18 stops reading a line at
// a NUL byte (a binary file is silently ignored), prints the raw bytes of a binary line, reports a YAML syntax
// error without its line, and recurses until the stack overflows on a file that includes itself. The check
// reads every file named by -options_file / -options_file_yaml on the command line or in PETSC_OPTIONS (and the
// files that a plain options file includes) and reports the first problem as one message naming the file and the line.
//
// What is accepted is what PETSc 3.18 reads (src/sys/objects/options.c, PetscOptionsInsertFilePetsc and
// PetscOptionsInsertFileYAML), nothing more:
//  - every file: text, i.e. UTF-8 without NUL or control characters other than tab, CR and LF;
//  - a plain options file, line by line: text from '#' on is a comment ('!' and '%' are not comments); tabs and
//    CR are blanks; a line is blank, "-name [value]" (one value; a value with blanks in "double quotes"), or
//    "alias -new -existing"; an "-options_file F" line includes F (a path relative to the working directory);
//  - YAML (a name ending in .yaml, .yml or .json, a ':yaml' suffix, -options_file_yaml, or a file that begins
//    with "%YAML " or "---", as PETSc decides): what libyaml parses, a mapping at the top of each document,
//    names (scalars) as keys, and as values a scalar, a mapping or a list of scalars or mappings. A YAML deck
//    cannot include another file (PETSc 3.18 keeps an options_file key as an option and never reads the file).
// A name with "${" (PETSc substitutes variables) or a pipe (read once, by PETSc) is left to PETSc.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace suite {

// One line (without its newline) of a plain options file.
struct OptionsLine {
  enum Kind { Blank, Option, Alias, Invalid };
  Kind kind = Blank;
  std::string name;    // Option, Alias: the option name ("-ksp_type"), or the new name of an alias
  std::string value;   // Option: its value ("" when none); Alias: the existing name
  std::string problem; // Invalid: what is wrong, for the message
};
OptionsLine classifyOptionsLine(const std::string& line);

// The first byte that is not text (NUL, a control character other than tab/CR/LF, invalid UTF-8) as
// "line L, column C: byte 0xNN (what)" (column counted in bytes); "" when all of it is text.
std::string findNonText(const std::string& bytes);

// `text` printable for a message: control and non-UTF-8 bytes as \xNN, at most max_chars bytes, then "...".
std::string escapedExcerpt(const std::string& text, size_t max_chars = 60);

// An options file that a plain options file includes (its -options_file or -options_file_yaml lines).
struct IncludedFile {
  std::string name;
  bool yaml_flag = false; // named by -options_file_yaml: YAML whatever its name
  int line = 0;
};
// The contents of one file: "" when PETSc reads them as intended, else what is wrong, to follow the file's
// name in a message ("line L: ...", "is not text: line L, column C: ...").
std::string checkPlainOptionsText(const std::string& text, std::vector<IncludedFile>* included);
std::string checkYamlOptionsText(const std::string& text);

// PETSc's reading of the value `arg` of -options_file: the file's name (without a ':yaml' suffix), and whether
// it is read as YAML (yaml_flag: named by -options_file_yaml; head: the first bytes of the file).
std::string optionsFilePath(const std::string& arg);
bool optionsFileIsYaml(const std::string& arg, bool yaml_flag, const std::string& head);

// Collective on comm (needs MPI, not PETSc): rank 0 checks every options file named in PETSC_OPTIONS and argv
// and every file they include; on return every rank holds the same message, "" when all are fine.
int checkOptionsFiles(MPI_Comm comm, int argc, char** argv, std::string* message);

} // namespace suite
