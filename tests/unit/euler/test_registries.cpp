// The registries that document -problem and -scheme in the Euler app's -help: every registered
// value has a one-line description, and the documented lists are exactly the lists the factories accept.
#include "euler/problem.hpp"
#include "euler/problem_nd.hpp"
#include "euler/schemes.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

using namespace suite::euler;

namespace {
std::string joined(const std::vector<ProblemDoc>& docs) {
  std::string out;
  for (const ProblemDoc& d : docs) out += (out.empty() ? "" : ", ") + std::string(d.name);
  return out;
}
void expectDocumented(const std::vector<ProblemDoc>& docs) {
  std::set<std::string> seen;
  for (const ProblemDoc& d : docs) {
    EXPECT_TRUE(seen.insert(d.name).second) << d.name << " registered twice";
    ASSERT_NE(d.description, nullptr) << d.name;
    EXPECT_GT(std::strlen(d.description), 10u) << d.name;
    EXPECT_EQ(std::strchr(d.description, '\n'), nullptr) << d.name << ": one line";
  }
}
} // namespace

TEST(EulerRegistries, ProblemsOneDAreDocumented) {
  expectDocumented(problemDocs());
  EXPECT_EQ(joined(problemDocs()), problemNames());
}

TEST(EulerRegistries, ProblemsNDAreDocumented) {
  expectDocumented(problemDocsND());
  EXPECT_EQ(joined(problemDocsND()) + "; planar (1D problems along -axis): " + problemNames(),
            problemNamesND());
}

TEST(EulerRegistries, SchemesAreDocumentedAndFound) {
  std::string names;
  for (const SchemeInfo* s : allSchemes()) {
    ASSERT_NE(s->description, nullptr);
    EXPECT_GT(std::strlen(s->description), 10u) << s->name;
    EXPECT_EQ(findScheme(s->name), s);
    names += (names.empty() ? "" : ", ") + std::string(s->name);
  }
  EXPECT_EQ(names, schemeNames());
}
