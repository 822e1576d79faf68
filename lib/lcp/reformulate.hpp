// Box LCP / MLCP -> standard LCP of size m >= n (Cottle, Pang & Stone 2009, sec. 1.2): z = c + S x with
//   l, u finite:  z = l + x,  extra multiplier v >= 0 of the upper bound:  (Mz+q) + v >= 0 _|_ x,
//                 u - l - x >= 0 _|_ v;
//   l finite:     z = l + x,  (Mz+q) >= 0 _|_ x;      u finite:  z = u - y,  -(Mz+q) >= 0 _|_ y;
//   free:         eliminated first when M_FF is well conditioned (rcond > 1e-12): z_F = -M_FF^{-1}(q_F + M_FB z_B),
//                 the rest a box problem with the Schur complement M_BB - M_BF M_FF^{-1} M_FB (the MLCP
//                 reduction, Cottle, Pang & Stone 2009 sec. 1.5); else z = x+ - x-,  (Mz+q) >= 0 _|_ x+,
//                 -(Mz+q) >= 0 _|_ x-.
// Used by the methods defined for standard LCPs only (Lemke, Cottle-Dantzig) as their box extension.
#pragma once

#include "lcp/problem.hpp"

namespace suite::lcp {

struct Reformulation {
  Problem lcp; // standard LCP in x
  Mat S;       // z = c + S x  (n x m)
  Vec c;
  Vec recover(const Vec& x) const { return c + S * x; }
};

Reformulation toStandardLcp(const Problem& p);

} // namespace suite::lcp
