// Fifth-order WENO-Z interface value (explicit, non-compact), the `weno5` comparator, and the WENO-Z weights of
// the CRWENO5 rows (crweno5.hpp). Reference: Jiang & Shu, J. Comput. Phys. 126 (1996) 202, eqs. (2.10)-(2.17)
// for candidates and smoothness indicators; Borges, Carmona, Costa & Don, J. Comput. Phys. 227 (2008) 3191,
// eq. (28) for the Z weights alpha_k = d_k (1 + (tau / (beta_k + eps))^p); epsilon = 1e-6 times the mean
// square of the stencil values (scale-invariant form of Ghosh & Baeder's 1e-6).
// The exponent p (measured at HyPar's Sod / Lax settings, rf-char):
//  - explicit values (weno5ZValue: the `weno5` scheme, the WENO5 closures of the compact schemes, the
//    Lax-Friedrichs term of their rf-char faces): p = 1, Borges et al.'s original, less dissipative at
//    discontinuities: WENO5 L1(rho) Sod N = 200 2.22e-3 with p = 1, 2.46e-3 with p = 2 (HyPar's WENO5
//    2.39e-3), Lax 7.81e-3 against 8.94e-3; order 5.3 at critical points here (scale-relative epsilon).
//    Without the positivity limiter it fails LeBlanc at -cfl 0.4 (p = 2 completes); the limiter is on by
//    default and covers it.
//  - the upwind part of enopade6's ENO-Pade row: p = 1 (crweno_cu6.hpp).
//  - CRWENO5 rows (wenoZWeights): p = 2 (Don & Borges, J. Comput. Phys. 250 (2013) 347). p = 1 lowers
//    crweno5's errors below HyPar's too (Sod 200 1.72e-3 against 1.90e-3 with p = 2), but its weights then
//    pass round-off differences on to the tridiagonal systems: with -line_solve substructured (not bitwise
//    across ranks) the 3D explosion at 24^3 differs by 1e-11 between 1 and 2 ranks after 8 steps instead of
//    < 1e-12.
#pragma once

#include "euler/row.hpp"

#include <cmath>

namespace suite::euler {

// epsilon relative to the data scale: 1e-6 (Ghosh & Baeder 2012) times the mean square of the stencil values,
// so that round-off-level variations (e.g. the acoustic characteristic fields of a pure entropy wave) give
// the optimal weights instead of arbitrary ones; with arbitrary weights, compact (CRWENO) systems can become
// ill-conditioned.
constexpr double kWenoEpsRel = 1e-6, kWenoEpsAbs = 1e-40;

// Smoothness indicators beta_0..2 of Jiang & Shu on v[0..4] = f_{j-2} .. f_{j+2}.
void weno5Smoothness(const double* v, double beta[3]);
// WENO-Z nonlinear weights for linear weights d[3], from v[0..4] = f_{j-2} .. f_{j+2}.
void wenoZWeights(const double* v, const double d[3], double w[3]);
// The same from the indicators beta[0..2] of v already computed (weno5Smoothness).
void wenoZWeightsFromBeta(const double* v, const double beta[3], const double d[3], double w[3]);
// Left-biased fifth-order WENO-Z value f_{j+1/2} from v[0..4] = f_{j-2} .. f_{j+2}.
double weno5Value(const double* v);
// The same from the five values, inline so that loops over many stencils vectorise (Weno5Line). Four divisions
// (the division is the costliest operation here): the weights' normalisation and the candidates' 1/6 are one
// division of the weighted sum, and the epsilon's 1/5 is a product (round-off level changes only).
inline double weno5ZValue(double v0, double v1, double v2, double v3, double v4) {
  const double t0 = v0 - 2.0 * v1 + v2, s0 = v0 - 4.0 * v1 + 3.0 * v2;
  const double t1 = v1 - 2.0 * v2 + v3, s1 = v1 - v3;
  const double t2 = v2 - 2.0 * v3 + v4, s2 = 3.0 * v2 - 4.0 * v3 + v4;
  const double b0 = 13.0 / 12.0 * t0 * t0 + 0.25 * s0 * s0;
  const double b1 = 13.0 / 12.0 * t1 * t1 + 0.25 * s1 * s1;
  const double b2 = 13.0 / 12.0 * t2 * t2 + 0.25 * s2 * s2;
  const double tau = std::abs(b0 - b2);
  const double eps = kWenoEpsAbs + kWenoEpsRel / 5.0 * (v0 * v0 + v1 * v1 + v2 * v2 + v3 * v3 + v4 * v4);
  const double q0 = tau / (b0 + eps), q1 = tau / (b1 + eps), q2 = tau / (b2 + eps);
  const double a0 = 0.1 * (1.0 + q0), a1 = 0.6 * (1.0 + q1), a2 = 0.3 * (1.0 + q2);
  const double c0 = 2.0 * v0 - 7.0 * v1 + 11.0 * v2, c1 = -v1 + 5.0 * v2 + 2.0 * v3;
  const double c2 = 2.0 * v2 + 5.0 * v3 - v4;
  return (a0 * c0 + a1 * c1 + a2 * c2) / (6.0 * (a0 + a1 + a2));
}
// Explicit row (a = c = 0, b = 1) from v[0..5] = f_{j-2} .. f_{j+3} (v[5] unused).
Row weno5Row(const double* v);

} // namespace suite::euler
