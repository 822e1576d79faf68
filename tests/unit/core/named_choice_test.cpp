// Named-choice options (lib/core/named_choice): a registered value is read, the default is kept, an unknown
// value is one error naming the option and the known values, a list is read in order with each entry checked.
#include "../test_helpers.hpp"
#include "core/named_choice.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

const std::vector<suite::Choice> kFruit = {{"apple", "a pome"}, {"cherry", "a drupe"}, {"fig", "a syconium"}};

PetscErrorCode readOne(std::string* value, PetscBool* set) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, "", "Named choice test", "");
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-fruit", "A fruit", kFruit, value, set));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode readList(std::vector<std::string>* values) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, "", "Named choice test", "");
  PetscCall(suite::optionsChoiceList(PetscOptionsObject, "-fruits", "Fruits", kFruit, values));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

TEST(NamedChoice, DefaultKeptAndGivenValueRead) {
  std::string v = "cherry";
  PetscBool set = PETSC_TRUE;
  ASSERT_EQ(readOne(&v, &set), 0);
  EXPECT_EQ(v, "cherry");
  EXPECT_FALSE(set);
  PetscOptionsSetValue(nullptr, "-fruit", "fig");
  ASSERT_EQ(readOne(&v, &set), 0);
  PetscOptionsClearValue(nullptr, "-fruit");
  EXPECT_EQ(v, "fig");
  EXPECT_TRUE(set);
}

TEST(NamedChoice, UnknownValueIsAnError) {
  std::string v = "apple";
  PetscOptionsSetValue(nullptr, "-fruit", "banana");
  EXPECT_EQ(suite_test::quietly([&] { return readOne(&v, nullptr); }), PETSC_ERR_ARG_UNKNOWN_TYPE);
  PetscOptionsClearValue(nullptr, "-fruit");
  EXPECT_EQ(suite::choiceNames(kFruit), "apple, cherry or fig");
}

TEST(NamedChoice, ListKeepsOrderAndChecksEachEntry) {
  std::vector<std::string> v = {"apple"};
  ASSERT_EQ(readList(&v), 0);
  EXPECT_EQ(v, (std::vector<std::string>{"apple"}));
  PetscOptionsSetValue(nullptr, "-fruits", "fig,apple");
  ASSERT_EQ(readList(&v), 0);
  EXPECT_EQ(v, (std::vector<std::string>{"fig", "apple"}));
  PetscOptionsSetValue(nullptr, "-fruits", "fig,kiwi");
  EXPECT_EQ(suite_test::quietly([&] { return readList(&v); }), PETSC_ERR_ARG_UNKNOWN_TYPE);
  PetscOptionsSetValue(nullptr, "-fruits", "fig,,apple");
  EXPECT_EQ(suite_test::quietly([&] { return readList(&v); }), PETSC_ERR_ARG_WRONG);
  PetscOptionsClearValue(nullptr, "-fruits");
}

} // namespace

namespace {
struct Entry {
  const char* name;
  const char* description;
  int payload;
};

TEST(NamedChoice, ChoicesOfARegistryKeepNamesDescriptionsAndOrder) {
  const Entry registry[] = {{"b", "second letter", 2}, {"a", "first letter", 1}};
  const std::vector<suite::Choice> c = suite::choicesOf(registry);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].name, "b");
  EXPECT_EQ(c[0].help, "second letter");
  EXPECT_EQ(c[1].name, "a");
  EXPECT_EQ(c[1].help, "first letter");
}
} // namespace
