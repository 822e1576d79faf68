// ENO-Pade 6: sixth-order Pade (compact central) interface fluxes in smooth flow, CRWENO5-Z rows at
// discontinuities. References: Lele, J. Comput. Phys. 103 (1992) 16, eq. (2.1.7) with alpha = 1/3 (sixth
// order), written in the conservative interface form
//   (1/3) h_{j-1/2} + h_{j+1/2} + (1/3) h_{j+3/2} = (29/36)(f_j + f_{j+1}) + (1/36)(f_{j-1} + f_{j+2});
// Wang & Huang, J. Comput. Phys. 177 (2002) 37 (ENO-Pade idea: replace Pade rows near discontinuities by
// ENO-type compact rows); hybrid switch as in Pirozzoli, J. Comput. Phys. 178 (2002) 81 and Ren, Liu & Zhang,
// J. Comput. Phys. 192 (2003) 365.
//
// Variant implemented (and why): a row-wise hybrid. Interface j+1/2 is a "shock row" when the Jameson-type
// sensor
//   phi_m = |q_{m+1} - 2 q_m + q_{m-1}| / (|q_{m+1}| + 2|q_m| + |q_{m-1}|),  q in {rho, p},
// exceeds -shock_threshold (default 0.02) for any m in j-1 .. j+2 (the cells the row's stencils touch). Shock
// rows are CRWENO5 rows (Ghosh & Baeder 2012) with WENO-Z weights (p = 2), applied upwind to the split fluxes
// f+ and f- in characteristic variables; all other rows are the Pade row, which is central, so f+ + f- = f
// and the smooth-flow scheme is the dissipation-free sixth-order Pade scheme. Sensor on rho and p catches
// shocks and contacts; it is O(dx^2) on smooth data (about 1e-3 for the density_wave at N = 20), so smooth
// flow keeps the sixth-order rows. CRWENO rows rather than Wang & Huang's original ENO-Pade stencils: they
// share the tridiagonal structure, need no stencil selection (nonlinear weights instead), and WENO-Z weights
// keep fifth order at critical points where the Jiang-Shu weights of the original would drop to third/fourth
// order. Boundary closure (non-periodic lines): the first and last interface of the line use the explicit
// sixth-order central formula (f_{j-2} - 8 f_{j-1} + 37 f_j + 37 f_{j+1} - 8 f_{j+2} + f_{j+3})/60 on ghost
// cells (shock rows: explicit WENO5-Z), so the closure is sixth (fifth) order given ghost values of that
// order.
#pragma once

#include "euler/row.hpp"

namespace suite::euler {

// Pade row at x_{j+1/2} from v[0..5] = f_{j-2} .. f_{j+3} (v[0], v[5] unused).
Row padeRow(const double* v);
// Explicit sixth-order central interface value (boundary closure), v[0..5] = f_{j-2} .. f_{j+3}.
Row central6Row(const double* v);
// Shock sensor for the row at x_{j+1/2}: rho[0..5], p[0..5] at cells j-2 .. j+3.
bool enoPadeShockRow(const double* rho, const double* p, double threshold);

} // namespace suite::euler
