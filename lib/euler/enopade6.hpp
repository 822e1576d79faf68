// ENO-Pade 6: sixth-order Pade (compact central) interface fluxes in smooth flow, central-upwind compact WENO
// rows on lines with discontinuities. References: Lele, J. Comput. Phys. 103 (1992) 16, eq. (2.1.7) with alpha = 1/3 (sixth
// order), written in the conservative interface form
//   (1/3) h_{j-1/2} + h_{j+1/2} + (1/3) h_{j+3/2} = (29/36)(f_j + f_{j+1}) + (1/36)(f_{j-1} + f_{j+2});
// Wang & Huang, J. Comput. Phys. 177 (2002) 37 (ENO-Pade idea: replace Pade rows near discontinuities by
// ENO-type compact rows); hybrid switch as in Pirozzoli, J. Comput. Phys. 178 (2002) 81 and Ren, Liu & Zhang,
// J. Comput. Phys. 192 (2003) 365; Hu, Wang & Adams, J. Comput. Phys. 229 (2010) 8952 (central-upwind WENO).
//
// Variant implemented (and why): a line-wise hybrid. A line (a row of cells along the sweep direction, over
// all its ranks) where the sensor below finds no shock row is a Pade line: central, so f+ + f- = f, the
// smooth-flow scheme is the dissipation-free sixth-order Pade scheme and its solve is one scalar tridiagonal
// system per component. A line with a shock row anywhere gets the ENO-Pade row (crweno_cu6.hpp) on every
// interior row, characteristic-wise and upwinded per field by the sign of its Roe speed (rf-char,
// rf_char.hpp): a central-upwind compact WENO row whose smooth limit is this Pade row, blended into the
// CRWENO5-Z row (Ghosh & Baeder 2012) where its downwind candidate is rejected; at a face where rf-char
// upwinds every field the same way (supersonic), the CRWENO5-Z row (crweno5Row; DirectionSweep::supersonicFace:
// every wave runs downstream there, and the central part kept the near-vacuum rarefactions' start-up errors).
// Why not a row-wise switch (Pade rows, CRWENO5-Z rows on the flagged rows only): the Pade rows
// between and next to the flagged rows carry the grid-scale waves that the shocks and contacts shed, undamped
// and at spurious group velocities (upstream into a supersonic inflow on the Mach 100 case), and the switch
// between a central and an upwind row is abrupt; with every row of a shocked line nonlinear, the weights damp
// those waves where they arise and reach the Pade weights where the data are smooth. Measured (HyPar's Sod /
// Lax settings, docs/euler_extremes.md): L1(rho) Sod N = 200 / 800 1.765e-3 / 4.92e-4 (row-wise switch
// 2.401e-3 / 7.16e-4), Lax 6.26e-3 / 1.48e-3 (row-wise switch 8.74e-3 / 2.07e-3), all 5-19% below HyPar's
// CRWENO5; below this suite's crweno5 (mapped weights) on 14 of the 16 1D battery cases (ratios 0.83-0.99;
// Toro 123 1.037, contact_1e6 1.014).
// Boundary closure (non-periodic lines): the first and last interface of the line use the explicit
// sixth-order central formula (f_{j-2} - 8 f_{j-1} + 37 f_j + 37 f_{j+1} - 8 f_{j+2} + f_{j+3})/60 on ghost
// cells (shock rows: explicit WENO5-Z), so the closure is sixth (fifth) order given ghost values of that
// order.
//
// Shock sensor (resolution-aware; it picks the lines above and gives the flag field). Interface j+1/2 is a
// shock row when, for q = rho or q = p on the row's
// cells j-2 .. j+3, both tests fire:
//  - amplitude (Jameson, Schmidt & Turkel, AIAA 81-1259, 1981): some cell m in j-1 .. j+2 has
//      phi_m = |q_{m+1} - 2 q_m + q_{m-1}| / (|q_{m+1}| + 2|q_m| + |q_{m-1}|) > -shock_threshold (0.02);
//  - resolution: one of the row's three 4-cell windows (cells i-1 .. i+2, i = j-1, j, j+1) has
//      R = |D3 q| / (|D1 q|_{i-1/2} + |D1 q|_{i+1/2} + |D1 q|_{i+3/2}) > theta,
//    D1, D3 the undivided first and third differences of the window. The ratio of undivided differences of
//    two orders reads the scale of the data: D3 / D1 = O((k h)^2) on data resolved at wavenumber k, O(1) at
//    a jump (Harten, Engquist, Osher & Chakravarthy, J. Comput. Phys. 71 (1987) 231, sec. 3: undivided
//    differences grow with the order across a discontinuity and decay on smooth data; Harten, Comm. Pure
//    Appl. Math. 48 (1995) 1305: the same ratio as a multiresolution smoothness measure). theta is
//    calibrated on a sampled sine: over all phases R peaks at 4 sin^2(k h / 2) / (1 + 2 cos(k h)), so with
//    -shock_ppw P (default 8: theta = 0.243) theta = that peak at k h = 2 pi / P, and data resolved with more
//    than P points per wavelength are never shock rows (the Pade core's phase error at 8 points per
//    wavelength is 1e-4). A step gives R = 1 to 2 in every window that holds it, so the five rows whose
//    stencils hold a jump are shock rows. Why 8 and not 6 (theta = 0.5): the contact, once CRWENO rows have
//    smeared it over 4-5 cells, has R = 0.3-0.5; handed to the Pade rows it sheds grid-scale waves that the
//    Pade scheme carries at spurious group velocities to the outflow boundary, which reflects them as a smooth
//    acoustic pulse (Sod N = 800: L1(rho) 1.14e-3 at P = 6 against 7.2e-4 at P = 8 and 6.8e-4 with the
//    amplitude test alone). The 32^2 vortex peaks at R = 0.17.
// The amplitude test alone is the sensor of -shock_ppw 0. Jameson's phi is O(h^2 q''/q): alone it
// flags any smooth feature with a few cells across (the isentropic vortex at 32^2: ~3% of the rows over a
// run, a 9x larger L1 error than the Pade core), while the resolution test alone would flag round-off and
// the low-amplitude grid-scale ripples Pade rows leave in constant states (Sod's plateaus: relative
// amplitude 1e-3); together they flag non-negligible jumps only. Measured at the default settings: no shock
// rows on the isentropic vortex at 32^2 and 64^2 or the density_wave at N = 20 (every step), on Sod and
// Shu-Osher only rows within a few cells of the shocks and contacts (tests/euler).
#pragma once

#include "euler/row.hpp"

#include <vector>

namespace suite::euler {

// Pade row at x_{j+1/2} from v[0..5] = f_{j-2} .. f_{j+3} (v[0], v[5] unused).
Row padeRow(const double* v);
// Explicit sixth-order central interface value (boundary closure), v[0..5] = f_{j-2} .. f_{j+3}.
Row central6Row(const double* v);
// The resolution threshold theta of -shock_ppw P (see above); P = 0: 0, the resolution test always passes.
double shockResolutionRatio(double ppw);
// Shock sensor for the row at x_{j+1/2}: rho[0..5], p[0..5] at cells j-2 .. j+3; threshold: the amplitude
// test's, theta: the resolution test's. NaN data make a shock row.
bool enoPadeShockRow(const double* rho, const double* p, double threshold, double theta);
// enoPadeShockRow for the rows 0 .. nrow-1 of a line (row k reads rho[k .. k+5], p[k .. k+5]) into shock[k]
// (1: shock row), each cell's and window's test made once; work: scratch. The same rows as row by row.
void enoPadeShockRows(const double* rho, const double* p, int nrow, double threshold, double theta,
                      std::vector<char>* work, char* shock);

} // namespace suite::euler
