// Classification of an LCP for the solver portfolio (see problem_class.hpp).
#include "lcp/problem_class.hpp"

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

// One pass over M: symmetry, density, positive diagonal, strict row dominance, 2 x 2 principal minors of the
// symmetric part (necessary for positive definiteness).
void scanMatrix(const Mat& M, ProblemFeatures* f) {
  const Eigen::Index n = M.rows();
  double scale = 0, asym = 0;
  long long nnz = 0;
  bool dd = true, minors = true, diag = true;
  for (Eigen::Index j = 0; j < n; ++j) {
    diag = diag && M(j, j) > 0;
    double off = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double a = M(i, j), at = M(j, i);
      scale = std::max(scale, std::abs(a));
      nnz += a != 0.0;
      if (i == j) continue;
      off += std::abs(at); // row j of M
      asym = std::max(asym, std::abs(a - at));
      const double s = 0.5 * (a + at);
      minors = minors && M(i, i) * M(j, j) > s * s;
    }
    dd = dd && M(j, j) > 0 && off < M(j, j);
  }
  f->symmetric = asym <= 1e-14 * scale;
  f->density = n ? static_cast<double>(nnz) / (double(n) * double(n)) : 0.0;
  f->diag_positive = n > 0 && diag;
  f->diag_dominant = n > 0 && dd;
  f->minors_ok = f->diag_positive && minors;
}

bool choleskySucceeds(const Mat& S) {
  Eigen::LLT<Mat> llt(S);
  return llt.info() == Eigen::Success && llt.matrixLLT().diagonal().allFinite() &&
         llt.matrixLLT().diagonal().minCoeff() > 0;
}

} // namespace

ProblemFeatures classifyCheap(const Problem& p) {
  ProblemFeatures f;
  f.n = p.size();
  f.kind = p.kind;
  f.structure = structureOf(p);
  f.size = sizeOf(f.n);
  for (int i = 0; i < f.n; ++i) {
    f.finite_lower += std::isfinite(p.l[i]);
    f.finite_upper += std::isfinite(p.u[i]);
  }
  scanMatrix(p.M, &f);
  if (f.diag_dominant)
    f.matrix = "dd";
  else if (!f.minors_ok || f.n == 0)
    f.matrix = f.ifNotDefinite();
  return f;
}

void classifyByCholesky(const Problem& p, ProblemFeatures* f) {
  if (!f->matrix.empty()) return;
  f->cholesky_tried = true;
  f->cholesky_ok = f->symmetric ? choleskySucceeds(p.M) : choleskySucceeds(0.5 * (p.M + p.M.transpose()));
  f->matrix = f->cholesky_ok ? f->ifDefinite() : f->ifNotDefinite();
}

ProblemFeatures classify(const Problem& p) {
  ProblemFeatures f = classifyCheap(p);
  classifyByCholesky(p, &f);
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
