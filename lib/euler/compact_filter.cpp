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

// Whether the 7-point stencil around stored cell m (cells m-3 .. m+3) holds a jump of density or pressure.
template <int NV> bool stencilHasJump(const std::array<double, NV>* q, int m, double gamma, double jump) {
  double p[7];
  for (int s = 0; s < 7; ++s) p[s] = pressureOf<NV>(q[m - 3 + s], gamma);
  for (int s = 1; s < 6; ++s) {
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
void compactFilterRows(const std::array<double, NV>* q, long long n, long long xs, int xm, bool periodic,
                       double alpha, double gamma, double jump, double* abc, double* rhs) {
  constexpr int g = kLineGhost; // 3: the filter's half-width
  double a[4];
  compactFilterCoefficients(alpha, a);
  for (int k = 0; k < xm; ++k) {
    const long long i = xs + k;
    const int m = k + g;
    double* row = abc + 3 * k;
    double* r = rhs + (size_t)NV * k;
    const bool edge = !periodic && (i < g || i >= n - g);
    if (edge || stencilHasJump<NV>(q, m, gamma, jump)) {
      row[0] = 0.0, row[1] = 1.0, row[2] = 0.0;
      for (int c = 0; c < NV; ++c) r[c] = q[m][c];
      continue;
    }
    row[0] = alpha, row[1] = 1.0, row[2] = alpha;
    for (int c = 0; c < NV; ++c)
      r[c] = a[0] * q[m][c] + 0.5 * (a[1] * (q[m + 1][c] + q[m - 1][c]) + a[2] * (q[m + 2][c] + q[m - 2][c]) +
                                     a[3] * (q[m + 3][c] + q[m - 3][c]));
  }
}

template void compactFilterRows<3>(const std::array<double, 3>*, long long, long long, int, bool, double,
                                   double, double, double*, double*);
template void compactFilterRows<4>(const std::array<double, 4>*, long long, long long, int, bool, double,
                                   double, double, double*, double*);
template void compactFilterRows<5>(const std::array<double, 5>*, long long, long long, int, bool, double,
                                   double, double, double*, double*);

} // namespace suite::euler
