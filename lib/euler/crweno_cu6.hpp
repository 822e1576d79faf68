// Sixth-order central-upwind compact-reconstruction WENO rows (CRWENO-CU6) and the ENO-Pade row built on them,
// the rows of `enopade6` on every line that holds a discontinuity. References: Hu, Wang & Adams, J. Comput.
// Phys. 229 (2010) 8952 (WENO-CU6: the three upwind WENO5 candidates plus a downwind candidate whose smoothness
// indicator is that of the whole six-point stencil, beta_6, eq. (3.6), and the weights alpha_k = d_k (C +
// tau_6 / (beta_k + eps))^q, q = 2, tau_6 = |beta_6 - (beta_0 + 4 beta_1 + beta_2) / 6|); Ghosh & Baeder,
// SIAM J. Sci. Comput. 34 (2012) A1678 (the compact third-order candidates of CRWENO5, eqs. (13)-(17)).
//
// Compact candidates at x_{j+1/2} (f_m: cell values; h: interface fluxes); the first three are CRWENO5's, the
// fourth is the mirror image of the first (downwind):
//   c0: 2/3 h_{j-1/2} + 1/3 h_{j+1/2} = (f_{j-1} + 5 f_j) / 6
//   c1: 1/3 h_{j-1/2} + 2/3 h_{j+1/2} = (5 f_j + f_{j+1}) / 6
//   c2: 2/3 h_{j+1/2} + 1/3 h_{j+3/2} = (f_j + 5 f_{j+1}) / 6
//   c3: 1/3 h_{j+1/2} + 2/3 h_{j+3/2} = (5 f_{j+1} + f_{j+2}) / 6
// With the weights d = (1/10, 2/5, 2/5, 1/10) their combination is 3/5 times Lele's sixth-order Pade row
// (enopade6.hpp): the unique weights that give it, from the coefficients of h_{j-1/2}, h_{j+3/2}, f_{j-1}
// and f_{j+2}. So on smooth data, where the weights tend to d, a CU6 row is the Pade row, and near a
// discontinuity the downwind candidate's weight vanishes (beta_6 is large) and the row turns upwind.
// beta_6 = sum_{l=1..5} int_{I_j} (d^l p / dx^l)^2 dx for the quintic p of the six cell values (h = 1); its
// coefficients were rederived here symbolically (sympy) and agree with the paper's.
//
// The ENO-Pade row blends the CU6 row with a CRWENO5-Z row (crweno5.hpp, here with the WENO-Z exponent p = 1)
// by the downwind candidate's weight:
//   row = theta * CU6 + (1 - theta) * CRWENO5-Z,   theta = min(1, w_3 / d_3)^2,
// a convex combination of two consistent rows, so still a consistent compact row of fifth order or more:
// where the stencil is smooth (w_3 >= d_3) it is the CU6 row, tending to Pade; where the downwind part is
// rejected it becomes the CRWENO5-Z row, which keeps contacts sharper than CU6's own upwind limit (measured
// at HyPar's Sod / Lax settings, rf-char, every row of the line this row: Sod N = 200 / 800,
// Lax N = 200 / 800 L1(rho) CU6 alone 1.945e-3 / 5.72e-4 / 6.57e-3 / 1.58e-3, the blend with theta = w_3 / d_3
// 1.868e-3 / 5.43e-4 / 7.01e-3 / 1.71e-3, with its square 1.859e-3 / 5.47e-4 / 7.03e-3 / 1.71e-3 at C = 30).
// C = 30 instead of Hu et al.'s 20: scanned over 15, 20, 30, 40 on those four figures, 30 is the only value that
// met the four HyPar CRWENO5 figures (docs/euler_extremes.md). epsilon as in weno5.hpp (relative).
// p = 1 in the upwind part (Borges et al.'s original exponent; the CRWENO5-Z rows keep p = 2, weno5.hpp): less
// dissipative at shocks and contacts, with the CRWENO5-Z row at the supersonic faces (direction_sweep.cpp) the four
// figures above are 1.765e-3 / 4.92e-4 / 6.26e-3 / 1.48e-3 and every 1D battery case is at or below
// crweno5 with WENO-Z weights (with p = 2: 1.859e-3 / 5.47e-4 / 7.03e-3 / 1.71e-3, and four near-vacuum cases
// 0.5-0.7% above).
#pragma once

#include "euler/row.hpp"

namespace suite::euler {

// beta_6 of v[0..5] = f_{j-2} .. f_{j+3}.
double cu6Smoothness(const double* v);
// The CU6 weights w[0..3] (normalised) of the left-biased row at x_{j+1/2}, v[0..5] = f_{j-2} .. f_{j+3}.
void cu6Weights(const double* v, double w[4]);
// The compact row of the four candidates with weights w[0..3] (summing to 1).
Row cu6RowFromWeights(const double* v, const double w[4]);
// Left-biased CRWENO-CU6 row at x_{j+1/2} from v[0..5] = f_{j-2} .. f_{j+3}.
Row crwenoCu6Row(const double* v);
// Left-biased ENO-Pade row (the CU6 / CRWENO5-Z blend above) from v[0..5] = f_{j-2} .. f_{j+3}.
Row enoPadeBlendRow(const double* v);

} // namespace suite::euler
