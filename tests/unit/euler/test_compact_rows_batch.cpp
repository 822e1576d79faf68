// The batched compact rows (compact_rows_batch.hpp) against the scalar row functions they stand for: the same
// rows bitwise on smooth, discontinuous, constant, tiny, signed and non-finite stencils, for stencil counts that
// leave every remainder of the four-lane loop.
#include "euler/compact_rows_batch.hpp"
#include "euler/crweno5.hpp"
#include "euler/crweno_cu6.hpp"
#include "euler/enopade6.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace suite::euler;

namespace {

uint64_t bits(double x) {
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Stencil i of a varied set: kinds cycle through smooth, jump, constant, tiny, large-signed, random, NaN.
std::vector<double> stencil(int i, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(6);
  const double x0 = u(rng), h = 0.01 + 0.1 * std::abs(u(rng));
  for (int m = 0; m < 6; ++m) {
    const double x = x0 + m * h;
    switch (i % 7) {
    case 0:
      v[m] = std::sin(3.0 * x) + 2.0;
      break; // smooth
    case 1:
      v[m] = m < 3 ? 1.0 : 0.125 + 1e-3 * u(rng);
      break; // a jump
    case 2:
      v[m] = 0.7;
      break; // constant
    case 3:
      v[m] = 1e-300 * (1.0 + u(rng));
      break; // near underflow
    case 4:
      v[m] = (m % 2 ? -1e8 : 1e8) * (1.0 + 0.1 * u(rng));
      break; // large, alternating sign
    case 5:
      v[m] = u(rng);
      break; // random
    default:
      v[m] = m == 4 ? std::numeric_limits<double>::quiet_NaN() : x;
      break;
    }
  }
  return v;
}

// Runs the batched function on n stencils and compares each row with fn's; returns how many rows were the
// ENO-Pade row's pure CU6 case (theta = 1), to show that both arms of its select were exercised.
int expectSameRows(RowFunction fn, RowsFunction batch, int n) {
  std::mt19937_64 rng(42 + n);
  std::vector<double> soa((size_t)6 * n), out((size_t)4 * n);
  std::vector<Row> want(n);
  for (int i = 0; i < n; ++i) {
    const std::vector<double> v = stencil(i, rng);
    for (int m = 0; m < 6; ++m) soa[(size_t)m * n + i] = v[m];
    want[i] = fn(v.data());
  }
  batch(n, soa.data(), out.data());
  int pure = 0;
  for (int i = 0; i < n; ++i) {
    const double got[4] = {out[i], out[n + i], out[2 * n + i], out[3 * n + i]};
    const double exp[4] = {want[i].a, want[i].b, want[i].c, want[i].r};
    for (int j = 0; j < 4; ++j) {
      if (std::isnan(exp[j])) {
        EXPECT_TRUE(std::isnan(got[j])) << "stencil " << i << " entry " << j;
        continue;
      }
      EXPECT_EQ(bits(got[j]), bits(exp[j]))
          << "stencil " << i << " of " << n << " entry " << j << ": " << got[j] << " vs " << exp[j];
    }
    if (std::isfinite(exp[0])) {
      std::vector<double> v(6);
      for (int m = 0; m < 6; ++m) v[m] = soa[(size_t)m * n + i];
      double w[4];
      cu6Weights(v.data(), w);
      pure += bits(cu6RowFromWeights(v.data(), w).r) == bits(exp[3]) ? 1 : 0;
    }
  }
  return pure;
}

} // namespace

TEST(CompactRowsBatch, Crweno5RowsAreTheScalarRowsBitwise) {
  const RowsFunction batch = batchedRows(crweno5Row); // crweno5Rows (an ifunc: its address is not compared)
  ASSERT_NE(batch, nullptr);
  for (int n : {1, 2, 3, 4, 5, 7, 18, 37, 64}) expectSameRows(crweno5Row, batch, n);
}

TEST(CompactRowsBatch, Crweno5MappedRowsAreTheScalarRowsBitwise) {
  const RowsFunction batch = batchedRows(crweno5MappedRow);
  ASSERT_NE(batch, nullptr);
  for (int n : {1, 2, 3, 4, 5, 7, 18, 37, 64}) expectSameRows(crweno5MappedRow, batch, n);
}

TEST(CompactRowsBatch, EnoPadeBlendRowsAreTheScalarRowsBitwise) {
  const RowsFunction batch = batchedRows(enoPadeBlendRow);
  ASSERT_NE(batch, nullptr);
  for (int k : {1, 2, 3, 5, 6, 9, 18, 37}) expectSameRows(enoPadeBlendRow, batch, k);
  const int n = 70, pure = expectSameRows(enoPadeBlendRow, batch, n);
  EXPECT_GT(pure, 0) << "no stencil took the pure CU6 row";
  EXPECT_LT(pure, n - 10) << "too few stencils took the blend";
}

TEST(CompactRowsBatch, RowsWithoutABatchedFormHaveNone) {
  EXPECT_EQ(batchedRows(padeRow), nullptr);
  EXPECT_EQ(batchedRows(crwenoCu6Row), nullptr);
}
