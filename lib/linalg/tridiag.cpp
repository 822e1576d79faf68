// Tridiagonal and block-tridiagonal solves (Thomas, Sherman-Morrison/Woodbury, banded LU fallback).
// References: Golub & Van Loan, Matrix Computations, 4th ed., 4.3 (banded LU), 2.1.4
// (Sherman-Morrison-Woodbury).
#include "linalg/tridiag.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab, int* ipiv,
             int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs, const double* ab,
             const int* ldab, const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_len);
}

namespace suite::linalg {

namespace {
using SmallMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, 3, 3>;
using SmallVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
using MapMat = Eigen::Map<const SmallMat>;
constexpr double kTinyPivot = 1e-300;
} // namespace

bool thomas(int n, const double* a, const double* b, const double* c, double* d) {
  if (n <= 0) return true;
  std::vector<double> cp(n);
  double piv = b[0];
  if (std::abs(piv) < kTinyPivot) return false;
  cp[0] = c[0] / piv;
  d[0] /= piv;
  for (int i = 1; i < n; ++i) {
    piv = b[i] - a[i] * cp[i - 1];
    if (std::abs(piv) < kTinyPivot * (std::abs(b[i]) + std::abs(a[i]) + 1.0)) return false;
    cp[i] = (i < n - 1 ? c[i] : 0.0) / piv;
    d[i] = (d[i] - a[i] * d[i - 1]) / piv;
  }
  for (int i = n - 2; i >= 0; --i) d[i] -= cp[i] * d[i + 1];
  return true;
}

bool cyclicThomas(int n, const double* a, const double* b, const double* c, double* d) {
  if (n < 3) return false;
  // M = T + u v^T with u = (gamma, 0..0, c_{n-1}), v = (1, 0..0, a_0/gamma); T has b_0 - gamma, b_{n-1} - a_0
  // c_{n-1}/gamma.
  const double gamma = -b[0];
  std::vector<double> bb(b, b + n), u(n, 0.0);
  bb[0] = b[0] - gamma;
  bb[n - 1] = b[n - 1] - c[n - 1] * a[0] / gamma;
  u[0] = gamma;
  u[n - 1] = c[n - 1];
  if (!thomas(n, a, bb.data(), c, d)) return false;
  if (!thomas(n, a, bb.data(), c, u.data())) return false;
  const double vy = d[0] + a[0] / gamma * d[n - 1];
  const double vz = u[0] + a[0] / gamma * u[n - 1];
  if (std::abs(1.0 + vz) < kTinyPivot) return false;
  const double f = vy / (1.0 + vz);
  for (int i = 0; i < n; ++i) d[i] -= f * u[i];
  return true;
}

double blockTridiagResidual(int nb, int bs, const double* A, const double* B, const double* C,
                            const double* x, const double* d, bool periodic) {
  double rmax = 0.0, dmax = 0.0;
  const int bb = bs * bs;
  for (int i = 0; i < nb; ++i) {
    const int im = i > 0 ? i - 1 : (periodic ? nb - 1 : -1);
    const int ip = i < nb - 1 ? i + 1 : (periodic ? 0 : -1);
    for (int p = 0; p < bs; ++p) {
      double r = -d[i * bs + p];
      for (int q = 0; q < bs; ++q) {
        r += B[i * bb + p * bs + q] * x[i * bs + q];
        if (im >= 0) r += A[i * bb + p * bs + q] * x[im * bs + q];
        if (ip >= 0) r += C[i * bb + p * bs + q] * x[ip * bs + q];
      }
      rmax = std::max(rmax, std::abs(r));
      dmax = std::max(dmax, std::abs(d[i * bs + p]));
    }
  }
  return rmax / std::max(dmax, 1e-300);
}

namespace {
// Block Thomas with fixed-size blocks, factorisation and forward sweep fused, K right-hand-side columns per
// block. Returns false on a near-singular pivot block (1-norm condition estimate > 1e12).
template <int BS, int K>
bool blockThomasFixed(int nb, const double* A, const double* B, const double* C, double* X,
                      std::vector<double>* work) {
  using M = Eigen::Matrix<double, BS, BS, Eigen::RowMajor>;
  using R = Eigen::Matrix<double, BS, K, (K == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;
  constexpr int bb = BS * BS;
  work->resize(static_cast<std::size_t>(nb) * bb);
  M* cp = reinterpret_cast<M*>(work->data());
  R* x = reinterpret_cast<R*>(X);
  for (int i = 0; i < nb; ++i) {
    const Eigen::Map<const M> Ai(A + i * bb), Bi(B + i * bb), Ci(C + i * bb);
    M D = Bi;
    R rhs = x[i];
    if (i > 0) {
      D.noalias() -= Ai * cp[i - 1];
      rhs.noalias() -= Ai * x[i - 1];
    }
    M Dinv;
    if constexpr (BS == 1) {
      if (std::abs(D(0, 0)) < kTinyPivot) return false;
      Dinv(0, 0) = 1.0 / D(0, 0);
    } else {
      bool invertible = false;
      double det = 0;
      D.computeInverseAndDetWithCheck(Dinv, det, invertible, 0.0);
      if (!invertible) return false;
    }
    const double cond = D.cwiseAbs().rowwise().sum().maxCoeff() * Dinv.cwiseAbs().rowwise().sum().maxCoeff();
    if (!(cond < 1e12)) return false;
    if (i < nb - 1) cp[i].noalias() = Dinv * Ci;
    x[i].noalias() = Dinv * rhs;
  }
  for (int i = nb - 2; i >= 0; --i) x[i].noalias() -= cp[i] * x[i + 1];
  return true;
}

// Solves the (periodic) system by block Thomas, Woodbury for the corners. d overwritten. false: pivot
// breakdown.
template <int BS>
bool blockThomasSolve(int nb, const double* A, const double* B, const double* C, double* d, bool periodic,
                      std::vector<double>* work) {
  if (!periodic) return blockThomasFixed<BS, 1>(nb, A, B, C, d, work);
  constexpr int K = 1 + 2 * BS, bb = BS * BS;
  std::vector<double> X(static_cast<std::size_t>(nb) * BS * K,
                        0.0); // per block: BS rows x K columns, row-major
  for (int i = 0; i < nb; ++i)
    for (int p = 0; p < BS; ++p) X[(static_cast<std::size_t>(i) * BS + p) * K] = d[i * BS + p];
  for (int p = 0; p < BS; ++p)
    for (int q = 0; q < BS; ++q) {
      X[(static_cast<std::size_t>(0) * BS + p) * K + 1 + q] = A[p * BS + q];
      X[(static_cast<std::size_t>(nb - 1) * BS + p) * K + 1 + BS + q] = C[(nb - 1) * bb + p * BS + q];
    }
  if (!blockThomasFixed<BS, K>(nb, A, B, C, X.data(), work)) return false;
  Eigen::Matrix<double, 2 * BS, 2 * BS> S = Eigen::Matrix<double, 2 * BS, 2 * BS>::Identity();
  Eigen::Matrix<double, 2 * BS, 1> vy;
  for (int p = 0; p < BS; ++p) {
    const double* last = &X[(static_cast<std::size_t>(nb - 1) * BS + p) * K];
    const double* first = &X[static_cast<std::size_t>(p) * K];
    vy(p) = last[0];
    vy(BS + p) = first[0];
    for (int k = 0; k < 2 * BS; ++k) {
      S(p, k) += last[1 + k];
      S(BS + p, k) += first[1 + k];
    }
  }
  const Eigen::Matrix<double, 2 * BS, 1> w = S.fullPivLu().solve(vy);
  for (int r = 0; r < nb * BS; ++r) {
    const double* row = &X[static_cast<std::size_t>(r) * K];
    double s = row[0];
    for (int k = 0; k < 2 * BS; ++k) s -= row[1 + k] * w(k);
    d[r] = s;
  }
  return true;
}
} // namespace

void BlockTridiagSolver::factorBand(int nb, int bs, const double* A, const double* B, const double* C) {
  const int n = nb * bs, kl = 2 * bs - 1, ku = 2 * bs - 1, ldab = 2 * kl + ku + 1, bb = bs * bs;
  band_.assign(static_cast<std::size_t>(ldab) * n, 0.0);
  ipiv_.assign(n, 0);
  auto put = [&](int r, int col, double v) {
    band_[static_cast<std::size_t>(col) * ldab + kl + ku + r - col] = v;
  };
  for (int i = 0; i < nb; ++i)
    for (int p = 0; p < bs; ++p)
      for (int q = 0; q < bs; ++q) {
        const int r = i * bs + p;
        if (i > 0) put(r, (i - 1) * bs + q, A[i * bb + p * bs + q]);
        put(r, i * bs + q, B[i * bb + p * bs + q]);
        if (i < nb - 1) put(r, (i + 1) * bs + q, C[i * bb + p * bs + q]);
      }
  int info = 0;
  dgbtrf_(&n, &n, &kl, &ku, band_.data(), &ldab, ipiv_.data(), &info);
  if (info != 0)
    throw std::runtime_error("block-tridiagonal system is singular (banded LU pivot " + std::to_string(info) +
                             " is zero)");
}

void BlockTridiagSolver::applyInverse(int nb, int bs, const double*, int nrhs, double* X) const {
  const int n = nb * bs, kl = 2 * bs - 1, ku = 2 * bs - 1, ldab = 2 * kl + ku + 1;
  int info = 0;
  const char trans = 'N';
  dgbtrs_(&trans, &n, &kl, &ku, &nrhs, band_.data(), &ldab, ipiv_.data(), X, &n, &info, 1);
}

void BlockTridiagSolver::solveWithCurrentFactor(int nb, int bs, const double* A, const double* C, double* d,
                                                bool periodic) const {
  const int n = nb * bs, bb = bs * bs;
  if (!periodic) {
    applyInverse(nb, bs, A, 1, d);
    return;
  }
  // Woodbury: M = T + U V^T, U = [A_0 in block row 0 | C_{nb-1} in block row nb-1], V^T picks x_{nb-1}, x_0.
  const int m = 2 * bs;
  std::vector<double> Z(static_cast<std::size_t>(n) * m, 0.0);
  for (int q = 0; q < bs; ++q)
    for (int p = 0; p < bs; ++p) {
      Z[static_cast<std::size_t>(q) * n + p] = A[p * bs + q];
      Z[static_cast<std::size_t>(bs + q) * n + (nb - 1) * bs + p] = C[(nb - 1) * bb + p * bs + q];
    }
  applyInverse(nb, bs, A, 1, d);
  applyInverse(nb, bs, A, m, Z.data());
  Eigen::MatrixXd S = Eigen::MatrixXd::Identity(m, m);
  Eigen::VectorXd vy(m);
  for (int p = 0; p < bs; ++p) {
    vy(p) = d[(nb - 1) * bs + p];
    vy(bs + p) = d[p];
    for (int k = 0; k < m; ++k) {
      S(p, k) += Z[static_cast<std::size_t>(k) * n + (nb - 1) * bs + p];
      S(bs + p, k) += Z[static_cast<std::size_t>(k) * n + p];
    }
  }
  const Eigen::VectorXd w = S.fullPivLu().solve(vy);
  for (int k = 0; k < m; ++k)
    for (int r = 0; r < n; ++r) d[r] -= Z[static_cast<std::size_t>(k) * n + r] * w(k);
}

void BlockTridiagSolver::solve(int nb, int bs, const double* A, const double* B, const double* C, double* d,
                               bool periodic) {
  if (bs < 1 || bs > 3) throw std::invalid_argument("BlockTridiagSolver: block size must be 1..3");
  if (periodic && nb < 3)
    throw std::invalid_argument("BlockTridiagSolver: periodic system needs >= 3 block rows");
  ++stats_.solves;
  const int n = nb * bs;
  rhs_.assign(d, d + n);
  bool ok = false;
  switch (bs) {
  case 1:
    ok = blockThomasSolve<1>(nb, A, B, C, d, periodic, &cp_);
    break;
  case 2:
    ok = blockThomasSolve<2>(nb, A, B, C, d, periodic, &cp_);
    break;
  default:
    ok = blockThomasSolve<3>(nb, A, B, C, d, periodic, &cp_);
    break;
  }
  if (ok && blockTridiagResidual(nb, bs, A, B, C, d, rhs_.data(), periodic) <= tolerance) return;
  ++stats_.lu_fallbacks;
  std::copy(rhs_.begin(), rhs_.end(), d);
  factorBand(nb, bs, A, B, C);
  solveWithCurrentFactor(nb, bs, A, C, d, periodic);
  const double res = blockTridiagResidual(nb, bs, A, B, C, d, rhs_.data(), periodic);
  if (!(res <= 1e3 * tolerance))
    throw std::runtime_error("block-tridiagonal solve is inaccurate (relative residual " +
                             std::to_string(res) + "): the system is numerically singular");
}

} // namespace suite::linalg
