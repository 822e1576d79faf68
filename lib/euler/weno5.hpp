// Fifth-order WENO-Z interface value (explicit, non-compact), the `weno5` comparator.
// Reference: Jiang & Shu, J. Comput. Phys. 126 (1996) 202, eqs. (2.10)-(2.17) for candidates and smoothness
// indicators; Borges, Carmona, Costa & Don, J. Comput. Phys. 227 (2008) 3191, eq. (28) for the Z weights; p =
// 2 as in Don & Borges, J. Comput. Phys. 250 (2013) 347, which keeps fifth order at first-order critical
// points; epsilon = 1e-6 times the mean square of the stencil values (scale-invariant form of Ghosh &
// Baeder's 1e-6).
#pragma once

#include "euler/row.hpp"

namespace suite::euler {

// Smoothness indicators beta_0..2 of Jiang & Shu on v[0..4] = f_{j-2} .. f_{j+2}.
void weno5Smoothness(const double* v, double beta[3]);
// WENO-Z nonlinear weights for linear weights d[3], from v[0..4] = f_{j-2} .. f_{j+2}.
void wenoZWeights(const double* v, const double d[3], double w[3]);
// Left-biased fifth-order WENO-Z value f_{j+1/2} from v[0..4] = f_{j-2} .. f_{j+2}.
double weno5Value(const double* v);
// Explicit row (a = c = 0, b = 1) from v[0..5] = f_{j-2} .. f_{j+3} (v[5] unused).
Row weno5Row(const double* v);

} // namespace suite::euler
