// CRWENO5 compact rows (Ghosh & Baeder 2012, eqs. (13)-(17)) with WENO-Z weights (Borges et al. 2008) or
// Henrick-mapped weights (Henrick, Aslam & Powers 2005).
#include "euler/crweno5.hpp"

#include "euler/compact_row_kernels.hpp"

namespace suite::euler {

Row crweno5RowFromWeights(const double* v, const double w[3]) {
  return kernels::toRow(kernels::crweno5RowFromWeights(v, w));
}

Row crweno5Row(const double* v) {
  return kernels::toRow(kernels::crweno5Row(v));
}

Row crweno5MappedRow(const double* v) {
  return kernels::toRow(kernels::crweno5MappedRow(v));
}
Row compactUpwind5Row(const double* v) {
  const double* w = kernels::kCrweno5Optimal;
  return kernels::toRow(kernels::crweno5RowFromWeights(v, w));
}

} // namespace suite::euler
