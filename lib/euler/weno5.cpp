// Fifth-order WENO-Z reconstruction (Jiang & Shu 1996; Borges et al. 2008; Don & Borges 2013, p = 2).
#include "euler/weno5.hpp"

#include <cmath>

namespace suite::euler {

void weno5Smoothness(const double* v, double beta[3]) {
  const double t0 = v[0] - 2.0 * v[1] + v[2], s0 = v[0] - 4.0 * v[1] + 3.0 * v[2];
  const double t1 = v[1] - 2.0 * v[2] + v[3], s1 = v[1] - v[3];
  const double t2 = v[2] - 2.0 * v[3] + v[4], s2 = 3.0 * v[2] - 4.0 * v[3] + v[4];
  beta[0] = 13.0 / 12.0 * t0 * t0 + 0.25 * s0 * s0;
  beta[1] = 13.0 / 12.0 * t1 * t1 + 0.25 * s1 * s1;
  beta[2] = 13.0 / 12.0 * t2 * t2 + 0.25 * s2 * s2;
}

void wenoZWeights(const double* v, const double d[3], double w[3]) {
  double beta[3];
  weno5Smoothness(v, beta);
  wenoZWeightsFromBeta(v, beta, d, w);
}

void wenoZWeightsFromBeta(const double* v, const double beta[3], const double d[3], double w[3]) {
  const double tau = std::abs(beta[0] - beta[2]);
  const double kEps =
      kWenoEpsAbs + kWenoEpsRel * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3] + v[4] * v[4]) / 5.0;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double q = tau / (beta[k] + kEps);
    w[k] = d[k] * (1.0 + q * q);
    sum += w[k];
  }
  for (int k = 0; k < 3; ++k) w[k] /= sum;
}

double weno5Value(const double* v) {
  return weno5ZValue(v[0], v[1], v[2], v[3], v[4]);
}

Row weno5Row(const double* v) {
  return {0.0, 1.0, 0.0, weno5Value(v)};
}

} // namespace suite::euler
