// LCP problem types (standard LCP, box LCP, MLCP as a box LCP with free variables), validation and the
// natural-map residual used as the acceptance test of every solver (Cottle, Pang & Stone 2009, ch. 1).
//
// Every problem is stored in the box form  l <= z <= u,  w = M z + q,  with
//   z_i = l_i  =>  w_i >= 0,   z_i = u_i  =>  w_i <= 0,   l_i < z_i < u_i  =>  w_i = 0.
// Standard LCP: l = 0, u = +inf.  MLCP: the first n_eq variables have l = -inf, u = +inf (w = 0 there).
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <string>

namespace suite::lcp {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;
constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind { LCP = 0, Box = 1, MLCP = 2 };
const char* kindName(Kind k);

struct Problem {
  Kind kind = Kind::LCP;
  Mat M;
  Vec q, l, u;  // l, u always sized n (LCP: 0 and +inf)
  int n_eq = 0; // MLCP: number of leading free (equality) variables
  Vec z_known;  // optional known solution (empty if none)
  // M == M^T exactly: -1 unknown (solvers test it, see isSymmetric(const Problem&)), 0 no, 1 yes. Set by
  // the generators, which know it, so that a batch does not re-test it for every solver.
  signed char symmetric = -1;
  std::string name;

  int size() const { return static_cast<int>(q.size()); }
  // Standard LCP (l = 0, u = +inf everywhere)?
  bool isStandard() const;
};

Problem makeLcp(Mat M, Vec q, std::string name = "");
Problem makeBox(Mat M, Vec q, Vec l, Vec u, std::string name = "");
// MLCP with an equality block of size n_eq first, then n - n_eq complementarity variables (z >= 0).
Problem makeMlcp(Mat M, Vec q, int n_eq, std::string name = "");

// Empty string when the problem is well formed, else a one-line description (non-square M, size
// mismatch, NaN/Inf in M or q, NaN bounds, l > u, l = +inf or u = -inf).
std::string validate(const Problem& p);

// w = M z + q.
inline Vec slack(const Problem& p, const Vec& z) {
  return p.M * z + p.q;
}
// Natural-map residual || z - mid(l, u, z - w) ||_inf.
double naturalResidual(const Problem& p, const Vec& z, const Vec& w);
// Complementarity: sum_i |(z_i - l_i) max(w_i,0)| + |(u_i - z_i) max(-w_i,0)| over finite bounds
// (= |z^T w| termwise for a standard LCP with z, w >= 0).
double complementarity(const Problem& p, const Vec& z, const Vec& w);
// The acceptance rule of the suite: residual <= rel_tol * (1 + ||q||_inf).
double acceptanceTolerance(const Problem& p, double rel_tol = 1e-10);
// Projection onto [l, u].
Vec clampToBox(const Problem& p, const Vec& z);

} // namespace suite::lcp
