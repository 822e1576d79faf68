// Energy spectra (lib/fft/energy_spectrum): a single Fourier mode puts all its energy in its shell, random
// fields satisfy Parseval to round-off, and the result does not depend on the rank count or decomposition
// (blocks split along y, which FFTW's slabs are not).
#include "fft/energy_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

namespace {

using Fn = std::function<double(long long z, long long y, long long x)>;

// This rank's block: the second-slowest dimension (y) split evenly over the ranks.
suite::fft::Block yBlock(const std::vector<long long>& dims) {
  int P, r;
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  suite::fft::Block b{dims, std::vector<long long>(dims.size(), 0), dims};
  const size_t y = dims.size() - 2;
  b.start[y] = dims[y] * r / P;
  b.count[y] = dims[y] * (r + 1) / P - b.start[y];
  return b;
}

std::vector<double> sample(const suite::fft::Block& b, const Fn& f) {
  std::vector<double> v;
  const bool d3 = b.dims.size() == 3;
  const long long z0 = d3 ? b.start[0] : 0, nz = d3 ? b.count[0] : 1;
  const size_t iy = b.dims.size() - 2, ix = iy + 1;
  for (long long z = z0; z < z0 + nz; ++z)
    for (long long y = b.start[iy]; y < b.start[iy] + b.count[iy]; ++y)
      for (long long x = b.start[ix]; x < b.start[ix] + b.count[ix]; ++x) v.push_back(f(z, y, x));
  return v;
}

std::vector<double> spectrum(const suite::fft::Block& b, const std::vector<Fn>& comps) {
  std::vector<std::vector<double>> data;
  std::vector<const double*> ptrs;
  for (const auto& f : comps) data.push_back(sample(b, f));
  for (const auto& d : data) ptrs.push_back(d.data());
  std::vector<double> E;
  EXPECT_EQ(suite::fft::energySpectrum(PETSC_COMM_WORLD, b, ptrs, &E), 0);
  return E;
}

TEST(EnergySpectrum, SingleModeFillsOneShell3D) {
  const std::vector<long long> dims{8, 12, 16};
  const auto b = yBlock(dims);
  // u = cos(2 pi 3 x / nx): |k| = 3, mean (1/2) u^2 = 1/4.
  auto E =
      spectrum(b, {[&](long long, long long, long long x) { return std::cos(2 * M_PI * 3 * x / 16.0); }});
  for (size_t k = 0; k < E.size(); ++k) EXPECT_NEAR(E[k], k == 3 ? 0.25 : 0.0, 1e-14) << "shell " << k;
  // v = sin(2 pi (2 x / nx + 1 y / ny + 2 z / nz)): |k| = 3, and w = 0.5: all energy of w in shell 0.
  E = spectrum(b, {[&](long long z, long long y, long long x) {
                     return std::sin(2 * M_PI * (2 * x / 16.0 + y / 12.0 + 2 * z / 8.0));
                   },
                   [](long long, long long, long long) { return 0.5; }});
  for (size_t k = 0; k < E.size(); ++k) EXPECT_NEAR(E[k], k == 3 ? 0.25 : (k == 0 ? 0.125 : 0.0), 1e-14);
}

TEST(EnergySpectrum, NyquistAndOddSizes2D) {
  const std::vector<long long> dims{9, 10}; // odd ny, even nx with its Nyquist column
  const auto b = yBlock(dims);
  auto E = spectrum(b, {[](long long, long long, long long x) { return (x % 2) ? -1.0 : 1.0; }});
  for (size_t k = 0; k < E.size(); ++k) EXPECT_NEAR(E[k], k == 5 ? 0.5 : 0.0, 1e-14) << "shell " << k;
}

TEST(EnergySpectrum, ParsevalOnRandomFields) {
  for (const auto& dims : {std::vector<long long>{6, 10, 7}, std::vector<long long>{11, 8}}) {
    const auto b = yBlock(dims);
    auto noise = [&](unsigned seed) {
      return [=](long long z, long long y, long long x) {
        std::mt19937_64 g(seed * 1000003ULL +
                          (unsigned long long)((z * dims[dims.size() - 2] + y) * 1000 + x));
        return std::uniform_real_distribution<double>(-1, 1)(g);
      };
    };
    auto E = spectrum(b, {noise(1), noise(2)});
    // (1/N) sum (1/2)(u^2 + v^2), computed directly
    double local = 0, total = 0, n = 1;
    for (auto d : dims) n *= d;
    for (unsigned s : {1u, 2u})
      for (double v : sample(b, noise(s))) local += 0.5 * v * v / n;
    MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    EXPECT_NEAR(std::accumulate(E.begin(), E.end(), 0.0), total, 1e-13 * total);
  }
}

} // namespace
