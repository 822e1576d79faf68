// Option text at any length and file lists (lib/core/option_text): a 100,000-character value is read whole, a
// 10,000-entry list keeps every entry, @LIST reads one path per line (comments, blank lines, paths relative to
// the list's folder), a glob pattern is expanded and sorted, a pattern matching nothing is one error naming it;
// an array given more entries than it holds is refused; -help prints `-name <value>: text` with lists whole and
// a choice list repeated by a later option once.
#include "../test_helpers.hpp"
#include "core/named_choice.hpp"
#include "core/option_text.hpp"
#include "core/option_value.hpp"

#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

// A scratch folder, removed at the end.
struct Scratch {
  std::string dir;
  Scratch() {
    char t[] = "/tmp/option_text_XXXXXX";
    dir = mkdtemp(t);
  }
  ~Scratch() { std::filesystem::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text = "x") const {
    std::ofstream(dir + "/" + name) << text;
    return dir + "/" + name;
  }
};

struct Values {
  std::string s = "default";
  std::vector<std::string> fruits = {"apple"}, files;
  PetscReal a[2] = {1.0, 2.0};
  PetscInt na = 2;
};

const std::vector<suite::Choice> kFruit = {{"apple", "a pome"}, {"cherry", "a drupe"}, {"fig", "a syconium"}};

PetscErrorCode readAll(Values* v, const char* title = "Option text test") {
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, "", title, "");
  PetscCall(suite::optionsString(PetscOptionsObject, "-s", "A string", &v->s));
  PetscCall(suite::optionsChoiceList(PetscOptionsObject, "-fruits", "Fruits", kFruit, &v->fruits));
  PetscCall(suite::optionsFileList(PetscOptionsObject, "-files", "Files", &v->files));
  PetscCall(suite::optionsRealArray(PetscOptionsObject, "-a", "Two reals", "", v->a, &v->na, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode readWith(const char* name, const std::string& value, Values* v) {
  PetscOptionsSetValue(nullptr, name, value.c_str());
  const PetscErrorCode ierr = suite_test::quietly([&] { return readAll(v); });
  PetscOptionsClearValue(nullptr, name);
  return ierr;
}

std::string repeated(const std::string& entry, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += (i ? "," : "") + entry;
  return s;
}

TEST(OptionText, LongValueIsReadWhole) {
  Values v;
  const std::string value(100000, 'x');
  ASSERT_EQ(readWith("-s", value, &v), 0);
  EXPECT_EQ(v.s.size(), 100000u);
  EXPECT_EQ(v.s, value);
  std::string text;
  bool found = false;
  PetscOptionsSetValue(nullptr, "-option_text_long", value.c_str());
  ASSERT_EQ(suite::findOptionText("-option_text_long", &text, &found), 0);
  PetscOptionsClearValue(nullptr, "-option_text_long");
  EXPECT_TRUE(found);
  EXPECT_EQ(text, value);
}

TEST(OptionText, TenThousandEntryListsKeepEveryEntry) {
  Values v;
  ASSERT_EQ(readWith("-fruits", repeated("fig", 10000), &v), 0);
  EXPECT_EQ(v.fruits.size(), 10000u);
  EXPECT_EQ(v.fruits.back(), "fig");
  std::string files;
  for (int i = 0; i < 10000; ++i) files += (i ? ",d/p" : "d/p") + std::to_string(i) + ".dat";
  ASSERT_EQ(readWith("-files", files, &v), 0);
  ASSERT_EQ(v.files.size(), 10000u);
  EXPECT_EQ(v.files[0], "d/p0.dat");
  EXPECT_EQ(v.files[9999], "d/p9999.dat");
  // an unknown entry far down the list is still found
  EXPECT_EQ(readWith("-fruits", repeated("fig", 9999) + ",kiwi", &v), PETSC_ERR_ARG_UNKNOWN_TYPE);
}

TEST(OptionText, ArrayGivenTooManyEntriesIsRefused) {
  Values v;
  ASSERT_EQ(readWith("-a", "3,4", &v), 0);
  EXPECT_EQ(v.a[1], 4.0);
  v.na = 2;
  EXPECT_EQ(readWith("-a", "1,2,3", &v), PETSC_ERR_ARG_WRONG);
  v.na = 2;
  EXPECT_EQ(readWith("-a", repeated("1", 10000), &v), PETSC_ERR_ARG_WRONG);
}

TEST(OptionText, ListFileReadsOnePathPerLine) {
  Scratch d;
  d.write("sub_a.dat");
  const std::string list =
      d.write("list.txt", "# problems\n\nsub_a.dat\n  spaced name.dat  # trailing comment\n/abs/b.h5\r\n");
  std::vector<std::string> files;
  ASSERT_EQ(suite::expandFileList("-file", "@" + list + ",tail.dat", &files), "");
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(files[0], d.dir + "/sub_a.dat"); // relative to the list's folder
  EXPECT_EQ(files[1], d.dir + "/spaced name.dat");
  EXPECT_EQ(files[2], "/abs/b.h5");
  EXPECT_EQ(files[3], "tail.dat"); // command-line entries as given
  EXPECT_NE(suite::expandFileList("-file", "@" + d.dir + "/missing.txt", &files).find("cannot open"),
            std::string::npos);
  const std::string nested = d.write("nested.txt", "@list.txt\n");
  EXPECT_NE(suite::expandFileList("-file", "@" + nested, &files).find("not nested"), std::string::npos);
  // through the option, collectively
  Values v;
  ASSERT_EQ(readWith("-files", "@" + list, &v), 0);
  EXPECT_EQ(v.files.size(), 3u);
}

TEST(OptionText, GlobIsExpandedAndSorted) {
  Scratch d;
  for (const char* f : {"p2.h5", "p10.h5", "p1.h5", "q.dat"}) d.write(f);
  std::vector<std::string> files;
  ASSERT_EQ(suite::expandFileList("-file", d.dir + "/p*.h5," + d.dir + "/q.dat", &files), "");
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(files[0], d.dir + "/p1.h5");
  EXPECT_EQ(files[1], d.dir + "/p10.h5");
  EXPECT_EQ(files[2], d.dir + "/p2.h5");
  EXPECT_EQ(files[3], d.dir + "/q.dat");
  const std::string list = d.write("list.txt", "p?.h5\n");
  ASSERT_EQ(suite::expandFileList("-file", "@" + list, &files), "");
  EXPECT_EQ(files, (std::vector<std::string>{d.dir + "/p1.h5", d.dir + "/p2.h5"}));
}

TEST(OptionText, GlobWithoutMatchIsOneError) {
  Scratch d;
  std::vector<std::string> files;
  const std::string why = suite::expandFileList("-file", d.dir + "/*.h5", &files);
  EXPECT_NE(why.find("-file: no file matches '" + d.dir + "/*.h5'"), std::string::npos) << why;
  Values v;
  EXPECT_EQ(readWith("-files", d.dir + "/none_*.dat", &v), PETSC_ERR_FILE_OPEN);
  EXPECT_EQ(suite_test::quietly(
                [&] { return suite::expandFileList(PETSC_COMM_WORLD, "-file", d.dir + "/x*", &files); }),
            PETSC_ERR_FILE_OPEN);
}

TEST(OptionText, RealTextIsShortAndReadsBack) {
  EXPECT_EQ(suite::realText(0.0), "0.");
  EXPECT_EQ(suite::realText(1e4), "10000.");
  EXPECT_EQ(suite::realText(-9.81), "-9.81");
  EXPECT_EQ(suite::realText(1e-10), "1e-10");
  EXPECT_EQ(suite::realText(0.1), "0.1");
  EXPECT_EQ(std::strtod(suite::realText(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);
  EXPECT_EQ(suite::shownValue(std::string(200, 'y')).size(),
            120u + std::string("... (200 characters)").size());
}

std::string g_help;
PetscErrorCode captureHelp(MPI_Comm, const char format[], ...) {
  char b[4096];
  va_list ap;
  va_start(ap, format);
  std::vsnprintf(b, sizeof b, format, ap);
  va_end(ap);
  g_help += b;
  return 0;
}

PetscErrorCode readShared(const char* title) {
  std::string one = "fig";
  std::vector<std::string> many = {"apple", "cherry"};
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, "", title, "");
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-help_fruit", "A fruit", kFruit, &one));
  PetscCall(suite::optionsChoiceList(PetscOptionsObject, "-help_fruits", "Fruits",
                                     {kFruit[0], kFruit[1], kFruit[2], {"kiwi", "a berry"}}, &many));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

TEST(OptionText, HelpShowsValuesWholeAndEachListOnce) {
  Values v;
  PetscOptionsSetValue(nullptr, "-help", nullptr);
  auto* const saved = PetscHelpPrintf;
  PetscHelpPrintf = captureHelp;
  g_help.clear();
  const PetscErrorCode a = readAll(&v, "Option text help test");
  const PetscErrorCode b = readShared("Option text help test, shared list");
  PetscHelpPrintf = saved;
  PetscOptionsClearValue(nullptr, "-help");
  ASSERT_EQ(a, 0);
  ASSERT_EQ(b, 0);
  EXPECT_NE(g_help.find("  -s <default>: A string\n"), std::string::npos) << g_help;
  EXPECT_NE(g_help.find("  -a <1.,2.>: Two reals\n"), std::string::npos) << g_help;
  EXPECT_NE(g_help.find("  -fruits <apple>: Fruits (comma-separated list); each one of:\n      apple"),
            std::string::npos)
      << g_help;
  // -help_fruit repeats -fruits' list: one line naming it; -help_fruits adds kiwi to it
  EXPECT_NE(g_help.find("  -help_fruit <fig>: A fruit; one of:\n      (as -fruits)\n  -help_fruits"),
            std::string::npos)
      << g_help;
  EXPECT_NE(g_help.find("      (as -fruits)\n      kiwi  a berry\n"), std::string::npos) << g_help;
  EXPECT_EQ(g_help.find("now"), std::string::npos) << g_help;
}

} // namespace
