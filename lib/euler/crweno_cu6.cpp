// CRWENO-CU6 and ENO-Pade blend rows (Hu, Wang & Adams 2010; Ghosh & Baeder 2012): see crweno_cu6.hpp; the
// arithmetic is in compact_row_kernels.hpp (shared with the batched rows).
#include "euler/crweno_cu6.hpp"

#include "euler/compact_row_kernels.hpp"

namespace suite::euler {

double cu6Smoothness(const double* v) {
  return kernels::cu6Smoothness(v);
}

void cu6Weights(const double* v, double w[4]) {
  double beta[4];
  kernels::weno5Smoothness(v, beta);
  kernels::cu6WeightsFromBeta(v, beta, w);
}

Row cu6RowFromWeights(const double* v, const double w[4]) {
  return kernels::toRow(kernels::cu6RowFromWeights(v, w));
}

Row crwenoCu6Row(const double* v) {
  double w[4];
  cu6Weights(v, w);
  return kernels::toRow(kernels::cu6RowFromWeights(v, w));
}

Row enoPadeBlendRow(const double* v) {
  return kernels::toRow(kernels::enoPadeBlendRow(v));
}

} // namespace suite::euler
