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

bool enoPadeShockRow(const double* rho, const double* p, double threshold) {
  for (int m = 1; m <= 4; ++m) {
    const double sr = std::abs(rho[m + 1] - 2.0 * rho[m] + rho[m - 1]) /
                      (std::abs(rho[m + 1]) + 2.0 * std::abs(rho[m]) + std::abs(rho[m - 1]) + 1e-300);
    const double sp = std::abs(p[m + 1] - 2.0 * p[m] + p[m - 1]) /
                      (std::abs(p[m + 1]) + 2.0 * std::abs(p[m]) + std::abs(p[m - 1]) + 1e-300);
    if (!(sr <= threshold && sp <= threshold)) return true; // NaN counts as a shock
  }
  return false;
}

} // namespace suite::euler
