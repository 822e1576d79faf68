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

// Column by column (contiguous, vectorised): density, positive diagonal, strict row diagonal dominance.
void scanColumns(const Mat& M, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  Vec off = Vec::Zero(n); // row sums of |M_ij|, j != i
  long long nnz = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double* c = M.col(j).data();
    double* o = off.data();
    long long z = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      o[i] += std::abs(c[i]);
      z += c[i] == 0.0;
    }
    nnz += n - z;
  }
  const Vec d = M.diagonal();
  off -= d.cwiseAbs();
  f->density = n ? static_cast<double>(nnz) / (double(n) * double(n)) : 0.0;
  f->diag_positive = n > 0 && d.minCoeff() > 0;
  f->diag_dominant = f->diag_positive && (off.array() < d.array()).all();
}

// Every 2 x 2 principal minor of (M + M^T) / 2 > 0 (the diagonal is positive): necessary for definiteness.
// Symmetric M: column by column, vectorised; otherwise the transposed entries are read in 16 x 16 tiles.
bool minorsPositive(const Mat& M, bool symmetric) {
  const Eigen::Index n = M.rows();
  const Vec d = M.diagonal();
  if (symmetric) {
    for (Eigen::Index j = 0; j + 1 < n; ++j) {
      const Eigen::Index k = n - j - 1;
      if (!((d(j) * d.tail(k).array() - M.col(j).tail(k).array().square()) > 0).all()) return false;
    }
    return true;
  }
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

// Positive definite (symmetric part) as far as the tests of problem_class.hpp go.
bool definite(const Problem& p, bool cholesky, ProblemFeatures* f) {
  f->minors_ok = f->diag_positive && minorsPositive(p.M, f->symmetric);
  if (!f->minors_ok || !cholesky) return f->minors_ok;
  f->cholesky_tried = true;
  f->cholesky_ok = f->symmetric ? choleskySucceeds(p.M) : choleskySucceeds(0.5 * (p.M + p.M.transpose()));
  return f->cholesky_ok;
}

} // namespace

ProblemFeatures classify(const Problem& p, bool cholesky) {
  ProblemFeatures f;
  f.n = p.size();
  f.kind = p.kind;
  f.structure = structureOf(p);
  f.size = sizeOf(f.n);
  for (int i = 0; i < f.n; ++i) {
    f.finite_lower += std::isfinite(p.l[i]);
    f.finite_upper += std::isfinite(p.u[i]);
  }
  scanColumns(p.M, &f);
  f.symmetric = isSymmetric(p);
  if (f.diag_dominant) {
    f.matrix = "dd";
    return f;
  }
  const bool def = definite(p, cholesky, &f);
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
