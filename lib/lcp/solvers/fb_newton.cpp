// Semismooth Newton method on the Fischer-Burmeister reformulation with Armijo line search on
// Psi = |Phi|^2/2 (De Luca, Facchinei & Kanzow 1996, Math. Prog. 75, Alg. 3.1), box LCPs through Billups'
// composition Phi_i = phi(z_i - l_i, -phi(u_i - z_i, -w_i)) (Billups 1995, thesis, ch. 2), with
// phi(a, b) = a + b - sqrt(a^2 + b^2). Warm start: the initial z.
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

struct Phi {
  double v, da, db; // value and partial derivatives
};
Phi fb(double a, double b) {
  const double r = std::hypot(a, b);
  if (r < 1e-300) return {0.0, 1.0 - M_SQRT1_2, 1.0 - M_SQRT1_2}; // an element of the generalized gradient
  return {a + b - r, 1.0 - a / r, 1.0 - b / r};
}

// Phi(z) and the diagonal factors of J = diag(gz) + diag(gw) M.
void evalPhi(const Problem& p, const Vec& z, const Vec& w, Vec* F, Vec* gz, Vec* gw) {
  const int n = p.size();
  for (int i = 0; i < n; ++i) {
    const bool lf = std::isfinite(p.l[i]), uf = std::isfinite(p.u[i]);
    if (lf && uf) {
      const Phi in = fb(p.u[i] - z[i], -w[i]);  // d/dz: -da, d/dw: -db
      const Phi out = fb(z[i] - p.l[i], -in.v); // d/dz: da, d/d(in): -db
      (*F)[i] = out.v;
      (*gz)[i] = out.da + out.db * in.da;
      (*gw)[i] = out.db * in.db;
    } else if (lf) {
      const Phi f = fb(z[i] - p.l[i], w[i]);
      (*F)[i] = f.v;
      (*gz)[i] = f.da;
      (*gw)[i] = f.db;
    } else if (uf) {
      const Phi f = fb(p.u[i] - z[i], -w[i]);
      (*F)[i] = -f.v;
      (*gz)[i] = f.da;
      (*gw)[i] = f.db;
    } else {
      (*F)[i] = w[i];
      (*gz)[i] = 0.0;
      (*gw)[i] = 1.0;
    }
  }
}

class FbNewton : public Solver {
public:
  std::string name() const override { return "fb_newton"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const int cap = opt.max_iterations > 0 ? opt.max_iterations : 200;
    const double tol = acceptanceTolerance(p, opt.rel_tol);
    const double sigma = 1e-4, rho = 1e-10;
    Result r;
    Vec z = (opt.warm_start && opt.warm_start->size() == n) ? *opt.warm_start : Vec::Zero(n);
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(z[i])) z[i] = 0.0;
    Vec w = p.M * z + p.q, F(n), gz(n), gw(n), Fn(n), gzn(n), gwn(n);
    evalPhi(p, z, w, &F, &gz, &gw);
    double psi = 0.5 * F.squaredNorm();
    Mat J(n, n);
    while (true) {
      if (naturalResidual(p, z, w) <= tol) {
        r.status = Status::Solved;
        break;
      }
      if (r.iterations >= cap) {
        r.status = Status::MaxIterations;
        break;
      }
      J = gw.asDiagonal() * p.M;
      J.diagonal() += gz;
      const Vec grad = J.transpose() * F;
      Eigen::PartialPivLU<Mat> lu(J);
      Vec d = lu.solve(-F);
      if (!d.allFinite() || grad.dot(d) > -rho * std::pow(d.norm(), 2.1)) d = -grad; // gradient step
      double t = 1.0;
      bool accepted = false;
      Vec zn;
      for (int ls = 0; ls < 60; ++ls) {
        zn = z + t * d;
        const Vec wn = p.M * zn + p.q;
        evalPhi(p, zn, wn, &Fn, &gzn, &gwn);
        const double psin = 0.5 * Fn.squaredNorm();
        if (psin <= psi + sigma * t * grad.dot(d)) {
          z = zn;
          w = wn;
          F = Fn;
          gz = gzn;
          gw = gwn;
          psi = psin;
          accepted = true;
          break;
        }
        t *= 0.5;
      }
      ++r.iterations;
      if (!accepted) {
        // stationary point of the merit function: report, the refinement in solve() may still rescue it
        r.status = naturalResidual(p, z, w) <= tol ? Status::Solved : Status::Breakdown;
        if (r.status != Status::Solved)
          r.message = "line search failed (stationary point of the merit function)";
        break;
      }
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

std::unique_ptr<Solver> makeFbNewton() {
  return std::make_unique<FbNewton>();
}

} // namespace suite::lcp
