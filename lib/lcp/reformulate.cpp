// Box LCP -> standard LCP reformulation; see reformulate.hpp.
#include "lcp/reformulate.hpp"

#include <cmath>
#include <vector>

namespace suite::lcp {

namespace {
Reformulation boxToStandard(const Problem& p) {
  const int n = p.size();
  // LCP variables: (orig index, sign of z in x, kind 0 = primary, 1 = upper-bound multiplier v)
  struct Var {
    int i;
    double sign;
    int kind;
  };
  std::vector<Var> vars;
  Reformulation R;
  R.c = Vec::Zero(n);
  for (int i = 0; i < n; ++i) {
    const bool lf = std::isfinite(p.l[i]), uf = std::isfinite(p.u[i]);
    if (lf) {
      R.c[i] = p.l[i];
      vars.push_back({i, +1.0, 0});
      if (uf) vars.push_back({i, 0.0, 1});
    } else if (uf) {
      R.c[i] = p.u[i];
      vars.push_back({i, -1.0, 0});
    } else {
      vars.push_back({i, +1.0, 0});
      vars.push_back({i, -1.0, 0});
    }
  }
  const int m = static_cast<int>(vars.size());
  R.S = Mat::Zero(n, m);
  for (int k = 0; k < m; ++k)
    if (vars[k].kind == 0) R.S(vars[k].i, k) = vars[k].sign;
  const Mat MS = p.M * R.S;
  const Vec r0 = p.M * R.c + p.q;
  Mat Mx = Mat::Zero(m, m);
  Vec qx(m);
  std::vector<int> v_of(n, -1);
  for (int k = 0; k < m; ++k)
    if (vars[k].kind == 1) v_of[vars[k].i] = k;
  for (int k = 0; k < m; ++k) {
    const Var& v = vars[k];
    if (v.kind == 0) {
      Mx.row(k) = v.sign * MS.row(v.i);
      qx[k] = v.sign * r0[v.i];
      if (v_of[v.i] >= 0) Mx(k, v_of[v.i]) = 1.0;
    } else { // u - l - x >= 0
      qx[k] = p.u[v.i] - p.l[v.i];
      Mx(k, k - 1) = -1.0; // the primary x of the same index precedes v
    }
  }
  R.lcp = makeLcp(std::move(Mx), std::move(qx), p.name + " (standard form)");
  return R;
}
} // namespace

Reformulation toStandardLcp(const Problem& p) {
  const int n = p.size();
  std::vector<int> F, B;
  for (int i = 0; i < n; ++i) (std::isfinite(p.l[i]) || std::isfinite(p.u[i]) ? B : F).push_back(i);
  if (F.empty()) return boxToStandard(p);
  // Free variables: eliminated by the Schur complement when M_FF is well conditioned, z_F = -M_FF^{-1}(q_F +
  // M_FB z_B), leaving a box problem on B with M' = M_BB - M_BF M_FF^{-1} M_FB (the x+ - x- split doubles the
  // free variables into a singular block on which Lemke's tableau loses accuracy: ray terminations at cond 1e4).
  Eigen::PartialPivLU<Mat> lu(p.M(F, F));
  if (!(lu.rcond() > 1e-12)) return boxToStandard(p); // singular block: the split still applies
  // M_FF^{-1} M_FB; no bounded variable (B empty): no columns, and Eigen's triangular solve of a 0-column
  // right-hand side binds a reference to its null data pointer (undefined behaviour, UBSan), so skip it.
  const Mat G = B.empty() ? Mat(static_cast<Eigen::Index>(F.size()), 0) : Mat(lu.solve(p.M(F, B)));
  const Vec g = lu.solve(p.q(F)); // M_FF^{-1} q_F
  Problem red;
  red.kind = Kind::Box;
  red.M = p.M(B, B) - p.M(B, F) * G;
  red.q = p.q(B) - p.M(B, F) * g;
  red.l = p.l(B);
  red.u = p.u(B);
  red.name = p.name;
  const Reformulation Rb = boxToStandard(red);
  const int m = static_cast<int>(Rb.S.cols());
  Reformulation R;
  R.lcp = Rb.lcp;
  R.c = Vec::Zero(n);
  R.S = Mat::Zero(n, m);
  const Vec cF = -g - G * Rb.c;
  const Mat SF = -G * Rb.S;
  for (size_t a = 0; a < B.size(); ++a) {
    R.c[B[a]] = Rb.c[a];
    R.S.row(B[a]) = Rb.S.row(a);
  }
  for (size_t a = 0; a < F.size(); ++a) {
    R.c[F[a]] = cF[a];
    R.S.row(F[a]) = SF.row(a);
  }
  return R;
}

} // namespace suite::lcp
