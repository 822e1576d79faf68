// LCP problem types, validation, natural-map residual and complementarity (see problem.hpp).
#include "lcp/problem.hpp"

#include <cmath>
#include <sstream>

namespace suite::lcp {

const char* kindName(Kind k) {
  switch (k) {
  case Kind::LCP:
    return "lcp";
  case Kind::Box:
    return "box";
  case Kind::MLCP:
    return "mlcp";
  }
  return "?";
}

bool Problem::isStandard() const {
  for (int i = 0; i < size(); ++i)
    if (l[i] != 0.0 || u[i] != kInf) return false;
  return true;
}

Problem makeLcp(Mat M, Vec q, std::string name) {
  Problem p;
  p.kind = Kind::LCP;
  p.M = std::move(M);
  p.q = std::move(q);
  p.l = Vec::Zero(p.q.size());
  p.u = Vec::Constant(p.q.size(), kInf);
  p.name = std::move(name);
  return p;
}

Problem makeBox(Mat M, Vec q, Vec l, Vec u, std::string name) {
  Problem p;
  p.kind = Kind::Box;
  p.M = std::move(M);
  p.q = std::move(q);
  p.l = std::move(l);
  p.u = std::move(u);
  p.name = std::move(name);
  return p;
}

Problem makeMlcp(Mat M, Vec q, int n_eq, std::string name) {
  Problem p = makeLcp(std::move(M), std::move(q), std::move(name));
  p.kind = Kind::MLCP;
  p.n_eq = n_eq;
  for (int i = 0; i < n_eq && i < p.size(); ++i) p.l[i] = -kInf;
  return p;
}

std::string validate(const Problem& p) {
  std::ostringstream os;
  const long n = p.q.size();
  if (p.M.rows() != p.M.cols()) {
    os << "M is not square (" << p.M.rows() << " x " << p.M.cols() << ")";
    return os.str();
  }
  if (p.M.rows() != n) {
    os << "M is " << p.M.rows() << " x " << p.M.cols() << " but q has " << n << " entries";
    return os.str();
  }
  if (n == 0) return "empty problem (n = 0)";
  if (p.l.size() != n || p.u.size() != n) {
    os << "bounds have " << p.l.size() << " / " << p.u.size() << " entries, expected " << n;
    return os.str();
  }
  for (long j = 0; j < n; ++j)
    for (long i = 0; i < n; ++i)
      if (!std::isfinite(p.M(i, j))) {
        os << "M(" << i << "," << j << ") = " << p.M(i, j) << " is not finite";
        return os.str();
      }
  for (long i = 0; i < n; ++i) {
    if (!std::isfinite(p.q[i])) {
      os << "q[" << i << "] = " << p.q[i] << " is not finite";
      return os.str();
    }
    if (std::isnan(p.l[i]) || std::isnan(p.u[i])) {
      os << "bound " << i << " is NaN";
      return os.str();
    }
    if (p.l[i] > p.u[i]) {
      os << "l[" << i << "] = " << p.l[i] << " > u[" << i << "] = " << p.u[i];
      return os.str();
    }
    if (p.l[i] == kInf || p.u[i] == -kInf) {
      os << "bound " << i << " is infinite on the wrong side (l = " << p.l[i] << ", u = " << p.u[i] << ")";
      return os.str();
    }
  }
  if (p.n_eq < 0 || p.n_eq > n) {
    os << "equality block size " << p.n_eq << " outside [0, " << n << "]";
    return os.str();
  }
  if (p.z_known.size() != 0 && p.z_known.size() != n) {
    os << "known solution has " << p.z_known.size() << " entries, expected " << n;
    return os.str();
  }
  return "";
}

double naturalResidual(const Problem& p, const Vec& z, const Vec& w) {
  double r = 0.0;
  for (int i = 0; i < p.size(); ++i) {
    const double t = std::min(p.u[i], std::max(p.l[i], z[i] - w[i]));
    const double d = std::abs(z[i] - t);
    if (!(d <= r)) r = std::isnan(d) ? kInf : d; // NaN -> inf
  }
  return r;
}

double complementarity(const Problem& p, const Vec& z, const Vec& w) {
  double c = 0.0;
  for (int i = 0; i < p.size(); ++i) {
    if (std::isfinite(p.l[i])) c += std::abs((z[i] - p.l[i]) * std::max(w[i], 0.0));
    if (std::isfinite(p.u[i])) c += std::abs((p.u[i] - z[i]) * std::max(-w[i], 0.0));
  }
  return c;
}

double acceptanceTolerance(const Problem& p, double rel_tol) {
  return rel_tol * (1.0 + p.q.lpNorm<Eigen::Infinity>());
}

Vec clampToBox(const Problem& p, const Vec& z) {
  return z.cwiseMax(p.l).cwiseMin(p.u);
}

} // namespace suite::lcp
