// Cottle-Dantzig principal pivoting method (Cottle & Dantzig 1968, Linear Algebra Appl. 1; Cottle, Pang &
// Stone 2009, Alg. 4.5.1, "PPM II"): a major cycle picks a distinguished basic variable with negative value
// (Dantzig's choice: the most negative), increases its complement, and performs simple pivots on the
// blocking basic variables (the new driver is the complement of the one that left) until the distinguished
// variable leaves at zero. Processes P- and positive semidefinite matrices. Box LCPs and MLCPs go through the
// standard-form reformulation of reformulate.hpp. No warm start (starts from the basis w).
#include "lcp/reformulate.hpp"
#include "lcp/solver.hpp"
#include "lcp/tableau.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

struct CdOut {
  Vec z;
  Status status = Status::MaxIterations;
  long long pivots = 0;
  int majors = 0;
  std::string message;
};

CdOut cottleDantzig(const Mat& M, const Vec& q, long long cap) {
  const int n = static_cast<int>(q.size());
  CdOut out;
  if (n == 0) { // everything was eliminated (free variables only)
    out.status = Status::Solved;
    out.z = Vec();
    return out;
  }
  Tableau T(M, q, nullptr);
  const double vtol = 1e-13 * (1.0 + q.lpNorm<Eigen::Infinity>());
  while (true) {
    int r = -1;
    double most = -vtol;
    for (int i = 0; i < n; ++i)
      if (T.b[i] < most) {
        most = T.b[i];
        r = i;
      }
    if (r < 0) {
      out.status = Status::Solved;
      break;
    }
    ++out.majors;
    const int dist = T.basic[r];
    int driver = Tableau::complement(dist, n);
    bool major_done = false;
    while (!major_done) {
      if (out.pivots >= cap) {
        out.status = Status::MaxIterations;
        out.message = "pivot cap reached";
        break;
      }
      const int c = T.col_of[driver];
      const double ptol = 1e-12 * std::max(1.0, T.A.col(c).lpNorm<Eigen::Infinity>());
      const int rd = T.row_of[dist];
      int best = -1;
      double tbest = kInf;
      // the distinguished variable (negative) increases to zero
      if (T.A(rd, c) > ptol) {
        tbest = -T.b[rd] / T.A(rd, c);
        best = rd;
      }
      for (int i = 0; i < n; ++i) {
        if (i == rd || T.A(i, c) >= -ptol || T.b[i] < -vtol) continue; // negative ones may decrease
        const double t = std::max(0.0, T.b[i]) / -T.A(i, c);
        if (t < tbest - 1e-12 * std::max(1.0, std::abs(tbest))) {
          tbest = t;
          best = i;
        }
      }
      if (best < 0) {
        out.status = Status::RayTermination;
        out.message = "unblocked driving variable: the LCP has no solution (or M is not processable)";
        break;
      }
      const int leaving = T.basic[best];
      T.pivot(best, c);
      ++out.pivots;
      if (!T.b.allFinite()) {
        out.status = Status::NumericalError;
        break;
      }
      if (leaving == dist)
        major_done = true;
      else
        driver = Tableau::complement(leaving, n);
    }
    if (!major_done) break;
  }
  out.z = T.zValues();
  return out;
}

class CottleDantzig : public Solver {
public:
  std::string name() const override { return "cottle_dantzig"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    Result r;
    const long long cap = opt.max_iterations > 0 ? opt.max_iterations : 100LL * p.size() + 1000;
    CdOut c;
    if (p.isStandard()) {
      c = cottleDantzig(p.M, p.q, cap);
      r.z = c.z;
    } else {
      const Reformulation R = toStandardLcp(p);
      c = cottleDantzig(R.lcp.M, R.lcp.q, cap);
      r.z = clampToBox(p, R.recover(c.z));
    }
    r.status = c.status;
    r.pivots = c.pivots;
    r.iterations = static_cast<int>(c.pivots);
    r.message = c.message;
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeCottleDantzig() {
  return std::make_unique<CottleDantzig>();
}

} // namespace suite::lcp
