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

// Strictly row diagonally dominant with M_ii > 0.
bool diagonallyDominant(const Mat& M) {
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    const double d = M(i, i);
    if (!(d > 0) || !(M.row(i).cwiseAbs().sum() - d < d)) return false;
  }
  return true;
}

bool choleskySucceeds(const Mat& S) {
  Eigen::LLT<Mat> llt(S);
  return llt.info() == Eigen::Success && llt.matrixLLT().diagonal().allFinite() &&
         llt.matrixLLT().diagonal().minCoeff() > 0;
}

void classifyMatrix(const Problem& p, ProblemFeatures* f) {
  const double scale = p.M.cwiseAbs().maxCoeff();
  f->symmetric = (p.M - p.M.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale;
  f->diag_positive = p.M.size() > 0 && p.M.diagonal().minCoeff() > 0;
  f->diag_dominant = diagonallyDominant(p.M);
  if (f->diag_dominant) {
    f->matrix = "dd";
    return;
  }
  if (!f->diag_positive && f->symmetric) { // M_ii <= 0: not positive definite, no factorisation needed
    f->matrix = "sym";
    return;
  }
  f->cholesky_ok = f->symmetric ? choleskySucceeds(p.M) : choleskySucceeds(0.5 * (p.M + p.M.transpose()));
  f->matrix = f->symmetric ? (f->cholesky_ok ? "spd" : "sym") : (f->cholesky_ok ? "pd" : "gen");
}

} // namespace

ProblemFeatures classify(const Problem& p) {
  ProblemFeatures f;
  f.n = p.size();
  f.kind = p.kind;
  f.structure = structureOf(p);
  f.size = sizeOf(f.n);
  f.density = f.n ? static_cast<double>((p.M.array() != 0.0).count()) / (double(f.n) * f.n) : 0.0;
  for (int i = 0; i < f.n; ++i) {
    f.finite_lower += std::isfinite(p.l[i]);
    f.finite_upper += std::isfinite(p.u[i]);
  }
  if (f.n == 0) {
    f.matrix = "gen";
    return f;
  }
  classifyMatrix(p, &f);
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
