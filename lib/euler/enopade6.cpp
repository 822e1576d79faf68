// ENO-Pade 6 rows and shock switch (Lele 1992 alpha = 1/3 Pade core; Wang & Huang 2002; see enopade6.hpp).
#include "euler/enopade6.hpp"

#include <cmath>

namespace suite::euler {

Row padeRow(const double* v) {
  return {1.0 / 3.0, 1.0, 1.0 / 3.0, 29.0 / 36.0 * (v[2] + v[3]) + 1.0 / 36.0 * (v[1] + v[4])};
}

Row central6Row(const double* v) {
  return {0.0, 1.0, 0.0, (v[0] - 8.0 * v[1] + 37.0 * v[2] + 37.0 * v[3] - 8.0 * v[4] + v[5]) / 60.0};
}

double shockResolutionRatio(double ppw) {
  if (ppw <= 0.0) return 0.0;
  const double kh = 2.0 * M_PI / ppw, s = std::sin(0.5 * kh);
  return 4.0 * s * s / (1.0 + 2.0 * std::cos(kh));
}

namespace {
// Amplitude test: phi_m > threshold for some m = 1 .. 4 of q[0..5] (NaN fires).
bool amplitudeFires(const double* q, double threshold) {
  for (int m = 1; m <= 4; ++m) {
    const double phi = std::abs(q[m + 1] - 2.0 * q[m] + q[m - 1]) /
                       (std::abs(q[m + 1]) + 2.0 * std::abs(q[m]) + std::abs(q[m - 1]) + 1e-300);
    if (!(phi <= threshold)) return true;
  }
  return false;
}

// Resolution test: |D3| > theta (|D1| + |D1| + |D1|) in one of the 4-cell windows q[i .. i+3], i = 0 .. 2
// (NaN fires; theta <= 0: always fires).
bool resolutionFires(const double* q, double theta) {
  if (theta <= 0.0) return true; // -shock_ppw 0: the amplitude test alone
  double d[5];
  for (int i = 0; i < 5; ++i) d[i] = q[i + 1] - q[i];
  for (int i = 0; i < 3; ++i) {
    const double d3 = std::abs(d[i + 2] - 2.0 * d[i + 1] + d[i]);
    if (!(d3 <= theta * (std::abs(d[i]) + std::abs(d[i + 1]) + std::abs(d[i + 2])))) return true;
  }
  return false;
}
} // namespace

bool enoPadeShockRow(const double* rho, const double* p, double threshold, double theta) {
  return (amplitudeFires(rho, threshold) && resolutionFires(rho, theta)) ||
         (amplitudeFires(p, threshold) && resolutionFires(p, theta));
}

} // namespace suite::euler
