// The sixth-order compact filter (lib/euler/compact_filter.hpp): its transfer function (zero at the 2-dx mode,
// identity at alpha = 1/2, 1 - T = O(w^6)); its conservative face form equals the cell form on a periodic line,
// removes a checkerboard added to smooth data exactly (linearity and T(pi) = 0) and conserves the line sum; faces
// next to a jump and next to a non-periodic end carry no flux, and a closed line keeps its sum.
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

// Filtered cells of a line of n cells on one rank (face form: cyclic Thomas on the n faces when periodic, Thomas
// on the n + 1 faces otherwise).
std::vector<V3> filtered(const std::vector<V3>& q, int n, bool periodic, double alpha) {
  const int nf = periodic ? n : n + 1;
  std::vector<double> abc(3 * nf), rhs(3 * nf), a(nf), b(nf), c(nf), d(nf), g(3 * (n + 1));
  compactFilterFaceRows<3>(q.data(), n, 0, nf, periodic, alpha, 1.4, 0.02, abc.data(), rhs.data());
  for (int k = 0; k < nf; ++k) a[k] = abc[3 * k], b[k] = abc[3 * k + 1], c[k] = abc[3 * k + 2];
  for (int comp = 0; comp < 3; ++comp) {
    for (int k = 0; k < nf; ++k) d[k] = rhs[3 * k + comp];
    EXPECT_TRUE(periodic ? suite::linalg::cyclicThomas(nf, a.data(), b.data(), c.data(), d.data())
                         : suite::linalg::thomas(nf, a.data(), b.data(), c.data(), d.data()));
    for (int k = 0; k <= n; ++k) g[3 * k + comp] = d[k % nf];
  }
  std::vector<V3> out(n);
  compactFilterApply<3>(q.data(), n, g.data(), out.data());
  return out;
}

// The filter in its cell form (the header's first formula) on a periodic line: cyclic Thomas per component.
std::vector<V3> cellForm(const std::vector<V3>& q, int n, double alpha) {
  double co[4];
  compactFilterCoefficients(alpha, co);
  std::vector<double> a(n, alpha), b(n, 1.0), c(n, alpha), d(n);
  std::vector<V3> out(n);
  for (int comp = 0; comp < 3; ++comp) {
    for (int i = 0; i < n; ++i) {
      const int m = i + 3;
      d[i] = co[0] * q[m][comp];
      for (int j = 1; j <= 3; ++j) d[i] += 0.5 * co[j] * (q[m + j][comp] + q[m - j][comp]);
    }
    EXPECT_TRUE(suite::linalg::cyclicThomas(n, a.data(), b.data(), c.data(), d.data()));
    for (int i = 0; i < n; ++i) out[i][comp] = d[i];
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

TEST(CompactFilter, FaceFormIsTheFilterRemovesCheckerboardConservesSum) {
  const int n = 64;
  const std::vector<V3> q = periodicLine(n, 1e-3);
  const std::vector<V3> smooth = filtered(periodicLine(n, 0.0), n, true, 0.45);
  const std::vector<V3> noisy = filtered(q, n, true, 0.45);
  const std::vector<V3> cells = cellForm(q, n, 0.45);
  for (int comp = 0; comp < 3; ++comp) {
    double sum0 = 0.0, sum1 = 0.0;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(noisy[k][comp], cells[k][comp], 1e-14) << k;  // the conservative form is the filter
      EXPECT_NEAR(noisy[k][comp], smooth[k][comp], 1e-14) << k; // the 2-dx mode is gone
      sum0 += q[k + 3][comp], sum1 += noisy[k][comp];
    }
    EXPECT_NEAR(sum1, sum0, 1e-13 * std::fabs(sum0));
  }
}

TEST(CompactFilter, NoFluxAtJumpsAndEndsConservative) {
  const int n = 40;
  std::vector<V3> q(n + 6);
  for (int m = 0; m < n + 6; ++m) {
    const int i = m - 3;
    const double rho = (i < n / 2 ? 1.0 : 0.125) + 1e-3 * (i % 2 ? -1.0 : 1.0), p = i < n / 2 ? 1.0 : 0.1;
    q[m] = {rho, 0.0, p / 0.4};
  }
  std::vector<double> abc(3 * (n + 1)), rhs(3 * (n + 1));
  compactFilterFaceRows<3>(q.data(), n, 0, n + 1, false, 0.45, 1.4, 0.02, abc.data(), rhs.data());
  for (int k = 0; k <= n; ++k) {
    // the jump lies at face n/2: Jameson's phi is nonzero at cells n/2 - 1 and n/2, which face k's cells
    // k-2 .. k+1 reach for k = n/2 - 2 .. n/2 + 2; faces 0..2 and n-2..n reach past the ends
    const bool off = k < 3 || k > n - 3 || (k >= n / 2 - 2 && k <= n / 2 + 2);
    EXPECT_EQ(abc[3 * k], off ? 0.0 : 0.45) << k;
    EXPECT_EQ(abc[3 * k + 1], 1.0) << k;
    if (off) {
      EXPECT_EQ(rhs[3 * k], 0.0) << k;
    }
  }
  const std::vector<V3> out = filtered(q, n, false, 0.45);
  double sum0 = 0.0, sum1 = 0.0;
  for (int i = 0; i < n; ++i) sum0 += q[i + 3][0], sum1 += out[i][0];
  EXPECT_NEAR(sum1, sum0, 1e-14 * sum0);                                     // closed line: conserved
  for (int i : {0, 1, n - 2, n - 1, n / 2 - 2, n / 2 - 1, n / 2, n / 2 + 1}) // no flux on either face
    EXPECT_EQ(out[i][0], q[i + 3][0]) << i;
  // the checkerboard (1e-3) between the end and the jump is damped > 10-fold (measured 6e-5: faces with no
  // flux 5 and 10 cells away keep the finite segment from the periodic filter's exact removal)
  EXPECT_LT(std::fabs(out[8][0] - 1.0), 1e-4);
}
