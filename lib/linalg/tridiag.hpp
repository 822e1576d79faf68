// Tridiagonal and block-tridiagonal solves: Thomas algorithm, cyclic (periodic) systems by Sherman-Morrison /
// Woodbury, and a verified block Thomas with a banded-LU-with-partial-pivoting fallback (LAPACK dgbtrf).
// References: Thomas (1949); Sherman & Morrison (1950); Golub & Van Loan, Matrix Computations, 4th
// ed., 4.3, 2.1.4.
#pragma once

#include <vector>

namespace suite::linalg {

// Scalar tridiagonal system a_i x_{i-1} + b_i x_i + c_i x_{i+1} = d_i, i = 0..n-1 (a_0, c_{n-1} ignored).
// Thomas algorithm without pivoting; d is overwritten by x. Returns false on a zero (or tiny) pivot.
bool thomas(int n, const double* a, const double* b, const double* c, double* d);

// Periodic (cyclic) scalar system: a_0 couples x_{n-1}, c_{n-1} couples x_0. Sherman-Morrison on top of
// Thomas. Returns false on a tiny pivot. n >= 3.
bool cyclicThomas(int n, const double* a, const double* b, const double* c, double* d);

// Block-tridiagonal system with bs x bs blocks (bs <= 3), nb block rows, row-major blocks:
//   A_i x_{i-1} + B_i x_i + C_i x_{i+1} = d_i,   periodic: A_0 multiplies x_{nb-1}, C_{nb-1} multiplies x_0.
// Solve strategy, exact for any nonsingular system:
//   1. block Thomas (no pivoting) for the non-periodic part, Woodbury (rank 2 bs) for the periodic corners;
//   2. the result is verified by its residual; if a pivot block is near-singular or the relative residual
//   exceeds
//      tol, the non-periodic part is refactored by banded LU with partial pivoting (dgbtrf, kl = ku = 2 bs -
//      1), which handles rows that are not diagonally dominant (e.g. CRWENO5 rows with omega_1 > 1/2).
// Throws std::runtime_error if the system is numerically singular.
class BlockTridiagSolver {
public:
  struct Stats {
    long long solves = 0, lu_fallbacks = 0;
  };
  // A, B, C: nb*bs*bs each; d: nb*bs, overwritten by the solution.
  void solve(int nb, int bs, const double* A, const double* B, const double* C, double* d, bool periodic);
  const Stats& stats() const { return stats_; }
  double tolerance = 1e-10;

private:
  // Banded LU with partial pivoting of the non-periodic part (fallback).
  void factorBand(int nb, int bs, const double* A, const double* B, const double* C);
  void applyInverse(int nb, int bs, const double* A, int nrhs, double* X) const; // X: nrhs columns of nb*bs
  void solveWithCurrentFactor(int nb, int bs, const double* A, const double* C, double* d,
                              bool periodic) const;

  std::vector<double> cp_, rhs_; // block Thomas work (modified upper blocks), saved right-hand side
  std::vector<double> band_;     // LAPACK band storage
  std::vector<int> ipiv_;
  Stats stats_;
};

// Relative residual max|Mx - d| / max(max|d|, tiny) of a (periodic or not) block-tridiagonal system.
double blockTridiagResidual(int nb, int bs, const double* A, const double* B, const double* C,
                            const double* x, const double* d, bool periodic);

} // namespace suite::linalg
