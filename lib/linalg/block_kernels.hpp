// Small dense kernels of the substructured block-tridiagonal line solvers (substructured_block_line.cpp,
// substructured_block_lines.cpp): LU with partial pivoting of one bs x bs block, block products with
// compile-time sizes (unrolled by the compiler), and the subnormal flush of spike columns. Internal header.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

namespace suite::linalg::detail {

// LU with partial pivoting of one bs x bs block; solve() applies its inverse to a bs x ncols row-major block.
template <int BS> struct SmallLU {
  double lu[BS * BS];
  double inv[BS]; // 1 / U_kk, for solveFast
  int piv[BS];

  // False when a pivot is below 1e-14 times the largest entry of M (or not finite).
  bool factor(const double* M) {
    double scale = 0.0;
    for (int e = 0; e < BS * BS; ++e) {
      lu[e] = M[e];
      scale = std::max(scale, std::fabs(M[e]));
    }
    for (int k = 0; k < BS; ++k) {
      int p = k;
      for (int i = k + 1; i < BS; ++i)
        if (std::fabs(lu[i * BS + k]) > std::fabs(lu[p * BS + k])) p = i;
      piv[k] = p;
      if (!(std::fabs(lu[p * BS + k]) > 1e-14 * scale)) return false; // also catches NaN
      if (p != k)
        for (int j = 0; j < BS; ++j) std::swap(lu[k * BS + j], lu[p * BS + j]);
      for (int i = k + 1; i < BS; ++i) {
        const double l = lu[i * BS + k] /= lu[k * BS + k];
        for (int j = k + 1; j < BS; ++j) lu[i * BS + j] -= l * lu[k * BS + j];
      }
    }
    for (int k = 0; k < BS; ++k) inv[k] = 1.0 / lu[k * BS + k];
    return true;
  }
  // Applies the inverse to a bs x ncols block with row stride `stride`; NC > 0 fixes the column count at
  // compile time (unrolled kernels), NC = 0 takes ncols.
  template <int NC = 0> void solve(double* X, int stride, int ncols = NC) const {
    const int nc = NC > 0 ? NC : ncols;
    if constexpr (BS > 1) { // (BS = 1: no row exchange)
      for (int k = 0; k < BS; ++k)
        if (piv[k] != k)
          for (int c = 0; c < nc; ++c) std::swap(X[k * stride + c], X[piv[k] * stride + c]);
    }
    for (int i = 1; i < BS; ++i)
      for (int k = 0; k < i; ++k)
        for (int c = 0; c < nc; ++c) X[i * stride + c] -= lu[i * BS + k] * X[k * stride + c];
    for (int i = BS - 1; i >= 0; --i) {
      for (int k = i + 1; k < BS; ++k)
        for (int c = 0; c < nc; ++c) X[i * stride + c] -= lu[i * BS + k] * X[k * stride + c];
      for (int c = 0; c < nc; ++c) X[i * stride + c] /= lu[i * BS + i];
    }
  }
  // As solve(), multiplying by the stored reciprocals of the pivots instead of dividing (faster; results
  // differ from solve() by round-off).
  template <int NC = 0> void solveFast(double* X, int stride, int ncols = NC) const {
    const int nc = NC > 0 ? NC : ncols;
    if constexpr (BS > 1) {
      for (int k = 0; k < BS; ++k)
        if (piv[k] != k)
          for (int c = 0; c < nc; ++c) std::swap(X[k * stride + c], X[piv[k] * stride + c]);
    }
    for (int i = 1; i < BS; ++i)
      for (int k = 0; k < i; ++k)
        for (int c = 0; c < nc; ++c) X[i * stride + c] -= lu[i * BS + k] * X[k * stride + c];
    for (int i = BS - 1; i >= 0; --i) {
      for (int k = i + 1; k < BS; ++k)
        for (int c = 0; c < nc; ++c) X[i * stride + c] -= lu[i * BS + k] * X[k * stride + c];
      for (int c = 0; c < nc; ++c) X[i * stride + c] *= inv[i];
    }
  }
};

// Y (bs x ncols) -= M (bs x bs) * X (bs x ncols), rows of X and Y `stride` apart; NC > 0 fixes ncols.
template <int BS, int NC = 0>
inline void subtractProduct(const double* M, const double* X, int stride, double* Y, int ncols = NC) {
  const int nc = NC > 0 ? NC : ncols;
  for (int a = 0; a < BS; ++a)
    for (int b = 0; b < BS; ++b) {
      const double v = M[a * BS + b];
      for (int c = 0; c < nc; ++c) Y[a * stride + c] -= v * X[b * stride + c];
    }
}

// Y (bs x ncols) += M (bs x bs) * X (bs x ncols), rows of X and Y `stride` apart; NC > 0 fixes ncols.
template <int BS, int NC = 0>
inline void addProduct(const double* M, const double* X, int stride, double* Y, int ncols = NC) {
  const int nc = NC > 0 ? NC : ncols;
  for (int a = 0; a < BS; ++a)
    for (int b = 0; b < BS; ++b) {
      const double v = M[a * BS + b];
      for (int c = 0; c < nc; ++c) Y[a * stride + c] += v * X[b * stride + c];
    }
}

// The spike columns P and Q decay geometrically away from the row that drives them (exponentially, for a
// diagonally dominant line); left alone they underflow through subnormal numbers, whose arithmetic is ~100x
// slower (measured: periodic CRWENO5 lines 8x slower than open ones). Entries below 1e-200 of these O(1)
// columns are set to exactly zero; that changes x = Y + P xl + Q xr by less than 1e-200 |x|.
template <int BS> inline void flushSpikes(double* row, int first, int last, int stride) {
  for (int a = 0; a < BS; ++a)
    for (int c = first; c < last; ++c)
      if (std::fabs(row[a * stride + c]) < 1e-200) row[a * stride + c] = 0.0;
}

} // namespace suite::linalg::detail
