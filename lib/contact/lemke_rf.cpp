// Lemke's method in revised form with refactorisation (see lemke_rf.hpp; Cottle, Pang & Stone 2009,
// Alg. 4.4.5 and sec. 4.9 for the lexicographic rule).
#include "contact/lemke_rf.hpp"

#include <Eigen/LU>

#include <cmath>

namespace suite::contact {
namespace {

using lcp::kInf;
using lcp::Mat;
using lcp::Vec;

// The revised tableau of C x = q: the basic variables, the basis inverse and the basic solution x.
struct RevisedBasis {
  const Mat& M;
  const Vec& q;
  const int n;
  const double qn;
  std::vector<int> basis;
  Mat Binv;
  Vec x;

  explicit RevisedBasis(const lcp::Problem& p)
      : M(p.M), q(p.q), n(p.size()), qn(p.q.lpNorm<Eigen::Infinity>()), basis(n), Binv(Mat::Identity(n, n)),
        x(p.q) {
    for (int i = 0; i < n; ++i) basis[i] = i;
  }

  // column of variable id in C x = q: w_i -> e_i, z_j -> -M e_j, z0 -> -e
  void column(int id, Vec* c) const {
    if (id < n)
      *c = Vec::Unit(n, id);
    else if (id < 2 * n)
      *c = -M.col(id - n);
    else
      *c = -Vec::Ones(n);
  }

  bool refactor() {
    Mat B(n, n);
    Vec c;
    for (int i = 0; i < n; ++i) column(basis[i], &c), B.col(i) = c;
    Eigen::PartialPivLU<Mat> lu(B);
    Binv = lu.inverse();
    x = lu.solve(q);
    x += lu.solve(q - B * x); // one step of iterative refinement
    return Binv.allFinite() && x.allFinite();
  }

  // Every basic variable >= 0 to round-off (Lemke's pivots keep the basis feasible; a basic value below
  // -1e-9 (1 + |q| + |x|) after a refactorisation means the pivots have lost the path, and it cycles there).
  bool feasible() const { return x.minCoeff() >= -1e-9 * (1.0 + qn + x.lpNorm<Eigen::Infinity>()); }

  bool drifted() const {
    Vec res = -q, c;
    for (int i = 0; i < n; ++i) column(basis[i], &c), res += c * x[i];
    return res.lpNorm<Eigen::Infinity>() > 1e-13 * (1.0 + qn + x.lpNorm<Eigen::Infinity>());
  }

  // lexicographic comparison of rows a, b for the ratios (x_i, Binv_i) / col_i: true if a is smaller
  bool lexLess(int a, double ca, int b, double cb) const {
    const double xa = x[a] / ca, xb = x[b] / cb;
    const double t = 1e-11 * std::max({1.0, std::abs(xa), std::abs(xb)});
    if (xa < xb - t) return true;
    if (xa > xb + t) return false;
    for (int k = 0; k < n; ++k) {
      const double ya = Binv(a, k) / ca, yb = Binv(b, k) / cb;
      const double t2 = 1e-11 * std::max({1.0, std::abs(ya), std::abs(yb)});
      if (ya < yb - t2) return true;
      if (ya > yb + t2) return false;
    }
    return false;
  }

  void pivot(int row, const Vec& col) {
    const double piv = col[row];
    Binv.row(row) /= piv;
    x[row] /= piv;
    for (int i = 0; i < n; ++i) {
      if (i == row || col[i] == 0.0) continue;
      Binv.row(i) -= col[i] * Binv.row(row);
      x[i] -= col[i] * x[row];
    }
  }

  // Minimum-ratio row for the entering column col (-1: secondary ray); among (near-)ties z0 leaves if it can,
  // else the largest pivot element (numerically safest), and the lexicographic rule decides what is left.
  int leavingRow(const Vec& col) const {
    const double ptol = 1e-9 * std::max(1.0, col.lpNorm<Eigen::Infinity>());
    double m = kInf;
    for (int i = 0; i < n; ++i)
      if (col[i] > ptol) m = std::min(m, x[i] / col[i]);
    if (!(m < kInf)) return -1;
    const double mt = m + 1e-12 * std::max(1.0, std::abs(m));
    int best = -1;
    for (int i = 0; i < n; ++i) {
      if (col[i] <= ptol || x[i] / col[i] > mt) continue;
      if (basis[i] == 2 * n) return i;
      if (best < 0 || col[i] > col[best] * (1 + 1e-9) ||
          (col[i] >= col[best] * (1 - 1e-9) && lexLess(i, col[i], best, col[best])))
        best = i;
    }
    return best;
  }
};

lcp::Status fail(lcp::Result* r, lcp::Status s, const char* message) {
  r->message = message;
  return s;
}

// The pivots after the initial one, until z0 leaves the basis or the method stops; r->pivots counted.
lcp::Status pivotLoop(RevisedBasis& t, int entering, long long cap, lcp::Result* r) {
  const int n = t.n, z0 = 2 * n;
  Vec col;
  long long since = 0;
  while (true) {
    if (r->pivots >= cap) return fail(r, lcp::Status::MaxIterations, "pivot cap reached");
    t.column(entering, &col);
    col = t.Binv * col;
    const int best = t.leavingRow(col);
    if (best < 0)
      return fail(r, lcp::Status::RayTermination, "secondary ray: no solution found by Lemke's method");
    const int leaving = t.basis[best];
    t.pivot(best, col);
    t.basis[best] = entering;
    ++r->pivots;
    ++since;
    if (since >= 64 || (since % 8 == 0 && t.drifted())) {
      if (!t.refactor()) return fail(r, lcp::Status::NumericalError, "singular basis");
      if (!t.feasible()) return fail(r, lcp::Status::NumericalError, "basis lost feasibility");
      since = 0;
    }
    if (!t.x.allFinite()) return lcp::Status::NumericalError;
    if (leaving == z0) {
      if (since > 0 && !t.refactor()) return fail(r, lcp::Status::NumericalError, "singular final basis");
      return lcp::Status::Solved;
    }
    entering = leaving < n ? leaving + n : leaving - n;
  }
}

class LemkeRefactored : public lcp::Solver {
public:
  std::string name() const override { return "lemke_rf"; }

  lcp::Result run(const lcp::Problem& p, const lcp::SolverOptions& opt) const override {
    lcp::Result r;
    const int n = p.size();
    r.z = Vec::Zero(n);
    if (!p.isStandard()) {
      r.status = lcp::Status::Unsupported;
      r.message = "lemke_rf: standard LCPs only";
      return r;
    }
    if (n == 0 || p.q.minCoeff() >= 0.0) {
      r.status = lcp::Status::Solved;
      return r;
    }
    const long long cap = opt.max_iterations > 0 ? opt.max_iterations : std::max(100000LL, 100LL * n);
    RevisedBasis t(p);
    // initial pivot: z0 enters, the row of the lexicographically most negative q leaves
    int row = 0;
    for (int i = 1; i < n; ++i)
      if (t.lexLess(row, -1.0, i, -1.0)) row = i;
    Vec col;
    t.column(2 * n, &col);
    col = t.Binv * col;
    const int leaving = t.basis[row];
    t.pivot(row, col);
    t.basis[row] = 2 * n;
    r.status = pivotLoop(t, leaving + n, cap, &r); // leaving + n: the complement of w_row
    for (int i = 0; i < n; ++i)
      if (t.basis[i] >= n && t.basis[i] < 2 * n) r.z[t.basis[i] - n] = std::max(0.0, t.x[i]);
    r.iterations = static_cast<int>(std::min<long long>(r.pivots, 2147483647LL));
    return r;
  }
};

} // namespace

std::unique_ptr<lcp::Solver> makeLemkeRefactored() {
  return std::make_unique<LemkeRefactored>();
}

std::unique_ptr<lcp::Solver> makeContactSolver(const std::string& name) {
  if (name == "lemke_rf") return makeLemkeRefactored();
  return lcp::makeSolver(name);
}

std::vector<Choice> contactSolverChoices() {
  std::vector<Choice> v = choicesOf(lcp::solverRegistry());
  v.push_back(
      {"lemke_rf", "Lemke, revised form with LU refactorisation (contact library; standard LCPs only)"});
  return v;
}

} // namespace suite::contact
