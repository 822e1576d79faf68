// Collective field checks: the first offending global index is found and reported as an error.
#include "../test_helpers.hpp"
#include "core/field_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using suite_test::fileExists;
using suite_test::quietly;

TEST(FieldCheck, FiniteDataPasses) {
  std::vector<double> d{1.0, 2.0, -3.0};
  EXPECT_EQ(suite::checkFinite(PETSC_COMM_WORLD, d.data(), 3, 1, 0, {"rho", 1, 0.1, 0}), 0);
  EXPECT_EQ(suite::checkAbove(PETSC_COMM_WORLD, d.data(), 2, 1, 0, 0.0, {"rho", 1, 0.1, 0}), 0);
}

TEST(FieldCheck, NanInfAndNegativeAreErrors) {
  std::vector<double> d{1.0, NAN, 2.0};
  EXPECT_EQ(quietly([&] {
              return suite::checkFinite(PETSC_COMM_WORLD, d.data(), 3, 1, 0, {"rho", 1, 0.1, 0});
            }),
            PETSC_ERR_FP);
  d[1] = INFINITY;
  EXPECT_EQ(quietly([&] {
              return suite::checkFinite(PETSC_COMM_WORLD, d.data(), 3, 1, 0, {"rho", 1, 0.1, 0});
            }),
            PETSC_ERR_FP);
  // Strided: component 1 of (rho, p) pairs holds a negative pressure; component 0 is fine.
  std::vector<double> s{1.0, 1.0, 1.0, -1e-3};
  EXPECT_EQ(suite::checkAbove(PETSC_COMM_WORLD, s.data(), 2, 2, 0, 0.0, {"rho", 1, 0.1, 0}), 0);
  EXPECT_EQ(quietly([&] {
              return suite::checkAbove(PETSC_COMM_WORLD, s.data(), 2, 2, 1, 0.0, {"p", 1, 0.1, 0});
            }),
            PETSC_ERR_FP);
}

} // namespace
