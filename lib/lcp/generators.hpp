// Problem generators of the LCP benchmark (registry by family name), seeded per (seed, problem index):
//   random_spd  standard LCP, M = Q diag(sigma) Q^T (Alefeld, Chen & Potra 1999), Q Haar-random (QR of a
//               Gaussian matrix with the signs of diag(R) fixed, Mezzadri 2007), sigma log-spaced from 1 down
//               to 1/cond (cond(M) = cond exactly), q uniform in [-qrange, qrange];
//   random_box  the same M and q with bounds l = lower, u = upper (defaults -100, 100 = -+qrange);
//   pmatrix     nonsymmetric P-matrix: the SPD matrix above plus a random skew-symmetric part of norm ~ 1
//               (positive definite, hence P), q uniform;
//   psd         positive semidefinite and degenerate: M = B B^T with B of rank n/2 and repeated rows (so M
//               has repeated rows and columns), q = w* - M z* from a complementary pair with both z*_i and
//               w*_i zero on some indices (solvable, degenerate, non-unique solutions);
//   murty       Murty's example M = I + 2 * strict lower triangle, q = -e (Lemke: 2^n - 1 pivots).
#pragma once

#include "lcp/problem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace suite::lcp {

struct GeneratorParams {
  int n = 100;
  double cond = 1e4;
  double qrange = 1e2;
  double lower = -1e2, upper = 1e2; // random_box bounds (lcpbench default: -qrange, qrange)
  std::uint64_t seed = 1;
};

// Every family with its one-line description (for -help), in registry order.
struct FamilyInfo {
  std::string name, description;
};
std::vector<FamilyInfo> familyRegistry();
std::vector<std::string> familyNames();
bool isFamily(const std::string& name);
// Problem number `index` of the family (throws std::invalid_argument for an unknown family).
Problem generate(const std::string& family, const GeneratorParams& gp, std::uint64_t index);

// Building blocks (exposed for tests).
Mat haarOrthogonal(int n, class Rng& rng);
Mat spdWithCondition(int n, double cond, class Rng& rng);

} // namespace suite::lcp
