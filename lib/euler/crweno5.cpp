// CRWENO5-Z compact rows (Ghosh & Baeder 2012, eqs. (13)-(17); WENO-Z weights, Borges et al. 2008).
#include "euler/crweno5.hpp"

#include "euler/weno5.hpp"

namespace suite::euler {

Row crweno5RowFromWeights(const double* v, const double w[3]) {
  return {(2.0 * w[0] + w[1]) / 3.0, (w[0] + 2.0 * w[1] + 2.0 * w[2]) / 3.0, w[2] / 3.0,
          (w[0] * v[1] + (5.0 * w[0] + 5.0 * w[1] + w[2]) * v[2] + (w[1] + 5.0 * w[2]) * v[3]) / 6.0};
}

namespace {
const double kOptimal[3] = {0.2, 0.5, 0.3};
} // namespace

Row crweno5Row(const double* v) {
  double w[3];
  wenoZWeights(v, kOptimal, w);
  return crweno5RowFromWeights(v, w);
}

Row compactUpwind5Row(const double* v) {
  return crweno5RowFromWeights(v, kOptimal);
}

} // namespace suite::euler
