// When a face's characteristic basis is too ill-conditioned for double precision, so that the line schemes
// (DirectionSweep, Weno5Line) treat that face component-wise.
//
// The Roe eigenvectors of a face (gas_nd.hpp, LineGas::roeInto) with sound speed c have left eigenvectors with
// entries (gamma - 1) / (2 c^2) and 1 / (2 c): as c -> 0 the right eigenvectors (1, u -+ c, H -+ u c) and
// (1, u, |u|^2 / 2) become parallel. The characteristic schemes project data of the grid's flux scale onto them:
// the fluxes of a stencil that reaches a hot region, the neighbouring faces' fluxes that a compact row couples
// (its block row R diag(a) L), the difference of the left- and right-biased compact solutions that the rf-char
// pick sees. With Phi the grid's largest momentum flux p + rho |u|^2 and alpha its largest |u| + c, those data
// are of order Phi (momentum) and Phi alpha (energy); their characteristic values carry a round-off of
// eps Phi alpha (gamma - 1) / (2 c^2), which R maps back to an error of order eps Phi alpha in the face's
// energy flux and eps Phi alpha / c^2 in its mass flux. Over one step (dt alpha / dx <= the CFL number) that
// changes the energy and the density of a cell next to the face by a relative
//     eps Phi / p                                 (up to factors of order one),
// p the cell's pressure (rho c^2 = gamma p). Where that exceeds sqrt(eps), i.e. where one of the face's two
// cells has p < sqrt(eps) Phi, more than half of double's digits of each step's update are lost to the basis:
// such a face is treated component-wise (its rows and its upwinding). A cell that far below the grid's
// scale is a cold or near-vacuum gas (ahead of a strong shock, in a vacuum or near-vacuum region, a hypersonic
// cold jet), where the characteristic decomposition buys little.
// Measured (docs/euler_extremes.md): on `pressure_1e10` (p = 1 against 1e-10) with every face characteristic,
// one step already puts density changes of 1e-1 7-25 cells ahead of the shock into the gas at rest, O(1) noise
// by t = 0.15, and the result depends on round-off (the line solve, the rank count); with this test none, and
// the same result at 1, 2 and 3 ranks. Riemann problems whose pressures lie within 1e7 of each other (Sod,
// Lax, Toro's 1-5, Mach 100) have no such face.
// Reference: Higham, Accuracy and Stability of Numerical Algorithms (2002), ch. 7 (conditioning of a linear
// transform: relative error ~ eps times the condition number).
#pragma once

#include <cfloat>

namespace suite::euler {

// sqrt(DBL_EPSILON): the relative round-off of a cell's update above which its faces' characteristic bases
// are not used.
constexpr double kCharacteristicLoss = 1.4901161193847656e-08;

// Whether a face whose cells' smaller pressure is p is treated component-wise on a grid whose largest momentum
// flux p + rho |u|^2 is flux_scale (see above). p <= 0 gives true; NaN gives false (the run stops on the NaN
// elsewhere).
inline bool characteristicIllConditioned(double flux_scale, double p) {
  return DBL_EPSILON * flux_scale > kCharacteristicLoss * p;
}

} // namespace suite::euler
