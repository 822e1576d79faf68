// Options file check (lib/core/options_file_check): the line classifier of plain options files against what
// PETSc 3.18 reads (found by experiment: '#' comments, one value per option, "double quotes", alias lines),
// the text check, and the YAML check with the line of the problem.
#include "core/options_file_check.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

using suite::OptionsLine;

OptionsLine::Kind kindOf(const std::string& line) {
  return suite::classifyOptionsLine(line).kind;
}

TEST(OptionsFileCheck, BlankAndCommentLines) {
  for (const char* l : {"", "   ", "\t \r", "# a comment", "   # indented comment", "#-nx 10"})
    EXPECT_EQ(kindOf(l), OptionsLine::Blank) << l;
}

TEST(OptionsFileCheck, OptionLines) {
  const OptionsLine a = suite::classifyOptionsLine("  -ksp_type\tcg   # trailing comment\r");
  EXPECT_EQ(a.kind, OptionsLine::Option);
  EXPECT_EQ(a.name, "-ksp_type");
  EXPECT_EQ(a.value, "cg");
  const OptionsLine flag = suite::classifyOptionsLine("-quiet");
  EXPECT_EQ(flag.kind, OptionsLine::Option);
  EXPECT_EQ(flag.value, "");
  EXPECT_EQ(suite::classifyOptionsLine("-title \"a b c\"").value, "a b c");
  EXPECT_EQ(suite::classifyOptionsLine("-rho_l -1.5").value, "-1.5"); // a negative number is a value
  EXPECT_EQ(suite::classifyOptionsLine("-p_r -inf").value, "-inf");   // so is -inf (PETSc: strtod)
  EXPECT_EQ(suite::classifyOptionsLine("-beam_cells 10,2,2").value, "10,2,2");
  EXPECT_EQ(kindOf("--double_dash 1"), OptionsLine::Option);
}

TEST(OptionsFileCheck, AliasLines) {
  const OptionsLine a = suite::classifyOptionsLine("ALIAS -n -nx");
  EXPECT_EQ(a.kind, OptionsLine::Alias);
  EXPECT_EQ(a.name, "-n");
  EXPECT_EQ(a.value, "-nx");
  EXPECT_EQ(kindOf("alias -n"), OptionsLine::Invalid);
  EXPECT_EQ(kindOf("alias -n -nx -ny"), OptionsLine::Invalid);
}

TEST(OptionsFileCheck, InvalidLinesSayWhy) {
  const OptionsLine bare = suite::classifyOptionsLine("hello world");
  EXPECT_EQ(bare.kind, OptionsLine::Invalid);
  EXPECT_NE(bare.problem.find("'hello world' is not an option"), std::string::npos) << bare.problem;
  EXPECT_NE(suite::classifyOptionsLine("-b 2 3 4").problem.find("more than one value"), std::string::npos);
  EXPECT_NE(suite::classifyOptionsLine("-a 1 -b 2").problem.find("more than one value"), std::string::npos);
  EXPECT_NE(suite::classifyOptionsLine("-a -b").problem.find("two options"), std::string::npos);
  EXPECT_NE(suite::classifyOptionsLine("-1 x").problem.find("option name"), std::string::npos);
  EXPECT_EQ(kindOf("- 3"), OptionsLine::Invalid);
  EXPECT_EQ(kindOf("! not a comment for PETSc"), OptionsLine::Invalid);
  EXPECT_EQ(kindOf("% nor is this"), OptionsLine::Invalid);
  EXPECT_EQ(kindOf("nx: 10"), OptionsLine::Invalid); // YAML in a file PETSc reads as a plain options file
}

TEST(OptionsFileCheck, NonTextIsFoundWithLineColumnAndHexByte) {
  EXPECT_EQ(suite::findNonText("-nx 10\n\t-a 1\r\n-title \xC3\xA9t\xC3\xA9\n"), "");
  EXPECT_EQ(suite::findNonText(std::string("\0\0\0\0abc\n", 8)), "line 1, column 1: byte 0x00 (NUL)");
  EXPECT_EQ(suite::findNonText("-a 1\n-b \x01\n"), "line 2, column 4: byte 0x01 (a control character)");
  EXPECT_EQ(suite::findNonText("-a 1\n\n-b \xFF\n"), "line 3, column 4: byte 0xFF (not UTF-8)");
  EXPECT_EQ(suite::findNonText("\xC0\xAF"), "line 1, column 1: byte 0xC0 (not UTF-8)");      // overlong '/'
  EXPECT_EQ(suite::findNonText("x\xED\xA0\x80"), "line 1, column 2: byte 0xED (not UTF-8)"); // surrogate
  EXPECT_EQ(suite::findNonText("\xE2\x82"), "line 1, column 1: byte 0xE2 (not UTF-8)");      // truncated
  EXPECT_EQ(suite::findNonText("\x7F"), "line 1, column 1: byte 0x7F (a control character)");
}

TEST(OptionsFileCheck, ExcerptsAreEscapedAndTruncated) {
  EXPECT_EQ(suite::escapedExcerpt(std::string("a\0b\x1b\xFF", 5)), "a\\x00b\\x1B\\xFF");
  EXPECT_EQ(suite::escapedExcerpt("\xC3\xA9t\xC3\xA9"), "\xC3\xA9t\xC3\xA9");
  EXPECT_EQ(suite::escapedExcerpt(std::string(100, 'x'), 10), std::string(10, 'x') + "...");
}

TEST(OptionsFileCheck, PlainTextReportsTheLineAndIncludes) {
  std::vector<suite::IncludedFile> inc;
  EXPECT_EQ(
      suite::checkPlainOptionsText("# deck\n-nx 10\n\n-options_file other.txt\n-options_file_yaml o\n", &inc),
      "");
  ASSERT_EQ(inc.size(), 2u);
  EXPECT_EQ(inc[0].name, "other.txt");
  EXPECT_EQ(inc[0].line, 4);
  EXPECT_FALSE(inc[0].yaml_flag);
  EXPECT_TRUE(inc[1].yaml_flag);
  EXPECT_EQ(suite::checkPlainOptionsText("-nx 10\nfoo\n", &inc).rfind("line 2: 'foo' is not an option", 0),
            0u);
  EXPECT_EQ(suite::checkPlainOptionsText("-options_file\n", &inc),
            "line 1: -options_file without a file name");
  EXPECT_EQ(suite::checkPlainOptionsText(std::string("-nx 10\n\0\1\2", 10), &inc),
            "is not a text file: line 2, column 1: byte 0x00 (NUL)");
}

TEST(OptionsFileCheck, YamlDecks) {
  EXPECT_EQ(suite::checkYamlOptionsText("# Sod\nproblem: sod\nnx: 200\nksp:\n  type: cg\nb: [1, 2]\n"), "");
  EXPECT_EQ(suite::checkYamlOptionsText(""), "");
  EXPECT_EQ(suite::checkYamlOptionsText("---\n"), "");
  EXPECT_EQ(suite::checkYamlOptionsText("a: 1\n---\nb: 2\n"), "");
  EXPECT_EQ(suite::checkYamlOptionsText("a:\n  - b: 1\n  - c: 2\n"), "");
  const std::string flow = suite::checkYamlOptionsText("nx: 10\nsteps: [this is not\n");
  EXPECT_EQ(flow.rfind("line 3, column 1: YAML: did not find expected ',' or ']'", 0), 0u) << flow;
  EXPECT_NE(flow.find("at line 2, column 8"), std::string::npos) << flow;
  const std::string indent = suite::checkYamlOptionsText("a: 1\n b: 2\n");
  EXPECT_EQ(indent.rfind("line 2, column 3: YAML: ", 0), 0u) << indent;
  EXPECT_EQ(suite::checkYamlOptionsText("- 1\n- 2\n"),
            "line 1, column 1: the top level of a YAML options file must be a mapping (name: value)");
  EXPECT_EQ(suite::checkYamlOptionsText("just words\n").rfind("line 1, column 1: the top level", 0), 0u);
  EXPECT_EQ(suite::checkYamlOptionsText("a: [[1, 2], 3]\n"),
            "line 1, column 5: a list inside a list is not an option value");
  EXPECT_EQ(suite::checkYamlOptionsText("? [1]\n: 2\n"),
            "line 1, column 3: a key must be an option name, not a list");
  EXPECT_NE(suite::checkYamlOptionsText("nx: 10\noptions_file: other.yaml\n")
                .find("line 2, column 1: 'options_file'"),
            std::string::npos);
  EXPECT_EQ(suite::checkYamlOptionsText("a: 1\n\xFF\n"),
            "is not a text file: line 2, column 1: byte 0xFF (not UTF-8)");
}

TEST(OptionsFileCheck, YamlIsChosenAsPetscChooses) {
  EXPECT_TRUE(suite::optionsFileIsYaml("d.yaml", false, ""));
  EXPECT_TRUE(suite::optionsFileIsYaml("d.yml", false, ""));
  EXPECT_TRUE(suite::optionsFileIsYaml("d.json", false, ""));
  EXPECT_TRUE(suite::optionsFileIsYaml("d:yaml", false, ""));
  EXPECT_TRUE(suite::optionsFileIsYaml("d.txt", true, ""));
  EXPECT_TRUE(suite::optionsFileIsYaml("deck", false, "---\na:"));
  EXPECT_TRUE(suite::optionsFileIsYaml("deck", false, "%YAML 1.1"));
  EXPECT_FALSE(suite::optionsFileIsYaml("deck.YAML", false, "-a 1"));
  EXPECT_EQ(suite::optionsFilePath("d:yaml"), "d");
  EXPECT_EQ(suite::optionsFilePath("d.yaml"), "d.yaml");
}

// The whole check through checkOptionsFiles on files written here (one rank of the unit test's world).
std::string checkArgs(std::vector<std::string> args) {
  args.insert(args.begin(), "prog");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::string message;
  EXPECT_EQ(suite::checkOptionsFiles(MPI_COMM_SELF, (int)argv.size(), argv.data(), &message), MPI_SUCCESS);
  return message;
}

void writeFile(const std::string& name, const std::string& bytes) {
  std::ofstream(name, std::ios::binary) << bytes;
}

TEST(OptionsFileCheck, FilesOnTheCommandLine) {
  writeFile("ofc_good.txt", "-nx 10\n");
  writeFile("ofc_outer.txt", "-a 1\n-options_file ofc_inner.txt\n");
  writeFile("ofc_inner.txt", "-b 2\nbare\n");
  writeFile("ofc_self.txt", "-options_file ofc_self.txt\n");
  EXPECT_EQ(checkArgs({"-nx", "3", "-options_file", "ofc_good.txt", "-options_file"}), "");
  EXPECT_EQ(checkArgs({"-options_file", "ofc_missing.yaml"}),
            "options file 'ofc_missing.yaml' cannot be read: No such file or directory");
  EXPECT_EQ(checkArgs({"-options_file", "."}), "options file '.' is a directory, not a file");
  EXPECT_EQ(
      checkArgs({"-OPTIONS_FILE", "ofc_outer.txt"}),
      "options file 'ofc_inner.txt' line 2: 'bare' is not an option (-name [value]), an alias (alias -new "
      "-existing), a comment (#) or blank (included by 'ofc_outer.txt' line 2)");
  EXPECT_NE(checkArgs({"-options_file", "ofc_self.txt"}).find("includes itself"), std::string::npos);
  EXPECT_EQ(checkArgs({"-options_file_yaml", "ofc_good.txt"})
                .rfind("options file 'ofc_good.txt' line 1, column 1: "
                       "the top level",
                       0),
            0u);
  // PETSc reads PETSC_OPTIONS before the command line, -options_file included.
  const char* saved = std::getenv("PETSC_OPTIONS");
  const std::string keep = saved ? saved : "";
  setenv("PETSC_OPTIONS", "-quiet -options_file \"ofc_missing.txt\"", 1);
  EXPECT_EQ(checkArgs({"-options_file", "ofc_good.txt"}),
            "options file 'ofc_missing.txt' cannot be read: No such file or directory");
  if (saved)
    setenv("PETSC_OPTIONS", keep.c_str(), 1);
  else
    unsetenv("PETSC_OPTIONS");
  for (const char* f : {"ofc_good.txt", "ofc_outer.txt", "ofc_inner.txt", "ofc_self.txt"}) std::remove(f);
}

} // namespace
