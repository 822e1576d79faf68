// CRWENO-CU6 and ENO-Pade blend rows (Hu, Wang & Adams 2010; Ghosh & Baeder 2012): see crweno_cu6.hpp.
#include "euler/crweno_cu6.hpp"

#include "euler/crweno5.hpp"
#include "euler/weno5.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

namespace {
constexpr double kC = 30.0;                            // the weights' constant C (header: why 30)
constexpr double kOptimal[4] = {0.1, 0.4, 0.4, 0.1};   // the weights of the Pade row
constexpr double kCrweno5Optimal[3] = {0.2, 0.5, 0.3}; // CRWENO5's (crweno5.cpp)
} // namespace

double cu6Smoothness(const double* v) {
  const double a = v[0], b = v[1], c = v[2], d = v[3], e = v[4], f = v[5];
  const double s = 271779.0 * a * a +
                   a * (-2380800.0 * b + 4086352.0 * c - 3462252.0 * d + 1458762.0 * e - 245620.0 * f) +
                   b * (5653317.0 * b - 20427884.0 * c + 17905032.0 * d - 7727988.0 * e + 1325006.0 * f) +
                   c * (19510972.0 * c - 35817664.0 * d + 15929912.0 * e - 2792660.0 * f) +
                   d * (17195652.0 * d - 15880404.0 * e + 2863984.0 * f) +
                   e * (3824847.0 * e - 1429976.0 * f) + 139633.0 * f * f;
  return s / 120960.0;
}

static void cu6WeightsFromBeta(const double* v, double beta[4], double w[4]);

void cu6Weights(const double* v, double w[4]) {
  double beta[4];
  weno5Smoothness(v, beta);
  cu6WeightsFromBeta(v, beta, w);
}

// beta[0..2]: the Jiang-Shu indicators of v (weno5Smoothness); beta[3] is set here.
static void cu6WeightsFromBeta(const double* v, double beta[4], double w[4]) {
  beta[3] = cu6Smoothness(v);
  const double tau = std::abs(beta[3] - (beta[0] + 4.0 * beta[1] + beta[2]) / 6.0);
  double ms = 0.0;
  for (int m = 0; m < 6; ++m) ms += v[m] * v[m];
  const double eps = kWenoEpsAbs + kWenoEpsRel * ms / 6.0;
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double q = kC + tau / (beta[k] + eps);
    w[k] = kOptimal[k] * q * q;
    sum += w[k];
  }
  for (int k = 0; k < 4; ++k) w[k] /= sum;
}

Row cu6RowFromWeights(const double* v, const double w[4]) {
  return {(2.0 * w[0] + w[1]) / 3.0, (w[0] + 2.0 * (w[1] + w[2]) + w[3]) / 3.0, (w[2] + 2.0 * w[3]) / 3.0,
          (w[0] * v[1] + (5.0 * (w[0] + w[1]) + w[2]) * v[2] + (w[1] + 5.0 * (w[2] + w[3])) * v[3] +
           w[3] * v[4]) /
              6.0};
}

Row crwenoCu6Row(const double* v) {
  double w[4];
  cu6Weights(v, w);
  return cu6RowFromWeights(v, w);
}

Row enoPadeBlendRow(const double* v) {
  double beta[4], w[4], w5[3];
  weno5Smoothness(v, beta);
  cu6WeightsFromBeta(v, beta, w);
  const Row cu6 = cu6RowFromWeights(v, w);
  const double s = std::min(1.0, w[3] / kOptimal[3]), theta = s * s;
  if (theta == 1.0) return cu6;
  wenoZWeightsFromBeta(v, beta, kCrweno5Optimal, w5); // the CRWENO5-Z row on the same indicators
  const Row up = crweno5RowFromWeights(v, w5);
  return {theta * cu6.a + (1.0 - theta) * up.a, theta * cu6.b + (1.0 - theta) * up.b,
          theta * cu6.c + (1.0 - theta) * up.c, theta * cu6.r + (1.0 - theta) * up.r};
}

} // namespace suite::euler
