// Portable random numbers for the problem generators: std::mt19937_64 (its output sequence is fixed by the
// C++ standard) with our own uniform and normal transforms (the std distributions differ between standard
// libraries). Each problem gets its own stream from (seed, problem index), so a batch is identical at any
// rank count and in any order.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace suite::lcp {

class Rng {
public:
  Rng(std::uint64_t seed, std::uint64_t index) : g_(mix(mix(seed) ^ (index * 0x9E3779B97F4A7C15ULL + 1))) {}
  // Uniform in [0, 1): the top 53 bits.
  double uniform() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Standard normal by Box-Muller (both values used).
  double normal() {
    if (have_) {
      have_ = false;
      return spare_;
    }
    double u1;
    do {
      u1 = uniform();
    } while (u1 <= 0.0);
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1)), th = 2.0 * M_PI * u2;
    spare_ = r * std::sin(th);
    have_ = true;
    return r * std::cos(th);
  }
  // Integer in [0, n).
  std::uint64_t below(std::uint64_t n) {
    return static_cast<std::uint64_t>(uniform() * static_cast<double>(n)) % n;
  }

private:
  static std::uint64_t mix(std::uint64_t x) { // splitmix64 finaliser
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
  }
  std::mt19937_64 g_;
  bool have_ = false;
  double spare_ = 0.0;
};

} // namespace suite::lcp
