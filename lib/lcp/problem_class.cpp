// Classification of an LCP for the solver portfolio (see problem_class.hpp).
#include "lcp/problem_class.hpp"

#include "lcp/solver.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace suite::lcp {

namespace {

const char* structureOf(const Problem& p) {
  if (p.n_eq > 0) return "mlcp";
  return p.isStandard() ? "lcp" : "box";
}

const char* sizeOf(int n) {
  return n <= 32 ? "small" : n <= 256 ? "medium" : "large";
}

// Sum of |c_i| over c[0, n): four independent accumulators (a single += chain waits on each addition's
// latency: measured 120 us for the columns of a 300 x 300 matrix, against bpp's 80 us solve).
double absSum(const double* c, Eigen::Index n) {
  double s[4] = {0, 0, 0, 0};
  Eigen::Index i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) s[k] += std::abs(c[i + k]);
  for (; i < n; ++i) s[0] += std::abs(c[i]);
  return (s[0] + s[1]) + (s[2] + s[3]);
}

// min over i in [from, n) of d_j d_i - c_i^2 (the 2 x 2 principal minors of rows i, j), +inf if empty.
double minMinor(const double* c, const double* d, double dj, Eigen::Index from, Eigen::Index n) {
  double m[4] = {kInf, kInf, kInf, kInf};
  Eigen::Index i = from;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) m[k] = std::min(m[k], dj * d[i + k] - c[i + k] * c[i + k]);
  for (; i < n; ++i) m[0] = std::min(m[0], dj * d[i] - c[i] * c[i]);
  return std::min(std::min(m[0], m[1]), std::min(m[2], m[3]));
}

// Column by column (contiguous, vectorised): positive diagonal, strict row diagonal dominance.
void scanColumns(const Mat& M, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  Vec off = Vec::Zero(n);                                          // row sums of |M_ij|, j != i
  for (Eigen::Index j = 0; j < n; ++j) off += M.col(j).cwiseAbs(); // elementwise: vectorised
  const Vec d = M.diagonal();
  off -= d.cwiseAbs();
  f->diag_positive = n > 0 && d.minCoeff() > 0;
  f->diag_dominant = f->diag_positive && (off.array() < d.array()).all();
}

// Symmetric M in one pass over the columns (contiguous; a column's sums are its row's): positive
// diagonal, strict diagonal dominance, and every 2 x 2 principal minor > 0 (necessary for definiteness).
void scanSymmetric(const Mat& M, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  const Vec d = M.diagonal();
  const bool pos = n > 0 && d.minCoeff() > 0;
  bool dd = pos, minors = pos;
  for (Eigen::Index j = 0; j < n; ++j) {
    dd = dd && absSum(M.col(j).data(), n) - std::abs(d(j)) < d(j);
    minors = minors && minMinor(M.col(j).data(), d.data(), d(j), j + 1, n) > 0.0;
  }
  f->diag_positive = pos;
  f->diag_dominant = dd;
  f->minors_ok = minors;
}

// Every 2 x 2 principal minor of (M + M^T) / 2 > 0 (the diagonal is positive), M nonsymmetric: the transposed
// entries are read in 16 x 16 tiles.
bool minorsPositive(const Mat& M) {
  const Eigen::Index n = M.rows();
  const Vec d = M.diagonal();
  constexpr Eigen::Index T = 16;
  for (Eigen::Index jb = 0; jb < n; jb += T)
    for (Eigen::Index ib = jb; ib < n; ib += T)
      for (Eigen::Index j = jb; j < std::min(n, jb + T); ++j)
        for (Eigen::Index i = std::max(ib, j + 1); i < std::min(n, ib + T); ++i) {
          const double s = 0.5 * (M(i, j) + M(j, i));
          if (!(d(i) * d(j) > s * s)) return false;
        }
  return true;
}

bool choleskySucceeds(const Mat& S) {
  Eigen::LLT<Mat> llt(S);
  return llt.info() == Eigen::Success && llt.matrixLLT().diagonal().allFinite() &&
         llt.matrixLLT().diagonal().minCoeff() > 0;
}

// Positive definite (symmetric part) as far as the tests of problem_class.hpp go (f->minors_ok set).
bool definite(const Problem& p, bool cholesky, ProblemFeatures* f) {
  if (!f->minors_ok || !cholesky) return f->minors_ok;
  f->cholesky_tried = true;
  f->cholesky_ok = f->symmetric ? choleskySucceeds(p.M) : choleskySucceeds(0.5 * (p.M + p.M.transpose()));
  return f->cholesky_ok;
}

} // namespace

ProblemFeatures classify(const Problem& p, bool thorough) {
  ProblemFeatures f;
  f.n = p.size();
  f.kind = p.kind;
  f.structure = structureOf(p);
  f.size = sizeOf(f.n);
  for (int i = 0; i < f.n; ++i) {
    f.finite_lower += std::isfinite(p.l[i]);
    f.finite_upper += std::isfinite(p.u[i]);
  }
  if (thorough)
    f.density = static_cast<double>((p.M.array() != 0.0).count()) / std::max(1.0, double(f.n) * f.n);
  f.symmetric = isSymmetric(p);
  if (f.symmetric) {
    scanSymmetric(p.M, &f);
  } else {
    scanColumns(p.M, &f);
    f.minors_ok = !f.diag_dominant && f.diag_positive && minorsPositive(p.M);
  }
  if (f.diag_dominant) {
    f.matrix = "dd";
    return f;
  }
  const bool def = definite(p, thorough, &f);
  f.matrix = f.symmetric ? (def ? "spd" : "sym") : (def ? "pd" : "gen");
  return f;
}

const std::vector<std::string>& problemClassNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const char* s : {"lcp", "box", "mlcp"})
      for (const char* m : {"dd", "spd", "sym", "pd", "gen"})
        for (const char* z : {"small", "medium", "large"}) v.push_back(std::string(s) + "-" + m + "-" + z);
    return v;
  }();
  return names;
}

int problemClassIndex(const std::string& name) {
  const auto& v = problemClassNames();
  const auto it = std::find(v.begin(), v.end(), name);
  return it == v.end() ? -1 : static_cast<int>(it - v.begin());
}

} // namespace suite::lcp
