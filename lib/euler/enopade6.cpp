// ENO-Pade 6 rows and shock switch (Lele 1992 alpha = 1/3 Pade core; Wang & Huang 2002; see enopade6.hpp).
#include "euler/enopade6.hpp"

#include <cmath>
#include <vector>

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

namespace {
// The two tests of enoPadeShockRow for every row 0 .. nrow-1 of q at once, each cell's amplitude test and each
// window's resolution test made once (a row reads four of each; the same operations, so the same outcome):
// fires[k] |= (amplitude fires at a cell k+1 .. k+4) && (resolution fires in a window k .. k+2).
void rowsFire(const double* q, int nrow, double threshold, double theta, char* amp, char* res, char* fires) {
  for (int c = 1; c <= nrow + 3; ++c) {
    const double phi = std::abs(q[c + 1] - 2.0 * q[c] + q[c - 1]) /
                       (std::abs(q[c + 1]) + 2.0 * std::abs(q[c]) + std::abs(q[c - 1]) + 1e-300);
    amp[c] = !(phi <= threshold);
  }
  for (int w = 0; w <= nrow + 1; ++w) {
    const double d0 = q[w + 1] - q[w], d1 = q[w + 2] - q[w + 1], d2 = q[w + 3] - q[w + 2];
    res[w] = theta <= 0.0 ||
             !(std::abs(d2 - 2.0 * d1 + d0) <= theta * (std::abs(d0) + std::abs(d1) + std::abs(d2)));
  }
  for (int k = 0; k < nrow; ++k)
    fires[k] |= (amp[k + 1] | amp[k + 2] | amp[k + 3] | amp[k + 4]) && (res[k] | res[k + 1] | res[k + 2]);
}
} // namespace

void enoPadeShockRows(const double* rho, const double* p, int nrow, double threshold, double theta,
                      std::vector<char>* work, char* shock) {
  if (nrow <= 0) return; // (no cell is read: the row-by-row sensor read none either)
  work->resize(2 * (size_t)(nrow + 4));
  char *amp = work->data(), *res = amp + nrow + 4;
  for (int k = 0; k < nrow; ++k) shock[k] = 0;
  rowsFire(rho, nrow, threshold, theta, amp, res, shock);
  rowsFire(p, nrow, threshold, theta, amp, res, shock);
}

} // namespace suite::euler
