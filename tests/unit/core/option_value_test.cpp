// Numeric and flag options (lib/core/option_value): the value is read when it is valid; no value, an empty one,
// text, nan, inf (unless the option accepts it), an integer beyond PetscInt and a non-flag are one error each;
// every entry of an array is checked.
#include "../test_helpers.hpp"
#include "core/option_value.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

struct Values {
  PetscReal r = 1.0, r_inf = 1.0, a[3] = {0, 0, 0};
  PetscInt i = 1, ia[3] = {0, 0, 0}, na = 3, nia = 3;
  PetscBool b = PETSC_FALSE;
};

PetscErrorCode readAll(Values* v) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, "", "Option value test", "");
  PetscCall(suite::optionsValue(PetscOptionsObject, "-r", "A real", &v->r));
  PetscCall(suite::optionsValue(PetscOptionsObject, "-r_inf", "A real or inf", &v->r_inf, nullptr,
                                suite::Real::or_inf));
  PetscCall(suite::optionsValue(PetscOptionsObject, "-i", "An integer", &v->i));
  PetscCall(suite::optionsValue(PetscOptionsObject, "-b", "A flag", &v->b));
  PetscCall(suite::optionsRealArray(PetscOptionsObject, "-a", "Reals", "", v->a, &v->na, nullptr));
  PetscCall(suite::optionsIntArray(PetscOptionsObject, "-ia", "Integers", "", v->ia, &v->nia, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

// The error code of reading the options with `name` set to `value` (nullptr: no value).
PetscErrorCode readWith(const char* name, const char* value, Values* v) {
  PetscOptionsSetValue(nullptr, name, value);
  const PetscErrorCode ierr = suite_test::quietly([&] { return readAll(v); });
  PetscOptionsClearValue(nullptr, name);
  return ierr;
}

TEST(OptionValue, ValidValuesAreRead) {
  Values v;
  ASSERT_EQ(readWith("-r", "2.5e3", &v), 0);
  ASSERT_EQ(readWith("-r_inf", "-inf", &v), 0);
  ASSERT_EQ(readWith("-i", "-2147483648", &v), 0);
  ASSERT_EQ(readWith("-b", nullptr, &v), 0);
  EXPECT_EQ(v.r, 2.5e3);
  EXPECT_TRUE(std::isinf(v.r_inf) && v.r_inf < 0);
  EXPECT_EQ(v.i, PETSC_MIN_INT);
  EXPECT_TRUE(v.b);
  v.na = 3; // (an array not given has n = 0 afterwards, as in PETSc)
  ASSERT_EQ(readWith("-a", "1,2.5", &v), 0);
  EXPECT_EQ(v.na, 2);
  EXPECT_EQ(v.a[1], 2.5);
  v.nia = 3;
  ASSERT_EQ(readWith("-ia", "4,5,6", &v), 0);
  EXPECT_EQ(v.nia, 3);
  EXPECT_EQ(v.ia[2], 6);
}

TEST(OptionValue, HostileValuesAreOneError) {
  Values v;
  for (const char* name : {"-r", "-i", "-a", "-ia"})
    for (const char* bad : {"nan", "inf", "-inf", "", "abc", "1e400"})
      EXPECT_EQ(readWith(name, bad, &v), PETSC_ERR_ARG_WRONG) << name << " '" << bad << "'";
  for (const char* name : {"-r", "-i", "-a", "-ia"})
    EXPECT_EQ(readWith(name, nullptr, &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-r_inf", "nan", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-i", "2147483648", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-i", "1.5", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-ia", "1,,2", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-a", "1,nan", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(readWith("-b", "maybe", &v), PETSC_ERR_ARG_WRONG);
  EXPECT_EQ(v.i, 1); // nothing was read
  EXPECT_EQ(v.r, 1.0);
}

} // namespace
