// Fifth-order WENO-Z reconstruction (Jiang & Shu 1996; Borges et al. 2008; Don & Borges 2013, p = 2).
#include "euler/weno5.hpp"

#include "euler/compact_row_kernels.hpp"

#include <cmath>

namespace suite::euler {

void weno5Smoothness(const double* v, double beta[3]) {
  kernels::weno5Smoothness(v, beta);
}

void wenoZWeights(const double* v, const double d[3], double w[3]) {
  double beta[3];
  kernels::weno5Smoothness(v, beta);
  kernels::wenoZWeightsFromBeta(v, beta, d, w);
}

void wenoZWeightsFromBeta(const double* v, const double beta[3], const double d[3], double w[3]) {
  kernels::wenoZWeightsFromBeta(v, beta, d, w);
}

double weno5Value(const double* v) {
  return weno5ZValue(v[0], v[1], v[2], v[3], v[4]);
}

Row weno5Row(const double* v) {
  return {0.0, 1.0, 0.0, weno5Value(v)};
}

} // namespace suite::euler
