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
    const Mat& M = p.M;
    const Vec& q = p.q;
    const int z0 = 2 * n;
    // column of variable id in C x = q: w_i -> e_i, z_j -> -M e_j, z0 -> -e
    auto column = [&](int id, Vec* c) {
      if (id < n)
        *c = Vec::Unit(n, id);
      else if (id < 2 * n)
        *c = -M.col(id - n);
      else
        *c = -Vec::Ones(n);
    };
    std::vector<int> basis(n);
    for (int i = 0; i < n; ++i) basis[i] = i;
    Mat Binv = Mat::Identity(n, n);
    Vec x = q;
    const double qn = q.lpNorm<Eigen::Infinity>();
    auto refactor = [&]() -> bool {
      Mat B(n, n);
      Vec c;
      for (int i = 0; i < n; ++i) column(basis[i], &c), B.col(i) = c;
      Eigen::PartialPivLU<Mat> lu(B);
      Binv = lu.inverse();
      x = lu.solve(q);
      x += lu.solve(q - B * x); // one step of iterative refinement
      return Binv.allFinite() && x.allFinite();
    };
    auto drifted = [&]() {
      Vec res = -q, c;
      for (int i = 0; i < n; ++i) column(basis[i], &c), res += c * x[i];
      return res.lpNorm<Eigen::Infinity>() > 1e-13 * (1.0 + qn + x.lpNorm<Eigen::Infinity>());
    };
    // lexicographic comparison of rows a, b for the ratios (x_i, Binv_i) / col_i: -1 if a is smaller
    auto lexLess = [&](int a, double ca, int b, double cb) {
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
    };
    auto pivot = [&](int row, const Vec& col) {
      const double piv = col[row];
      Binv.row(row) /= piv;
      x[row] /= piv;
      for (int i = 0; i < n; ++i) {
        if (i == row || col[i] == 0.0) continue;
        Binv.row(i) -= col[i] * Binv.row(row);
        x[i] -= col[i] * x[row];
      }
    };
    // initial pivot: z0 enters, the row of the lexicographically most negative q leaves
    int row = 0;
    for (int i = 1; i < n; ++i)
      if (lexLess(row, -1.0, i, -1.0)) row = i;
    Vec col;
    column(z0, &col);
    col = Binv * col;
    int leaving = basis[row];
    pivot(row, col);
    basis[row] = z0;
    int entering = leaving + n; // complement of w_row
    long long since = 0;
    while (true) {
      if (r.pivots >= cap) {
        r.status = lcp::Status::MaxIterations;
        r.message = "pivot cap reached";
        break;
      }
      column(entering, &col);
      col = Binv * col;
      const double ptol = 1e-9 * std::max(1.0, col.lpNorm<Eigen::Infinity>());
      // minimum ratio; among (near-)ties z0 leaves if it can, else the largest pivot element (numerically
      // safest), and the lexicographic rule decides what is left
      double m = kInf;
      for (int i = 0; i < n; ++i)
        if (col[i] > ptol) m = std::min(m, x[i] / col[i]);
      if (!(m < kInf)) {
        r.status = lcp::Status::RayTermination;
        r.message = "secondary ray: no solution found by Lemke's method";
        break;
      }
      const double mt = m + 1e-12 * std::max(1.0, std::abs(m));
      int best = -1;
      for (int i = 0; i < n; ++i) {
        if (col[i] <= ptol || x[i] / col[i] > mt) continue;
        if (basis[i] == z0) {
          best = i;
          break;
        }
        if (best < 0 || col[i] > col[best] * (1 + 1e-9) ||
            (col[i] >= col[best] * (1 - 1e-9) && lexLess(i, col[i], best, col[best])))
          best = i;
      }
      leaving = basis[best];
      pivot(best, col);
      basis[best] = entering;
      ++r.pivots;
      ++since;
      if (since >= 64 || (since % 8 == 0 && drifted())) {
        if (!refactor()) {
          r.status = lcp::Status::NumericalError;
          r.message = "singular basis";
          break;
        }
        since = 0;
      }
      if (!x.allFinite()) {
        r.status = lcp::Status::NumericalError;
        break;
      }
      if (leaving == z0) {
        if (since > 0 && !refactor()) {
          r.status = lcp::Status::NumericalError;
          r.message = "singular final basis";
          break;
        }
        r.status = lcp::Status::Solved;
        break;
      }
      entering = leaving < n ? leaving + n : leaving - n;
    }
    for (int i = 0; i < n; ++i)
      if (basis[i] >= n && basis[i] < 2 * n) r.z[basis[i] - n] = std::max(0.0, x[i]);
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

} // namespace suite::contact
