// Fifth-order compact-reconstruction WENO (CRWENO5) rows: with Henrick-mapped weights the `crweno5` comparator,
// with WENO-Z weights the rows of `enopade6` at its supersonic faces. Reference: Ghosh & Baeder, SIAM J. Sci.
// Comput. 34 (2012) A1678, eqs. (13)-(17) (three third-order compact candidates, optimal weights 1/5, 1/2,
// 3/10); weights from the Jiang-Shu indicators on f_{j-2} .. f_{j+2}: WENO-Z (Borges et al. 2008) with p = 2, as
// in Ghosh & Baeder's CRWENO5-Z variant, or Jiang-Shu's mapped as Henrick, Aslam & Powers (J. Comput. Phys. 207
// (2005) 542), HyPar's default. The mapped weights keep the row the linear compact scheme to O(dx^6) on smooth
// data (2D vortex at 128^2: L1(rho) 2.0e-7 against 6.1e-7 with WENO-Z; docs/euler_nd.md). The row (omega =
// nonlinear weights):
//   (2w1+w2)/3 h_{j-1/2} + (w1+2w2+2w3)/3 h_{j+1/2} + w3/3 h_{j+3/2} = w1/6 f_{j-1} + (5w1+5w2+w3)/6 f_j +
//   (w2+5w3)/6 f_{j+1}
// is not diagonally dominant when w1 > 1/2; linalg::BlockTridiagSolver handles such rows (verified, LU
// fallback).
#pragma once

#include "euler/row.hpp"

namespace suite::euler {

// Left-biased CRWENO5-Z row at x_{j+1/2} from v[0..5] = f_{j-2} .. f_{j+3} (v[5] unused).
Row crweno5Row(const double* v);
// The same row with Henrick-mapped weights (the `crweno5` scheme's rows).
Row crweno5MappedRow(const double* v);
// The CRWENO5 row of candidate weights w[0..2] (summing to 1).
Row crweno5RowFromWeights(const double* v, const double w[3]);
// The same row with the optimal (linear) weights: the fifth-order upwind compact scheme.
Row compactUpwind5Row(const double* v);

} // namespace suite::euler
