// Sixth-order compact filter of Gaikwad & Visbal: coefficients and line rows (see compact_filter.hpp).
#include "euler/compact_filter.hpp"

#include "euler/line_options.hpp"

#include <cmath>

namespace suite::euler {

void compactFilterCoefficients(double alpha, double a[4]) {
  a[0] = 11.0 / 16.0 + 5.0 * alpha / 8.0;
  a[1] = 15.0 / 32.0 + 17.0 * alpha / 16.0;
  a[2] = -3.0 / 16.0 + 3.0 * alpha / 8.0;
  a[3] = 1.0 / 32.0 - alpha / 16.0;
}

double compactFilterTransfer(double alpha, double w) {
  double a[4];
  compactFilterCoefficients(alpha, a);
  return (a[0] + a[1] * std::cos(w) + a[2] * std::cos(2 * w) + a[3] * std::cos(3 * w)) /
         (1.0 + 2.0 * alpha * std::cos(w));
}

namespace {
// Jameson's relative second difference at cell j of g.
double jamesonPhi(double gm, double g0, double gp) {
  return std::fabs(gp - 2.0 * g0 + gm) / std::fabs(gp + 2.0 * g0 + gm);
}

template <int NV> double pressureOf(const std::array<double, NV>& u, double gamma) {
  double m2 = 0.0;
  for (int c = 1; c < NV - 1; ++c) m2 += u[c] * u[c];
  return (gamma - 1.0) * (u[NV - 1] - 0.5 * m2 / u[0]);
}

// Whether the stencil of face k, stored cells m-3 .. m+2 (m: the stored index of cell k), holds a jump of density
// or pressure.
template <int NV> bool faceStencilHasJump(const std::array<double, NV>* q, int m, double gamma, double jump) {
  double p[6];
  for (int s = 0; s < 6; ++s) p[s] = pressureOf<NV>(q[m - 3 + s], gamma);
  for (int s = 1; s < 5; ++s) {
    const int j = m - 3 + s;
    // NaN compares false: a non-finite stencil counts as a jump (left alone for the state check to report)
    if (!(jamesonPhi(q[j - 1][0], q[j][0], q[j + 1][0]) <= jump) ||
        !(jamesonPhi(p[s - 1], p[s], p[s + 1]) <= jump))
      return true;
  }
  return false;
}
} // namespace

template <int NV>
void compactFilterFaceRows(const std::array<double, NV>* q, long long n, long long xs, int nface,
                           bool periodic, double alpha, double gamma, double jump, double* abc, double* rhs) {
  constexpr int g = kLineGhost; // 3: the stencil's reach to the left of a face
  constexpr double binom5[6] = {-1.0, 5.0, -10.0, 10.0, -5.0, 1.0}; // delta^5 over cells k-3 .. k+2
  const double scale = (1.0 - 2.0 * alpha) / 64.0;
  for (int f = 0; f < nface; ++f) {
    const long long k = xs + f;
    const int m = f + g; // stored index of cell k (the cell right of face k)
    double* row = abc + 3 * f;
    double* r = rhs + (size_t)NV * f;
    const bool edge = !periodic && (k < g || k > n - g);
    if (edge || faceStencilHasJump<NV>(q, m, gamma, jump)) {
      row[0] = 0.0, row[1] = 1.0, row[2] = 0.0;
      for (int c = 0; c < NV; ++c) r[c] = 0.0;
      continue;
    }
    row[0] = alpha, row[1] = 1.0, row[2] = alpha;
    for (int c = 0; c < NV; ++c) {
      double d5 = 0.0;
      for (int s = 0; s < 6; ++s) d5 += binom5[s] * q[m - 3 + s][c];
      r[c] = scale * d5;
    }
  }
}

template <int NV>
void compactFilterApply(const std::array<double, NV>* q, int xm, const double* g,
                        std::array<double, NV>* out) {
  for (int i = 0; i < xm; ++i)
    for (int c = 0; c < NV; ++c) out[i][c] = q[i + kLineGhost][c] + (g[NV * (i + 1) + c] - g[NV * i + c]);
}

#define SUITE_COMPACT_FILTER(NV)                                                                             \
  template void compactFilterFaceRows<NV>(const std::array<double, NV>*, long long, long long, int, bool,    \
                                          double, double, double, double*, double*);                         \
  template void compactFilterApply<NV>(const std::array<double, NV>*, int, const double*,                    \
                                       std::array<double, NV>*);
SUITE_COMPACT_FILTER(3)
SUITE_COMPACT_FILTER(4)
SUITE_COMPACT_FILTER(5)
#undef SUITE_COMPACT_FILTER

} // namespace suite::euler
