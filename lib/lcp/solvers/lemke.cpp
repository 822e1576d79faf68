// Lemke's complementary pivoting method with covering vector d = e and the lexicographic minimum-ratio
// rule for degeneracy (Lemke 1965; Cottle, Pang & Stone 2009, Alg. 4.4.5 and sec. 4.9). Box LCPs and MLCPs
// are solved through the standard-form reformulation of reformulate.hpp (the "box extension").
// Pivots counted: the complementary pivots after the initial one that brings z0 into the basis (the last one
// drives z0 out), Murty's count, so Murty's example of size n takes 2^n - 1 pivots (Murty 1988, sec. 6.1).
#include "lcp/reformulate.hpp"
#include "lcp/solver.hpp"
#include "lcp/tableau.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

struct Core {
  Vec z;
  Status status = Status::MaxIterations;
  long long pivots = 0;
  std::string message;
};

// -1 if row a is lexicographically smaller than row b for the ratios (b_i, Binv_i) / s_i.
int lexCompare(const Tableau& T, int ra, double sa, int rb, double sb) {
  const double xa = T.b[ra] / sa, xb = T.b[rb] / sb;
  const double tol = 1e-12 * std::max({1.0, std::abs(xa), std::abs(xb)});
  if (xa < xb - tol) return -1;
  if (xa > xb + tol) return 1;
  for (int k = 0; k < T.n; ++k) {
    const double ya = T.binv(ra, k) / sa, yb = T.binv(rb, k) / sb;
    const double t2 = 1e-12 * std::max({1.0, std::abs(ya), std::abs(yb)});
    if (ya < yb - t2) return -1;
    if (ya > yb + t2) return 1;
  }
  return 0;
}

Core lemkeCore(const Mat& M, const Vec& q, long long max_pivots) {
  const int n = static_cast<int>(q.size());
  Core out;
  out.z = Vec::Zero(n);
  if (n == 0 || q.minCoeff() >= 0.0) {
    out.status = Status::Solved;
    return out;
  }
  const Vec d = Vec::Ones(n);
  Tableau T(M, q, &d);
  const int z0 = 2 * n;
  // Initial pivot: z0 = max_i -q_i/d_i, lexicographic maximum of (-b_i, -Binv_i)/d_i (== minimum with s =
  // -d).
  int r = 0;
  for (int i = 1; i < n; ++i)
    if (lexCompare(T, i, -d[i], r, -d[r]) > 0) r = i;
  T.pivot(r, T.col_of[z0]); // initial almost-complementary basis: not counted
  int entering = n + r;     // w_r left the basis -> its complement z_r enters
  while (true) {
    if (out.pivots >= max_pivots) {
      out.status = Status::MaxIterations;
      out.message = "pivot cap reached";
      break;
    }
    const int c = T.col_of[entering];
    const double cn = T.A.col(c).lpNorm<Eigen::Infinity>();
    const double ptol = 1e-12 * std::max(1.0, cn);
    int best = -1;
    for (int i = 0; i < n; ++i) {
      const double a = T.A(i, c);
      if (a >= -ptol) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      const int cmp = lexCompare(T, i, -a, best, -T.A(best, c));
      if (cmp < 0) best = i;
    }
    if (best < 0) {
      out.status = Status::RayTermination;
      out.message = "secondary ray: no solution found by Lemke's method";
      break;
    }
    // Prefer z0 to leave on a tie of the primary ratio (ends the path as early as possible).
    const int rz0 = T.row_of[z0];
    if (rz0 >= 0 && rz0 != best && T.A(rz0, c) < -ptol) {
      const double x0 = T.b[rz0] / -T.A(rz0, c), xb = T.b[best] / -T.A(best, c);
      if (x0 <= xb + 1e-12 * std::max({1.0, std::abs(x0), std::abs(xb)})) best = rz0;
    }
    const int leaving = T.basic[best];
    T.pivot(best, c);
    ++out.pivots;
    if (!T.b.allFinite()) {
      out.status = Status::NumericalError;
      break;
    }
    if (leaving == z0) {
      out.status = Status::Solved;
      break;
    }
    entering = Tableau::complement(leaving, n);
  }
  out.z = T.zValues();
  return out;
}

class Lemke : public Solver {
public:
  std::string name() const override { return "lemke"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    Result r;
    const long long cap = opt.max_iterations > 0 ? opt.max_iterations : std::max(100000LL, 100LL * p.size());
    if (p.isStandard()) {
      Core c = lemkeCore(p.M, p.q, cap);
      r.z = c.z;
      r.status = c.status;
      r.pivots = c.pivots;
      r.message = c.message;
    } else {
      const Reformulation R = toStandardLcp(p);
      Core c = lemkeCore(R.lcp.M, R.lcp.q, cap);
      r.z = clampToBox(p, R.recover(c.z));
      r.status = c.status;
      r.pivots = c.pivots;
      r.message = c.message;
    }
    r.iterations = static_cast<int>(std::min<long long>(r.pivots, 2147483647LL));
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeLemke() {
  return std::make_unique<Lemke>();
}

} // namespace suite::lcp
