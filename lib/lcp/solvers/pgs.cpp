// Projected Gauss-Seidel / SOR for box LCPs (Cryer 1971; Cottle, Pang & Stone 2009, sec. 5.2) and its block
// version (per-contact blocks of size b, default 3, each block subproblem solved exactly by enumerating its
// 3^b index states; Lacoursiere 2003 / Jourdan, Alart & Jean 1998). Converges for symmetric positive
// definite M; requires M_ii > 0 (else Unsupported). Iterations = sweeps; residual checked every sweep.
// Warm start: the initial z.
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

Vec initialZ(const Problem& p, const SolverOptions& opt) {
  const int n = p.size();
  Vec z = (opt.warm_start && opt.warm_start->size() == n) ? *opt.warm_start : Vec::Zero(n);
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(z[i])) z[i] = 0.0;
  return clampToBox(p, z);
}

class Pgs : public Solver {
public:
  std::string name() const override { return "pgs"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const int cap = opt.max_iterations > 0 ? opt.max_iterations : 2000;
    const double tol = acceptanceTolerance(p, opt.rel_tol);
    const double omega = opt.omega;
    Result r;
    for (int i = 0; i < n; ++i)
      if (!(p.M(i, i) > 0.0)) {
        r.status = Status::Unsupported;
        r.message = "PGS needs M_ii > 0";
        r.z = Vec::Zero(n);
        return r;
      }
    Vec z = initialZ(p, opt);
    const Mat Mt = p.M.transpose(); // contiguous rows
    while (true) {
      const Vec w = p.M * z + p.q;
      if (naturalResidual(p, z, w) <= tol) {
        r.status = Status::Solved;
        break;
      }
      if (r.iterations >= cap) {
        r.status = Status::MaxIterations;
        break;
      }
      for (int i = 0; i < n; ++i) {
        const double wi = Mt.col(i).dot(z) + p.q[i];
        const double zi = z[i] - omega * wi / p.M(i, i);
        z[i] = std::min(p.u[i], std::max(p.l[i], zi));
      }
      ++r.iterations;
      if (!z.allFinite()) {
        r.status = Status::NumericalError;
        break;
      }
    }
    r.z = z;
    return r;
  }
};

// Exact solution of a small box LCP (size b <= 4) by enumeration of the 3^b index states.
bool solveSmallBox(const Mat& A, const Vec& c, const Vec& l, const Vec& u, Vec* x) {
  const int b = static_cast<int>(c.size());
  int total = 1;
  for (int i = 0; i < b; ++i) total *= 3;
  double best = kInf;
  Vec bestx;
  for (int code = 0; code < total; ++code) {
    std::vector<int> s(b);
    int cc = code;
    bool skip = false;
    for (int i = 0; i < b; ++i) {
      s[i] = cc % 3;
      cc /= 3;
      if ((s[i] == 0 && !std::isfinite(l[i])) || (s[i] == 1 && !std::isfinite(u[i]))) skip = true;
    }
    if (skip) continue;
    Vec y(b);
    std::vector<int> F;
    for (int i = 0; i < b; ++i) {
      if (s[i] == 2)
        F.push_back(i);
      else
        y[i] = s[i] == 0 ? l[i] : u[i];
    }
    if (!F.empty()) {
      const int k = static_cast<int>(F.size());
      Mat AF(k, k);
      Vec rhs(k);
      for (int a = 0; a < k; ++a) {
        rhs[a] = -c[F[a]];
        for (int j = 0; j < b; ++j)
          if (s[j] != 2) rhs[a] -= A(F[a], j) * y[j];
        for (int e = 0; e < k; ++e) AF(a, e) = A(F[a], F[e]);
      }
      Eigen::FullPivLU<Mat> lu(AF);
      if (!lu.isInvertible()) continue;
      const Vec yf = lu.solve(rhs);
      for (int a = 0; a < k; ++a) y[F[a]] = yf[a];
    }
    const Vec v = A * y + c;
    double viol = 0.0;
    for (int i = 0; i < b; ++i) {
      if (s[i] == 0)
        viol = std::max(viol, -v[i]);
      else if (s[i] == 1)
        viol = std::max(viol, v[i]);
      else
        viol = std::max({viol, l[i] - y[i], y[i] - u[i]});
    }
    if (viol < best) {
      best = viol;
      bestx = y;
    }
    if (viol <= 1e-14 * (1.0 + c.lpNorm<Eigen::Infinity>())) break;
  }
  if (bestx.size() == 0) return false;
  *x = bestx;
  return true;
}

class PgsBlock : public Solver {
public:
  std::string name() const override { return "pgs_block"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const int bs = std::max(1, std::min(4, opt.block_size));
    const int cap = opt.max_iterations > 0 ? opt.max_iterations : 2000;
    const double tol = acceptanceTolerance(p, opt.rel_tol);
    Result r;
    Vec z = initialZ(p, opt);
    while (true) {
      const Vec w = p.M * z + p.q;
      if (naturalResidual(p, z, w) <= tol) {
        r.status = Status::Solved;
        break;
      }
      if (r.iterations >= cap) {
        r.status = Status::MaxIterations;
        break;
      }
      for (int s = 0; s < n; s += bs) {
        const int b = std::min(bs, n - s);
        const Mat A = p.M.block(s, s, b, b);
        // c = q_B + M_B,rest z_rest
        Vec c = p.q.segment(s, b) + p.M.middleRows(s, b) * z - A * z.segment(s, b);
        Vec y;
        if (!solveSmallBox(A, c, p.l.segment(s, b), p.u.segment(s, b), &y)) {
          r.status = Status::Breakdown;
          r.message = "singular diagonal block";
          r.z = z;
          return r;
        }
        z.segment(s, b) = opt.omega * y + (1.0 - opt.omega) * z.segment(s, b);
        z.segment(s, b) = z.segment(s, b).cwiseMax(p.l.segment(s, b)).cwiseMin(p.u.segment(s, b));
      }
      ++r.iterations;
      if (!z.allFinite()) {
        r.status = Status::NumericalError;
        break;
      }
    }
    r.z = z;
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makePgs() {
  return std::make_unique<Pgs>();
}
std::unique_ptr<Solver> makePgsBlock() {
  return std::make_unique<PgsBlock>();
}

} // namespace suite::lcp
