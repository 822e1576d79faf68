// The arithmetic of the WENO-Z weights, the CRWENO5-Z row and the CRWENO-CU6 / ENO-Pade blend row, defined once,
// inline and generic in the number type T: double for the scalar row functions (weno5.cpp, crweno5.cpp,
// crweno_cu6.cpp), Lanes (four doubles, GCC vector extension) for the batched row kernels (compact_rows_batch.hpp).
// Both run the same IEEE operations in the same order on each stencil (no select becomes a branch: the vector
// ?: evaluates both arms), so the two give the same rows bitwise. Methods and references: weno5.hpp, crweno5.hpp,
// crweno_cu6.hpp.
#pragma once

#include "euler/row.hpp"
#include "euler/weno5.hpp"

#include <cmath>
#include <cstdint>

// Forced inline: the batched kernels keep their lanes in registers only when the whole row is inlined.
#define SUITE_ROW_INLINE inline __attribute__((always_inline))

namespace suite::euler::kernels {

using Lanes = double __attribute__((vector_size(32)));     // four stencils at once
using LaneBits = int64_t __attribute__((vector_size(32))); // their bit patterns / comparison masks

template <class T> struct RowOf { T a, b, c, r; };

constexpr double kCrweno5Optimal[3] = {0.2, 0.5, 0.3}; // CRWENO5's linear weights
constexpr double kCu6C = 30.0;                         // the CU6 weights' constant C (crweno_cu6.hpp: why 30)
constexpr double kCu6Optimal[4] = {0.1, 0.4, 0.4, 0.1}; // the weights of the Pade row

SUITE_ROW_INLINE double absOf(double x) {
  return std::abs(x);
}
SUITE_ROW_INLINE Lanes absOf(Lanes x) { // the sign bit cleared, as fabs
  const LaneBits mask = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};
  return (Lanes)((LaneBits)x & mask);
}

// Jiang-Shu smoothness indicators beta_0..2 on v[0..4] = f_{j-2} .. f_{j+2}.
template <class T> SUITE_ROW_INLINE void weno5Smoothness(const T* v, T beta[3]) {
  const T t0 = v[0] - 2.0 * v[1] + v[2], s0 = v[0] - 4.0 * v[1] + 3.0 * v[2];
  const T t1 = v[1] - 2.0 * v[2] + v[3], s1 = v[1] - v[3];
  const T t2 = v[2] - 2.0 * v[3] + v[4], s2 = 3.0 * v[2] - 4.0 * v[3] + v[4];
  beta[0] = 13.0 / 12.0 * t0 * t0 + 0.25 * s0 * s0;
  beta[1] = 13.0 / 12.0 * t1 * t1 + 0.25 * s1 * s1;
  beta[2] = 13.0 / 12.0 * t2 * t2 + 0.25 * s2 * s2;
}

// The weights' epsilon on v[0..4], relative to the stencil's mean square (weno5.hpp).
template <class T> SUITE_ROW_INLINE T weno5Epsilon(const T* v) {
  return kWenoEpsAbs +
         kWenoEpsRel * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3] + v[4] * v[4]) / 5.0;
}

// WENO-Z weights with exponent P (2: the CRWENO5 rows; 1: the upwind part of the ENO-Pade row) for the linear
// weights d[3] from the indicators beta of v.
template <int P = 2, class T>
SUITE_ROW_INLINE void wenoZWeightsFromBeta(const T* v, const T beta[3], const double d[3], T w[3]) {
  static_assert(P == 1 || P == 2, "WENO-Z exponent 1 or 2");
  const T tau = absOf(beta[0] - beta[2]);
  const T eps = weno5Epsilon(v);
  T sum = T{} + 0.0;
  for (int k = 0; k < 3; ++k) {
    const T q = tau / (beta[k] + eps);
    w[k] = d[k] * (1.0 + (P == 1 ? q : q * q));
    sum += w[k];
  }
  for (int k = 0; k < 3; ++k) w[k] /= sum;
}

// Henrick-mapped Jiang-Shu weights (Henrick, Aslam & Powers, J. Comput. Phys. 207 (2005) 542, eq. (8) on
// Jiang & Shu's alpha_k = d_k / (beta_k + eps)^2, the epsilon of wenoZWeightsFromBeta) for the linear weights d[3]
// from the indicators beta of v. The mapping g_k(w) = w (d_k + d_k^2 - 3 d_k w + w^2) / (d_k^2 + w (1 - 2 d_k))
// has g_k(d_k) = d_k and g_k' = g_k'' = 0 there: the weights meet d_k to O(dx^6) where the Jiang-Shu weights
// miss them by O(dx^2) or, at critical points, O(dx).
template <class T>
SUITE_ROW_INLINE void mappedWeightsFromBeta(const T* v, const T beta[3], const double d[3], T w[3]) {
  const T eps = weno5Epsilon(v);
  T a[3], sum = T{} + 0.0;
  for (int k = 0; k < 3; ++k) {
    const T e = beta[k] + eps;
    a[k] = d[k] / (e * e);
    sum += a[k];
  }
  T msum = T{} + 0.0;
  for (int k = 0; k < 3; ++k) {
    const T x = a[k] / sum;
    a[k] = x * (d[k] + d[k] * d[k] - 3.0 * d[k] * x + x * x) / (d[k] * d[k] + x * (1.0 - 2.0 * d[k]));
    msum += a[k];
  }
  for (int k = 0; k < 3; ++k) w[k] = a[k] / msum;
}

// The CRWENO5 row of candidate weights w[0..2].
template <class T> SUITE_ROW_INLINE RowOf<T> crweno5RowFromWeights(const T* v, const T w[3]) {
  return {(2.0 * w[0] + w[1]) / 3.0, (w[0] + 2.0 * w[1] + 2.0 * w[2]) / 3.0, w[2] / 3.0,
          (w[0] * v[1] + (5.0 * w[0] + 5.0 * w[1] + w[2]) * v[2] + (w[1] + 5.0 * w[2]) * v[3]) / 6.0};
}

// The CRWENO5-Z row of v[0..5].
template <class T> SUITE_ROW_INLINE RowOf<T> crweno5Row(const T* v) {
  T beta[3], w[3];
  weno5Smoothness(v, beta);
  wenoZWeightsFromBeta(v, beta, kCrweno5Optimal, w);
  return crweno5RowFromWeights(v, w);
}

// The CRWENO5 row of v[0..5] with Henrick-mapped weights (the `crweno5` scheme's rows).
template <class T> SUITE_ROW_INLINE RowOf<T> crweno5MappedRow(const T* v) {
  T beta[3], w[3];
  weno5Smoothness(v, beta);
  mappedWeightsFromBeta(v, beta, kCrweno5Optimal, w);
  return crweno5RowFromWeights(v, w);
}

// beta_6 of the whole six-point stencil (crweno_cu6.hpp).
template <class T> SUITE_ROW_INLINE T cu6Smoothness(const T* v) {
  const T a = v[0], b = v[1], c = v[2], d = v[3], e = v[4], f = v[5];
  const T s = 271779.0 * a * a +
              a * (-2380800.0 * b + 4086352.0 * c - 3462252.0 * d + 1458762.0 * e - 245620.0 * f) +
              b * (5653317.0 * b - 20427884.0 * c + 17905032.0 * d - 7727988.0 * e + 1325006.0 * f) +
              c * (19510972.0 * c - 35817664.0 * d + 15929912.0 * e - 2792660.0 * f) +
              d * (17195652.0 * d - 15880404.0 * e + 2863984.0 * f) + e * (3824847.0 * e - 1429976.0 * f) +
              139633.0 * f * f;
  return s / 120960.0;
}

// The CU6 weights w[0..3] from the indicators beta[0..2] of v (beta[3] is set to beta_6).
template <class T> SUITE_ROW_INLINE void cu6WeightsFromBeta(const T* v, T beta[4], T w[4]) {
  beta[3] = cu6Smoothness(v);
  const T tau = absOf(beta[3] - (beta[0] + 4.0 * beta[1] + beta[2]) / 6.0);
  T ms = T{} + 0.0;
  for (int m = 0; m < 6; ++m) ms += v[m] * v[m];
  const T eps = kWenoEpsAbs + kWenoEpsRel * ms / 6.0;
  T sum = T{} + 0.0;
  for (int k = 0; k < 4; ++k) {
    const T q = kCu6C + tau / (beta[k] + eps);
    w[k] = kCu6Optimal[k] * q * q;
    sum += w[k];
  }
  for (int k = 0; k < 4; ++k) w[k] /= sum;
}

// The CU6 row of weights w[0..3].
template <class T> SUITE_ROW_INLINE RowOf<T> cu6RowFromWeights(const T* v, const T w[4]) {
  return {(2.0 * w[0] + w[1]) / 3.0, (w[0] + 2.0 * (w[1] + w[2]) + w[3]) / 3.0, (w[2] + 2.0 * w[3]) / 3.0,
          (w[0] * v[1] + (5.0 * (w[0] + w[1]) + w[2]) * v[2] + (w[1] + 5.0 * (w[2] + w[3])) * v[3] +
           w[3] * v[4]) /
              6.0};
}

// The ENO-Pade row: theta CU6 + (1 - theta) CRWENO5-Z, theta = min(1, w_3 / d_3)^2 (crweno_cu6.hpp); at
// theta = 1 the CU6 row as it is. Both rows are computed and the result selected (std::min(1.0, r3) is
// r3 < 1 ? r3 : 1).
template <class T> SUITE_ROW_INLINE RowOf<T> enoPadeBlendRow(const T* v) {
  T beta[4], w[4], w5[3];
  weno5Smoothness(v, beta);
  cu6WeightsFromBeta(v, beta, w);
  const RowOf<T> cu6 = cu6RowFromWeights(v, w);
  const T one = T{} + 1.0, r3 = w[3] / kCu6Optimal[3], s = r3 < one ? r3 : one, theta = s * s;
  wenoZWeightsFromBeta<1>(v, beta, kCrweno5Optimal, w5); // the CRWENO5-Z row (p = 1) on the same indicators
  const RowOf<T> up = crweno5RowFromWeights(v, w5);
  const T u = 1.0 - theta;
  const RowOf<T> blend = {theta * cu6.a + u * up.a, theta * cu6.b + u * up.b, theta * cu6.c + u * up.c,
                          theta * cu6.r + u * up.r};
  const auto pure = theta == one;
  return {pure ? cu6.a : blend.a, pure ? cu6.b : blend.b, pure ? cu6.c : blend.c, pure ? cu6.r : blend.r};
}

SUITE_ROW_INLINE Row toRow(const RowOf<double>& r) {
  return {r.a, r.b, r.c, r.r};
}

} // namespace suite::euler::kernels
