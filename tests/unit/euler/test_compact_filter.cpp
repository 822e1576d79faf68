// The sixth-order compact filter (lib/euler/compact_filter.hpp): its transfer function (zero at the 2-dx mode,
// identity at alpha = 1/2, 1 - T = O(w^6)), and its rows on a periodic line solved by cyclic Thomas: a
// checkerboard added to smooth data is removed exactly (linearity and T(pi) = 0), the line sum is conserved,
// cells next to a jump and next to a non-periodic end get identity rows.
#include "euler/compact_filter.hpp"
#include "linalg/tridiag.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace suite::euler;

namespace {
constexpr double kPi = 3.14159265358979323846;
using V3 = std::array<double, 3>;

// A periodic line of n cells (plus 3 ghosts each side, wrapped): smooth gas, plus eps (-1)^i on every component.
std::vector<V3> periodicLine(int n, double eps) {
  std::vector<V3> q(n + 6);
  for (int m = 0; m < n + 6; ++m) {
    const int i = ((m - 3) % n + n) % n;
    const double x = (i + 0.5) / n, s = (i % 2 ? -1.0 : 1.0) * eps;
    const double rho = 1.0 + 0.1 * std::sin(2 * kPi * x), u = 0.5, p = 1.0;
    q[m] = {rho + s, rho * u + s, p / 0.4 + 0.5 * rho * u * u + s};
  }
  return q;
}

// Filtered owned cells of a periodic line (cyclic Thomas per component).
std::vector<V3> filtered(const std::vector<V3>& q, int n, double alpha) {
  std::vector<double> abc(3 * n), rhs(3 * n), a(n), b(n), c(n), d(n);
  compactFilterRows<3>(q.data(), n, 0, n, true, alpha, 1.4, 0.02, abc.data(), rhs.data());
  for (int k = 0; k < n; ++k) a[k] = abc[3 * k], b[k] = abc[3 * k + 1], c[k] = abc[3 * k + 2];
  std::vector<V3> out(n);
  for (int comp = 0; comp < 3; ++comp) {
    for (int k = 0; k < n; ++k) d[k] = rhs[3 * k + comp];
    EXPECT_TRUE(suite::linalg::cyclicThomas(n, a.data(), b.data(), c.data(), d.data()));
    for (int k = 0; k < n; ++k) out[k][comp] = d[k];
  }
  return out;
}
} // namespace

TEST(CompactFilter, TransferFunction) {
  // (1 - T(w)) (1 + 2 alpha cos w) = (1 - 2 alpha) (1 - cos w)^3 / 8: zero at w = pi, of order w^6 at w -> 0
  // (sixth order), no damping at alpha = 1/2. This closed form pins all four coefficients.
  for (double alpha : {-0.2, 0.0, 0.4, 0.45, 0.49, 0.5}) {
    for (double w : {0.01, 0.3, 1.0, 2.0, 3.0}) {
      const double num = (1.0 - compactFilterTransfer(alpha, w)) * (1.0 + 2.0 * alpha * std::cos(w));
      EXPECT_NEAR(num, (1.0 - 2.0 * alpha) * std::pow(1.0 - std::cos(w), 3) / 8.0, 1e-15)
          << alpha << " " << w;
    }
    if (alpha < 0.5) {
      EXPECT_NEAR(compactFilterTransfer(alpha, kPi), 0.0, 1e-15) << alpha;
    }
    EXPECT_NEAR(compactFilterTransfer(alpha, 0.0), 1.0, 1e-15) << alpha;
  }
}

TEST(CompactFilter, RemovesCheckerboardConservesSum) {
  const int n = 64;
  const std::vector<V3> smooth = filtered(periodicLine(n, 0.0), n, 0.45);
  const std::vector<V3> noisy = filtered(periodicLine(n, 1e-3), n, 0.45);
  const std::vector<V3> q = periodicLine(n, 1e-3);
  for (int comp = 0; comp < 3; ++comp) {
    double sum0 = 0.0, sum1 = 0.0;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(noisy[k][comp], smooth[k][comp], 1e-14) << k; // the 2-dx mode is gone
      sum0 += q[k + 3][comp], sum1 += noisy[k][comp];
    }
    EXPECT_NEAR(sum1, sum0, 1e-12 * std::fabs(sum0));
  }
}

TEST(CompactFilter, IdentityRowsAtJumpsAndEnds) {
  const int n = 40;
  std::vector<V3> q(n + 6);
  for (int m = 0; m < n + 6; ++m) {
    const double rho = m - 3 < n / 2 ? 1.0 : 0.125, p = m - 3 < n / 2 ? 1.0 : 0.1;
    q[m] = {rho, 0.0, p / 0.4};
  }
  std::vector<double> abc(3 * n), rhs(3 * n);
  compactFilterRows<3>(q.data(), n, 0, n, false, 0.45, 1.4, 0.02, abc.data(), rhs.data());
  for (int k = 0; k < n; ++k) {
    // the jump lies between cells n/2 - 1 and n/2: Jameson's phi is nonzero at both, which stencils
    // k-2 .. k+2 reach for k = n/2 - 3 .. n/2 + 2; the 3 cells at each end have no ghosts to use
    const bool identity = k < 3 || k >= n - 3 || (k >= n / 2 - 3 && k <= n / 2 + 2);
    EXPECT_EQ(abc[3 * k], identity ? 0.0 : 0.45) << k;
    EXPECT_EQ(abc[3 * k + 1], 1.0) << k;
    if (identity) {
      EXPECT_EQ(rhs[3 * k], q[k + 3][0]) << k;
    }
  }
}
