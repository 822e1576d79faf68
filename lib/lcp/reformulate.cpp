// Box LCP -> standard LCP reformulation; see reformulate.hpp.
#include "lcp/reformulate.hpp"

#include <cmath>
#include <vector>

namespace suite::lcp {

Reformulation toStandardLcp(const Problem& p) {
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

} // namespace suite::lcp
