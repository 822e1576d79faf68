// Smoothing Newton method with the smoothing parameter as an unknown (Qi, Sun & Zhou 2000, Math. Prog. 87,
// Alg. 1; the scheme of Zhang & Gao 2003 and Li & Fukushima 2000) on the CHKS-smoothed natural map
// H_mu(z) = z - mid_mu(l, u, z - w), mid_mu(t) = l + s_mu(t - l) - s_mu(t - u),
// s_mu(x) = (x + sqrt(x^2 + 4 mu^2)) / 2 (Chen-Harker-Kanzow-Smale). Warm start: the initial z.
#include "lcp/solver.hpp"

#include <cmath>

namespace suite::lcp {
namespace {

// H(mu, z), the diagonal D with dH/dz = (I - D) + D M, and dH/dmu.
void evalH(const Problem& p, double mu, const Vec& z, const Vec& w, Vec* H, Vec* D, Vec* Hmu) {
  const int n = p.size();
  const double m2 = 4.0 * mu * mu;
  for (int i = 0; i < n; ++i) {
    const double t = z[i] - w[i];
    double mid = t, dmid = 1.0, dmu = 0.0;
    const bool lf = std::isfinite(p.l[i]), uf = std::isfinite(p.u[i]);
    if (lf || uf) {
      mid = 0.0;
      dmid = 0.0;
      if (lf) {
        const double x = t - p.l[i], r = std::sqrt(x * x + m2);
        mid += p.l[i] + 0.5 * (x + r);
        dmid += 0.5 * (1.0 + (r > 0 ? x / r : 0.0));
        dmu += r > 0 ? 2.0 * mu / r : 0.0;
      }
      if (uf) {
        const double x = t - p.u[i], r = std::sqrt(x * x + m2);
        if (lf) {
          mid -= 0.5 * (x + r);
          dmid -= 0.5 * (1.0 + (r > 0 ? x / r : 0.0));
          dmu -= r > 0 ? 2.0 * mu / r : 0.0;
        } else { // u - s_mu(u - t)
          const double y = -x;
          mid += p.u[i] - 0.5 * (y + r);
          dmid += 0.5 * (1.0 + (r > 0 ? y / r : 0.0));
          dmu -= r > 0 ? 2.0 * mu / r : 0.0;
        }
      }
    }
    (*H)[i] = z[i] - mid;
    (*D)[i] = dmid;
    (*Hmu)[i] = -dmu;
  }
}

class SmoothedNewton : public Solver {
public:
  std::string name() const override { return "smoothed_newton"; }
  Result run(const Problem& p, const SolverOptions& opt) const override {
    const int n = p.size();
    const int cap = opt.max_iterations > 0 ? opt.max_iterations : 200;
    const double tol = acceptanceTolerance(p, opt.rel_tol);
    const double mu0 = 1.0, gamma = 0.2, sigma = 1e-4, delta = 0.5;
    Result r;
    Vec z = (opt.warm_start && opt.warm_start->size() == n) ? *opt.warm_start : Vec::Zero(n);
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(z[i])) z[i] = 0.0;
    double mu = mu0;
    Vec w = p.M * z + p.q, H(n), D(n), Hmu(n), Hn(n), Dn(n), Hmun(n);
    evalH(p, mu, z, w, &H, &D, &Hmu);
    double phi = mu * mu + H.squaredNorm();
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
      const double beta = gamma * std::min(1.0, phi);
      const double dmu = -mu + beta * mu0;
      J = D.asDiagonal() * p.M;
      J.diagonal() += Vec::Ones(n) - D;
      Eigen::PartialPivLU<Mat> lu(J);
      const Vec dz = lu.solve(-H - Hmu * dmu);
      if (!dz.allFinite()) {
        r.status = Status::Breakdown;
        r.message = "singular smoothed Jacobian";
        break;
      }
      double lam = 1.0;
      bool accepted = false;
      for (int ls = 0; ls < 60; ++ls) {
        const double mun = mu + lam * dmu;
        const Vec zn = z + lam * dz;
        const Vec wn = p.M * zn + p.q;
        evalH(p, mun, zn, wn, &Hn, &Dn, &Hmun);
        const double phin = mun * mun + Hn.squaredNorm();
        if (phin <= (1.0 - 2.0 * sigma * (1.0 - gamma * mu0) * lam) * phi) {
          mu = mun;
          z = zn;
          w = wn;
          H = Hn;
          D = Dn;
          Hmu = Hmun;
          phi = phin;
          accepted = true;
          break;
        }
        lam *= delta;
      }
      ++r.iterations;
      if (!accepted) {
        r.status = Status::Breakdown;
        r.message = "line search failed";
        break;
      }
    }
    r.z = z;
    return r;
  }
};

} // namespace

std::unique_ptr<Solver> makeSmoothedNewton() {
  return std::make_unique<SmoothedNewton>();
}

} // namespace suite::lcp
