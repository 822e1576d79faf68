// L1 distance between two grid solutions (see grid_distance.hpp for the method and its reference).
#include "model_choice/grid_distance.hpp"

#include <algorithm>
#include <cmath>

namespace suite::model_choice {

namespace {
double minmod4(double a, double b, double c, double d) {
  if (a > 0 && b > 0 && c > 0 && d > 0) return std::min(std::min(a, b), std::min(c, d));
  if (a < 0 && b < 0 && c < 0 && d < 0) return std::max(std::max(a, b), std::max(c, d));
  return 0.0;
}

// The six-point Lagrange weights at t in [0, 1] for the nodes -2 .. 3.
void lagrangeWeights(double t, double w[6]) {
  for (int k = 0; k < 6; ++k) {
    double num = 1.0, den = 1.0;
    for (int m = 0; m < 6; ++m)
      if (m != k) num *= t - (m - 2), den *= (double)(k - m);
    w[k] = num / den;
  }
}
} // namespace

double interpolateLine(const double* f, long long nf, double lo, double hi, double x) {
  const double s = (x - lo) / (hi - lo) * (double)nf - 0.5; // position in cell-centre index units
  if (nf == 1) return f[0];
  long long i0 = std::clamp((long long)std::floor(s), 0LL, nf - 2);
  const double t = s - (double)i0;
  if (nf < 6) return (1.0 - t) * f[i0] + t * f[i0 + 1];
  const long long first = std::clamp(i0 - 2, 0LL, nf - 6); // the stencil shifted inside the line
  double w[6];
  lagrangeWeights(s - (double)first - 2.0, w);
  double v = 0.0;
  for (int k = 0; k < 6; ++k) v += w[k] * f[first + k];
  auto d2 = [&](long long j) { // second difference at j, 0 at the ends
    return j <= 0 || j >= nf - 1 ? 0.0 : f[j + 1] - 2.0 * f[j] + f[j - 1];
  };
  const double m = 0.5 * std::abs(minmod4(d2(i0 - 1), d2(i0), d2(i0 + 1), d2(i0 + 2)));
  return std::clamp(v, std::min(f[i0], f[i0 + 1]) - m, std::max(f[i0], f[i0 + 1]) + m);
}

namespace {
// src (shape ns) interpolated along axis d to the centres of nt cells: the result has shape ns with ns[d] = nt.
std::vector<double> resampleAxis(const std::vector<double>& src, std::array<long long, 3> ns, int d,
                                 long long nt, double lo, double hi) {
  std::array<long long, 3> nr = ns;
  nr[d] = nt;
  std::vector<double> out((size_t)(nr[0] * nr[1] * nr[2])), line((size_t)ns[d]);
  const long long stride = d == 0 ? 1 : d == 1 ? ns[0] : ns[0] * ns[1];
  const long long rstride = d == 0 ? 1 : d == 1 ? nr[0] : nr[0] * nr[1];
  for (long long k = 0; k < (d == 2 ? 1 : ns[2]); ++k)
    for (long long j = 0; j < (d == 1 ? 1 : ns[1]); ++j)
      for (long long i = 0; i < (d == 0 ? 1 : ns[0]); ++i) {
        const long long base = i + ns[0] * (j + ns[1] * k), rbase = i + nr[0] * (j + nr[1] * k);
        for (long long q = 0; q < ns[d]; ++q) line[q] = src[base + q * stride];
        for (long long q = 0; q < nt; ++q)
          out[rbase + q * rstride] =
              interpolateLine(line.data(), ns[d], lo, hi, lo + (q + 0.5) * (hi - lo) / (double)nt);
      }
  return out;
}
} // namespace

double l1Distance(const GridField& a, const GridField& b) {
  const GridField& coarse = a.cells() <= b.cells() ? a : b;
  const GridField& fine = a.cells() <= b.cells() ? b : a;
  std::vector<double> v = fine.values;
  std::array<long long, 3> shape = fine.n;
  for (int d = 0; d < fine.dim; ++d)
    if (shape[d] != coarse.n[d]) {
      v = resampleAxis(v, shape, d, coarse.n[d], fine.lo[d], fine.hi[d]);
      shape[d] = coarse.n[d];
    }
  double sum = 0.0;
  for (size_t c = 0; c < v.size(); ++c) sum += std::abs(coarse.values[c] - v[c]);
  return sum / (double)v.size();
}

} // namespace suite::model_choice
