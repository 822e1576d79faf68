// Measured modified wavenumbers of the flux-derivative operators (see scheme_spectrum.hpp).
#include "euler/scheme_spectrum.hpp"

#include "linalg/tridiag.hpp"

#include <cmath>
#include <stdexcept>

namespace suite::euler {
namespace {

// D_j = h_{j+1/2} - h_{j-1/2} for point values f on a periodic grid, from the left-biased rows.
std::vector<double> fluxDerivative(RowFunction fn, const std::vector<double>& f) {
  const int n = (int)f.size();
  std::vector<double> a(n), b(n), c(n), h(n);
  for (int j = 0; j < n; ++j) { // face j+1/2 from f_{j-2} .. f_{j+3}
    double v[6];
    for (int m = 0; m < 6; ++m) v[m] = f[((j - 2 + m) % n + n) % n];
    const Row row = fn(v);
    a[j] = row.a, b[j] = row.b, c[j] = row.c, h[j] = row.r;
  }
  bool explicit_rows = true;
  for (int j = 0; j < n; ++j) explicit_rows = explicit_rows && a[j] == 0.0 && c[j] == 0.0;
  if (explicit_rows) {
    for (int j = 0; j < n; ++j) h[j] /= b[j];
  } else if (!linalg::cyclicThomas(n, a.data(), b.data(), c.data(), h.data())) {
    throw std::runtime_error("scheme spectrum: singular periodic row system");
  }
  std::vector<double> d(n);
  for (int j = 0; j < n; ++j) d[j] = h[j] - h[(j - 1 + n) % n];
  return d;
}

} // namespace

std::vector<SpectrumPoint> measureSchemeSpectrum(const SchemeInfo& scheme, bool smooth, int n) {
  if (scheme.state_riemann || !scheme.smooth_row)
    throw std::invalid_argument(std::string("scheme ") + scheme.name + " has no flux rows to analyse");
  if (n < 8 || n % 2) throw std::invalid_argument("scheme spectrum: n must be even and >= 8");
  const RowFunction fn = smooth ? scheme.smooth_row : scheme.shock_row;
  std::vector<SpectrumPoint> out;
  std::vector<double> fc(n), fs(n);
  for (int m = 1; m <= n / 2; ++m) {
    const double w = 2.0 * M_PI * m / n;
    for (int j = 0; j < n; ++j) fc[j] = std::cos(w * j), fs[j] = std::sin(w * j);
    const std::vector<double> dc = fluxDerivative(fn, fc), ds = fluxDerivative(fn, fs);
    // D = dc + i ds = i k' e^{iwj}  =>  k' = -i (dc + i ds) e^{-iwj}; averaged over j (exact for linear rows).
    double re = 0.0, im = 0.0;
    for (int j = 0; j < n; ++j) {
      const double cr = std::cos(w * j), ci = -std::sin(w * j);                // e^{-iwj}
      const double pr = dc[j] * cr - ds[j] * ci, pi = dc[j] * ci + ds[j] * cr; // (dc + i ds) e^{-iwj}
      re += pi;                                                                // -i (pr + i pi) = pi - i pr
      im += -pr;
    }
    out.push_back({w, re / n, im / n});
  }
  return out;
}

double padeModifiedWavenumber(double w) {
  const double alpha = 1.0 / 3.0, a = 14.0 / 9.0, b = 1.0 / 9.0;
  return (a * std::sin(w) + 0.5 * b * std::sin(2.0 * w)) / (1.0 + 2.0 * alpha * std::cos(w));
}

} // namespace suite::euler
