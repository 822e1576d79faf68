// Seeded problem generators of the LCP benchmark; see generators.hpp for the families and references.
#include "lcp/generators.hpp"
#include "lcp/rng.hpp"
#include "lcp/solver.hpp"

#include <cmath>
#include <stdexcept>

namespace suite::lcp {

Mat haarOrthogonal(int n, Rng& rng) {
  Mat G(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) G(i, j) = rng.normal();
  Eigen::HouseholderQR<Mat> qr(G);
  Mat Q = qr.householderQ();
  const Mat& R = qr.matrixQR();
  for (int j = 0; j < n; ++j)
    if (R(j, j) < 0) Q.col(j) = -Q.col(j);
  return Q;
}

Mat spdWithCondition(int n, double cond, Rng& rng) {
  const Mat Q = haarOrthogonal(n, rng);
  Vec sigma(n);
  for (int i = 0; i < n; ++i) sigma[i] = n > 1 ? std::pow(cond, -static_cast<double>(i) / (n - 1)) : 1.0;
  Mat M = Q * sigma.asDiagonal() * Q.transpose();
  return 0.5 * (M + M.transpose()); // exactly symmetric
}

namespace {
Vec uniformVec(int n, double a, double b, Rng& rng) {
  Vec v(n);
  for (int i = 0; i < n; ++i) v[i] = rng.uniform(a, b);
  return v;
}
} // namespace

std::vector<FamilyInfo> familyRegistry() {
  return {{"random_spd", "standard LCP, M SPD with condition number cond, q uniform in [-qrange, qrange]"},
          {"random_box", "box LCP: the random_spd M and q with bounds l = lower, u = upper"},
          {"pmatrix", "nonsymmetric P-matrix (random_spd M plus a skew-symmetric part), q uniform"},
          {"psd", "degenerate positive semidefinite M (rank n/2, repeated rows), solvable q"},
          {"murty", "Murty's example M = I + 2 strict lower triangle, q = -e (Lemke: 2^n - 1 pivots)"}};
}

std::vector<std::string> familyNames() {
  std::vector<std::string> v;
  for (const FamilyInfo& f : familyRegistry()) v.push_back(f.name);
  return v;
}

bool isFamily(const std::string& name) {
  for (const auto& f : familyNames())
    if (f == name) return true;
  return false;
}

namespace {
Problem generateRaw(const std::string& family, const GeneratorParams& gp, std::uint64_t index) {
  const int n = gp.n;
  Rng rng(gp.seed, index);
  const std::string name = family + "#" + std::to_string(index);
  if (family == "random_spd") {
    Mat M = spdWithCondition(n, gp.cond, rng);
    return makeLcp(std::move(M), uniformVec(n, -gp.qrange, gp.qrange, rng), name);
  }
  if (family == "random_box") {
    Mat M = spdWithCondition(n, gp.cond, rng);
    Vec q = uniformVec(n, -gp.qrange, gp.qrange, rng);
    return makeBox(std::move(M), std::move(q), Vec::Constant(n, gp.lower), Vec::Constant(n, gp.upper), name);
  }
  if (family == "pmatrix") {
    Mat M = spdWithCondition(n, gp.cond, rng);
    Mat S(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) S(i, j) = rng.normal() / std::sqrt(static_cast<double>(n));
    M += 0.5 * (S - S.transpose());
    return makeLcp(std::move(M), uniformVec(n, -gp.qrange, gp.qrange, rng), name);
  }
  if (family == "psd") {
    const int r = std::max(1, n / 2);
    Mat B(n, r);
    for (int j = 0; j < r; ++j)
      for (int i = 0; i < n; ++i) B(i, j) = rng.normal();
    for (int i = 1; i < n; i += 4) B.row(i) = B.row(i - 1); // repeated rows of B -> repeated rows/cols of M
    Mat M = B * B.transpose();
    Vec z(n), w(n);
    for (int i = 0; i < n; ++i) {
      const double t = rng.uniform();
      const double v = rng.uniform(0.0, gp.qrange);
      if (t < 0.4) {
        z[i] = v;
        w[i] = 0.0;
      } else if (t < 0.8) {
        z[i] = 0.0;
        w[i] = v;
      } else {
        z[i] = 0.0;
        w[i] = 0.0;
      } // degenerate
    }
    Vec q = w - M * z;
    Problem p = makeLcp(std::move(M), std::move(q), name);
    p.z_known = z;
    return p;
  }
  if (family == "murty") {
    Mat M = Mat::Identity(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = j + 1; i < n; ++i) M(i, j) = 2.0;
    return makeLcp(std::move(M), Vec::Constant(n, -1.0), "murty" + std::to_string(n));
  }
  throw std::invalid_argument("unknown problem family '" + family + "'");
}
} // namespace

Problem generate(const std::string& family, const GeneratorParams& gp, std::uint64_t index) {
  Problem p = generateRaw(family, gp, index);
  p.symmetric = isSymmetric(p.M) ? 1 : 0; // once per problem, shared by every solver of a batch
  return p;
}

} // namespace suite::lcp
