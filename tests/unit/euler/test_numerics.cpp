// Euler numerics without MPI: reconstruction orders (WENO5-Z, Pade, CRWENO5-Z at critical points), exact Riemann
// solver against Toro's tables (the line gas of 1D/2D/3D: test_line_gas.cpp).
#include "euler/crweno5.hpp"
#include "euler/crweno_cu6.hpp"
#include "euler/enopade6.hpp"
#include "euler/exact_riemann.hpp"
#include "euler/weno5.hpp"
#include "linalg/tridiag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace suite::euler;

namespace {
// L1 error of the conservative derivative (h_{j+1/2} - h_{j-1/2}) / dx of a periodic f on [-1, 1] with
// left-biased rows, solving the cyclic tridiagonal system when the rows are compact.
double derivativeError(int n, const std::function<double(double)>& f, const std::function<double(double)>& df,
                       RowFunction row) {
  const double dx = 2.0 / n;
  std::vector<double> fv(n), a(n), b(n), c(n), r(n);
  for (int j = 0; j < n; ++j) fv[j] = f(-1.0 + (j + 0.5) * dx);
  for (int j = 0; j < n; ++j) { // row for x_{j+1/2}, stored at index j
    double v[6];
    for (int m = 0; m < 6; ++m) v[m] = fv[((j - 2 + m) % n + n) % n];
    const Row rw = row(v);
    a[j] = rw.a, b[j] = rw.b, c[j] = rw.c, r[j] = rw.r;
  }
  suite::linalg::BlockTridiagSolver s;
  s.solve(n, 1, a.data(), b.data(), c.data(), r.data(), true);
  double err = 0;
  for (int j = 0; j < n; ++j)
    err += std::abs((r[j] - r[(j - 1 + n) % n]) / dx - df(-1.0 + (j + 0.5) * dx)) * dx;
  return err;
}

double order(const std::function<double(int)>& err, int n0, int levels, std::vector<double>* errs) {
  double o = 0;
  for (int l = 0; l < levels; ++l) {
    errs->push_back(err(n0 << l));
    if (l > 0) o = std::log2((*errs)[l - 1] / (*errs)[l]);
  }
  return o;
}

double smoothF(double x) {
  return std::sin(M_PI * x) + 0.3 * std::cos(2 * M_PI * x);
}
double smoothDF(double x) {
  return M_PI * std::cos(M_PI * x) - 0.6 * M_PI * std::sin(2 * M_PI * x);
}
// Henrick, Aslam & Powers (2005) critical-point profile.
double critF(double x) {
  return std::sin(M_PI * x - std::sin(M_PI * x) / M_PI);
}
double critDF(double x) {
  return std::cos(M_PI * x - std::sin(M_PI * x) / M_PI) * (M_PI - std::cos(M_PI * x));
}
} // namespace

TEST(EulerReconstruction, PadeIsSixthOrder) {
  std::vector<double> e;
  const double o = order([](int n) { return derivativeError(n, smoothF, smoothDF, padeRow); }, 20, 4, &e);
  for (double x : e) std::printf("  pade error %.3e\n", x);
  EXPECT_GE(o, 5.8);
}

TEST(EulerReconstruction, Weno5ZIsFifthOrder) {
  std::vector<double> e;
  const double o = order([](int n) { return derivativeError(n, critF, critDF, weno5Row); }, 40, 4, &e);
  std::printf("  weno5-z order at critical points %.2f\n", o);
  EXPECT_GE(o, 4.8);
}

TEST(EulerReconstruction, EnoPadeShockRowsKeepFifthOrderAtCriticalPoints) {
  // The crweno5 rows (and the upwind limit of enopade6's ENO-Pade rows), forced on every row, on sin(pi x - sin(pi x)/pi).
  std::vector<double> e;
  const double o = order([](int n) { return derivativeError(n, critF, critDF, crweno5Row); }, 40, 4, &e);
  for (double x : e) std::printf("  crweno5-z error %.3e\n", x);
  std::printf("  crweno5-z (ENO-Pade shock rows) order at critical points %.2f\n", o);
  EXPECT_GE(o, 4.8);
}

// crweno5's rows (Henrick-mapped weights) on Henrick et al.'s critical-point profile tend to the linear compact
// scheme (compactUpwind5Row): error above the linear scheme's by 53% at N = 80 and 12% at N = 160 (the excess
// falls 4.3x per halving), where the WENO-Z rows' is 120% and 34%; order from N = 160 to 320 5.17.
TEST(EulerReconstruction, MappedCrweno5RowsTendToTheLinearScheme) {
  double excess[2];
  for (int i = 0; i < 2; ++i) {
    const int n = 80 << i;
    const double lin = derivativeError(n, critF, critDF, compactUpwind5Row);
    const double mapped = derivativeError(n, critF, critDF, crweno5MappedRow);
    const double z = derivativeError(n, critF, critDF, crweno5Row);
    excess[i] = mapped / lin - 1;
    std::printf("  N = %d: linear %.6e, mapped %.6e (%+.3f), WENO-Z %.6e (%+.3f)\n", n, lin, mapped,
                excess[i], z, z / lin - 1);
  }
  EXPECT_LT(excess[0], 0.6);
  EXPECT_LT(excess[1], 0.14);
  EXPECT_GT(excess[0], 4.0 * excess[1]);
  std::vector<double> e;
  const double o =
      order([](int n) { return derivativeError(n, critF, critDF, crweno5MappedRow); }, 40, 4, &e);
  std::printf("  crweno5 (mapped) order at critical points %.2f\n", o);
  EXPECT_GE(o, 5.1);
}

// The ENO-Pade rows of enopade6's shocked lines (crweno_cu6.hpp).
TEST(EulerReconstruction, Cu6OptimalWeightsGiveThePadeRow) {
  const double d[4] = {0.1, 0.4, 0.4, 0.1};
  const double v[6] = {0.3, -1.2, 2.5, 0.7, 1.9, -0.4};
  const Row cu6 = cu6RowFromWeights(v, d), pade = padeRow(v);
  EXPECT_NEAR(cu6.a, 0.6 * pade.a, 1e-15);
  EXPECT_NEAR(cu6.b, 0.6 * pade.b, 1e-15);
  EXPECT_NEAR(cu6.c, 0.6 * pade.c, 1e-15);
  EXPECT_NEAR(cu6.r, 0.6 * pade.r, 1e-15);
}

TEST(EulerReconstruction, Cu6SmoothnessOfPolynomials) {
  // beta_6 = sum_l int_{-1/2}^{1/2} (p^(l))^2: p = x (cell values m) gives 1, p = x^2 (m^2 + 1/12) gives 13/3.
  double lin[6], quad[6];
  for (int m = 0; m < 6; ++m) lin[m] = m - 2, quad[m] = (m - 2) * (m - 2) + 1.0 / 12.0;
  EXPECT_NEAR(cu6Smoothness(lin), 1.0, 1e-12);
  EXPECT_NEAR(cu6Smoothness(quad), 13.0 / 3.0, 1e-12);
}

TEST(EulerReconstruction, EnoPadeRowsOrderAndJumps) {
  std::vector<double> e, ec;
  const double o =
      order([](int n) { return derivativeError(n, smoothF, smoothDF, enoPadeBlendRow); }, 20, 4, &e);
  const double oc =
      order([](int n) { return derivativeError(n, critF, critDF, enoPadeBlendRow); }, 40, 4, &ec);
  std::printf("  eno-pade rows: order %.2f (smooth), %.2f (critical points)\n", o, oc);
  EXPECT_GE(o, 5.8); // the Pade row's order where the weights reach d
  EXPECT_GE(oc, 4.8);
  // A jump in the downwind cells (f_{j+1} | f_{j+2} or f_{j+2} | f_{j+3}) rejects the downwind candidate: the
  // row is the CRWENO5-Z row.
  for (int f = 3; f <= 4; ++f) {
    double v[6];
    for (int m = 0; m < 6; ++m) v[m] = m <= f ? 1.0 : 0.125;
    const Row b = enoPadeBlendRow(v), c = crweno5Row(v);
    EXPECT_NEAR(b.a, c.a, 1e-6) << "jump after cell " << f;
    EXPECT_NEAR(b.c, c.c, 1e-6) << "jump after cell " << f;
    EXPECT_NEAR(b.r, c.r, 1e-6) << "jump after cell " << f;
  }
}

TEST(EulerReconstruction, ShockSensorQuietOnSmoothLoudOnJump) {
  EXPECT_DOUBLE_EQ(shockResolutionRatio(6.0), 0.5); // 4 sin^2(pi/6) / (1 + 2 cos(pi/3))
  const double theta = shockResolutionRatio(8.0);   // the default -shock_ppw
  double rho[6], p[6] = {1, 1, 1, 1, 1, 1};
  for (int m = 0; m < 6; ++m) rho[m] = 1.0 + 0.2 * std::sin(M_PI * (-1.0 + (m + 0.5) * 0.1)); // N = 20 wave
  EXPECT_FALSE(enoPadeShockRow(rho, p, 0.02, theta));
  // A jump at any of the five faces the row's stencil holds makes a shock row, in rho (contact) or p.
  for (int f = 0; f < 5; ++f) {
    double jump[6];
    for (int m = 0; m < 6; ++m) jump[m] = m <= f ? 1.0 : 0.125;
    EXPECT_TRUE(enoPadeShockRow(jump, p, 0.02, theta)) << "jump after cell " << f;
    EXPECT_TRUE(enoPadeShockRow(p, jump, 0.02, theta)) << "jump after cell " << f;
  }
  // An under-resolved smooth bump (the 32^2 isentropic vortex: a Gaussian density dip of depth 0.5 and 2.26
  // cells standard deviation) at every offset: the amplitude test alone (-shock_ppw 0) flags it, the
  // resolution test does not.
  bool amplitude_alone = false;
  for (int s = 0; s < 20; ++s)
    for (int m = 0; m < 6; ++m) {
      const double x = (m - 12 + 0.5 * s) / 2.26;
      rho[m] = 1.0 - 0.5 * std::exp(-0.5 * x * x);
      if (m == 5) {
        EXPECT_FALSE(enoPadeShockRow(rho, p, 0.02, theta)) << "offset " << s;
        amplitude_alone = amplitude_alone || enoPadeShockRow(rho, p, 0.02, 0.0);
      }
    }
  EXPECT_TRUE(amplitude_alone);
  // Grid-scale noise of small amplitude (1e-4): the resolution test fires, the amplitude test does not.
  for (int m = 0; m < 6; ++m) rho[m] = 0.4 + (m % 2 ? 1e-4 : -1e-4);
  EXPECT_FALSE(enoPadeShockRow(rho, p, 0.02, theta));
  rho[2] = std::nan("");
  EXPECT_TRUE(enoPadeShockRow(rho, p, 0.02, theta));
}

// The sensor of a whole line (each cell's and window's test made once) flags exactly the rows that the
// row-by-row sensor flags: a line with a smooth wave, a jump in rho, one in p, under-resolved bumps,
// grid-scale noise and a NaN, for both tests together and the amplitude test alone (theta = 0).
TEST(EulerReconstruction, LineSensorFlagsTheRowsOfTheRowSensor) {
  const int ncell = 64, nrow = ncell - 5;
  std::vector<double> rho(ncell), p(ncell);
  for (int c = 0; c < ncell; ++c) {
    const double x = (c + 0.5) / ncell;
    rho[c] = 1.0 + 0.2 * std::sin(2 * M_PI * x) + (c > 20 ? -0.5 : 0.0) +
             0.3 * std::exp(-0.5 * std::pow((c - 40) / 1.5, 2)) + (c > 50 && c % 2 ? 1e-4 : 0.0);
    p[c] = c < 30 ? 1.0 : 0.1 + 0.01 * std::cos(7 * x);
  }
  rho[57] = std::nan("");
  std::vector<char> work, line(nrow);
  int flagged = 0;
  for (double theta : {shockResolutionRatio(8.0), 0.0}) {
    enoPadeShockRows(rho.data(), p.data(), nrow, 0.02, theta, &work, line.data());
    for (int k = 0; k < nrow; ++k) {
      EXPECT_EQ(line[k] != 0, enoPadeShockRow(rho.data() + k, p.data() + k, 0.02, theta)) << "row " << k;
      flagged += line[k] != 0;
    }
  }
  EXPECT_GT(flagged, 10);
  EXPECT_LT(flagged, 2 * nrow);
}

TEST(EulerExactRiemann, ToroTable4_2) {
  const ExactRiemann sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  EXPECT_NEAR(sod.pStar(), 0.30313, 1e-5);
  EXPECT_NEAR(sod.uStar(), 0.92745, 1e-5);
  const ExactRiemann t123({1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 1.4);
  EXPECT_NEAR(t123.pStar(), 0.00189, 1e-5);
  EXPECT_NEAR(t123.uStar(), 0.0, 1e-12);
  const ExactRiemann t3({1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 1.4);
  EXPECT_NEAR(t3.pStar(), 460.894, 1e-3);
  EXPECT_NEAR(t3.uStar(), 19.5975, 1e-4);
  // Sampling: left state far left, star-region density left of the contact (Toro: 0.42632).
  EXPECT_DOUBLE_EQ(sod.sample(-10).rho, 1.0);
  EXPECT_NEAR(sod.sample(0.5).rho, 0.42632, 1e-5);
  EXPECT_NEAR(sod.sample(1.2).rho, 0.26557, 1e-5);
}
