// Substructured (partition-method) solve of one distributed block-tridiagonal line; see the header.
#include "linalg/substructured_block_line.hpp"

#include "linalg/block_kernels.hpp"
#include "linalg/lapack.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace suite::linalg {
namespace {

using detail::flushSpikes;
using detail::SmallLU;
using detail::subtractProduct;

// Block Thomas with NF forward columns (Y and P: right-hand sides that are non-zero from the first rows) and
// NB columns in all; the NB - NF columns of Q are zero except in the last row (-C_{n-1}), so their forward
// sweep is skipped. Row stride of R: BS * NB. G: the n - 1 blocks Bh_i^{-1} C_i.
template <int BS, int NF, int NB>
bool eliminateFixed(int n, const double* A, const double* B, const double* C, int nrhs, double* R,
                    double* G) {
  constexpr int bb = BS * BS, rs = BS * NB;
  for (int i = 0; i < n; ++i) {
    double Bh[bb];
    for (int e = 0; e < bb; ++e) Bh[e] = B[(size_t)i * bb + e];
    double* Ri = R + (size_t)i * rs;
    if (i > 0) {
      subtractProduct<BS, BS>(A + (size_t)i * bb, G + (size_t)(i - 1) * bb, BS, Bh);
      subtractProduct<BS, NF>(A + (size_t)i * bb, Ri - rs, NB, Ri);
    }
    SmallLU<BS> lu;
    if (!lu.factor(Bh)) return false;
    lu.template solve<NF>(Ri, NB);
    flushSpikes<BS>(Ri, nrhs, NF, NB);
    if constexpr (NB > NF) {
      if (i + 1 == n) lu.template solve<NB - NF>(Ri + NF, NB);
    }
    if (i + 1 < n) {
      double* Gi = G + (size_t)i * bb;
      for (int e = 0; e < bb; ++e) Gi[e] = C[(size_t)i * bb + e];
      lu.template solve<BS>(Gi, BS);
    }
  }
  for (int i = n - 2; i >= 0; --i) {
    subtractProduct<BS, NB>(G + (size_t)i * bb, R + (size_t)(i + 1) * rs, NB, R + (size_t)i * rs);
    flushSpikes<BS>(R + (size_t)i * rs, nrhs, NB, NB);
  }
  return true;
}

// Thrown (identically on every rank) when the substructured solve must hand over to the exact fallback.
struct NeedsFallback {};

} // namespace

// Block Thomas on this rank's rows with the m right-hand-side columns in R (overwritten by the solution).
// A_0 and C_{n-1} (the couplings to the neighbours) are not used: they are the P and Q columns.
template <int BS>
bool SubstructuredBlockLine::eliminate(int n, const double* A, const double* B, const double* C, int nrhs,
                                       int mf, int m, double* R) {
  constexpr int bb = BS * BS;
  G_.resize((size_t)n * bb);
  // The column counts that occur (nrhs 1 or 3, with or without the P and Q spikes), unrolled.
#define SUITE_FIXED(F, M)                                                                                    \
  if (mf == F && m == M) return eliminateFixed<BS, F, M>(n, A, B, C, nrhs, R, G_.data());
  if constexpr (BS == 3) {
    SUITE_FIXED(1, 1) SUITE_FIXED(4, 4) SUITE_FIXED(1, 4) SUITE_FIXED(4, 7)
  } else {
    SUITE_FIXED(3, 3)
    SUITE_FIXED(4, 4)
    SUITE_FIXED(3, 4)
    SUITE_FIXED(4, 5) SUITE_FIXED(1, 1) SUITE_FIXED(2, 2) SUITE_FIXED(1, 2) SUITE_FIXED(2, 3)
  }
#undef SUITE_FIXED
  const int rs = BS * m; // stride of one block row of R
  for (int i = 0; i < n; ++i) {
    double Bh[bb];
    for (int e = 0; e < bb; ++e) Bh[e] = B[(size_t)i * bb + e];
    double* Ri = R + (size_t)i * rs;
    if (i > 0) {
      subtractProduct<BS>(A + (size_t)i * bb, G_.data() + (size_t)(i - 1) * bb, BS, Bh, BS);
      subtractProduct<BS>(A + (size_t)i * bb, Ri - rs, m, Ri, m);
    }
    SmallLU<BS> lu;
    if (!lu.factor(Bh)) return false;
    lu.solve(Ri, m, m);
    flushSpikes<BS>(Ri, nrhs, m, m);
    if (i + 1 < n) {
      double* Gi = G_.data() + (size_t)i * bb;
      for (int e = 0; e < bb; ++e) Gi[e] = C[(size_t)i * bb + e];
      lu.solve(Gi, BS, BS);
    }
  }
  for (int i = n - 2; i >= 0; --i) {
    subtractProduct<BS>(G_.data() + (size_t)i * bb, R + (size_t)(i + 1) * rs, m, R + (size_t)i * rs, m);
    flushSpikes<BS>(R + (size_t)i * rs, nrhs, m, m);
  }
  return true;
}

// Reduced system for the first (F_r) and last (L_r) rows of every rank r, unknown blocks ordered
// F_0, L_0, F_1, L_1, ...:  F_r - PF_r L_{r-1} - QF_r F_{r+1} = YF_r  and the same for L_r with PL, QL, YL.
// On return *z holds the solution, column-major N x nrhs. Identical on every rank (same data, same LAPACK).
template <int BS>
void SubstructuredBlockLine::reducedSolve(int P, int nrhs, bool periodic, std::vector<double>* z) {
  const int N = 2 * P * BS, E = 2 * BS * nrhs + 4 * BS * BS + 1;
  const bool banded = !periodic && N > 1536;
  const int kl = 3 * BS - 1, ku = 3 * BS - 1, ldab = 2 * kl + ku + 1;
  red_.assign(banded ? (size_t)ldab * N : (size_t)N * N, 0.0);
  auto at = [&](int row, int col) -> double& {
    return banded ? red_[(size_t)(kl + ku + row - col) + (size_t)col * ldab] : red_[(size_t)col * N + row];
  };
  z->assign((size_t)N * nrhs, 0.0);
  for (int r = 0; r < P; ++r) {
    const double* e = all_ends_.data() + (size_t)r * E;
    const double *yF = e, *yL = yF + BS * nrhs, *PF = yL + BS * nrhs, *PL = PF + BS * BS, *QF = PL + BS * BS,
                 *QL = QF + BS * BS;
    const int left = r > 0 ? r - 1 : (periodic ? P - 1 : -1);
    const int right = r + 1 < P ? r + 1 : (periodic ? 0 : -1);
    for (int side = 0; side < 2; ++side) {
      const double *y = side ? yL : yF, *Pm = side ? PL : PF, *Qm = side ? QL : QF;
      for (int a = 0; a < BS; ++a) {
        const int row = (2 * r + side) * BS + a;
        at(row, row) += 1.0;
        for (int b = 0; b < BS; ++b) {
          if (left >= 0) at(row, (2 * left + 1) * BS + b) -= Pm[a * BS + b];
          if (right >= 0) at(row, 2 * right * BS + b) -= Qm[a * BS + b];
        }
        for (int k = 0; k < nrhs; ++k) (*z)[(size_t)k * N + row] = y[a * nrhs + k];
      }
    }
  }
  ipiv_.resize(N);
  int info = 0;
  if (banded)
    dgbsv_(&N, &kl, &ku, &nrhs, red_.data(), &ldab, ipiv_.data(), z->data(), &N, &info);
  else
    dgesv_(&N, &nrhs, red_.data(), &N, ipiv_.data(), z->data(), &N, &info);
  if (info != 0) z->assign(z->size(), NAN); // caught by the residual check: fallback
}

template <int BS>
void SubstructuredBlockLine::solveImpl(MPI_Comm comm, int n, const double* A, const double* B,
                                       const double* C, const double* d, int nrhs, bool periodic,
                                       long long first, int count, double* x) {
  int rank = 0, P = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &P);
  ++stats_.solves;
  const bool hasL = rank > 0 || periodic, hasR = rank + 1 < P || periodic;
  if (n < 2 || count < n || count > n + 1 || (count == n + 1 && !hasR))
    throw std::invalid_argument("SubstructuredBlockLine: needs >= 2 rows per rank and count = nloc (+1)");
  const int cP = nrhs, cQ = nrhs + (hasL ? BS : 0), m = cQ + (hasR ? BS : 0);
  const Layout L{n, nrhs, cP, cQ, m, BS * m, hasL, hasR};
  const bool ok = eliminateLocal<BS>(L, A, B, C, d);
  gatherEnds<BS>(comm, P, L, ok);
  reducedSolve<BS>(P, nrhs, periodic, &zr_);
  double xl[BS * 8], xr[BS * 8]; // nrhs <= 8
  finishRows<BS>(L, rank, P, xl, xr, x);
  if (count == n + 1)
    for (int e = 0; e < BS * nrhs; ++e) x[(size_t)n * BS * nrhs + e] = xr[e];
  (void)first;
  checkResidual<BS>(comm, L, A, B, C, d, xl, xr, x);
}

// Pass 1: this rank's rows of T_r [Y P Q] = [d, -A_0 E_0, -C_{n-1} E_{n-1}] into R_; false on a tiny pivot.
template <int BS>
bool SubstructuredBlockLine::eliminateLocal(const Layout& L, const double* A, const double* B,
                                            const double* C, const double* d) {
  constexpr int bb = BS * BS;
  const int n = L.n, nrhs = L.nrhs, m = L.m, rs = L.rs;
  R_.assign((size_t)n * rs, 0.0);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < BS; ++a)
      for (int k = 0; k < nrhs; ++k) R_[(size_t)i * rs + a * m + k] = d[((size_t)i * BS + a) * nrhs + k];
  for (int a = 0; a < BS; ++a)
    for (int b = 0; b < BS; ++b) {
      if (L.hasL) R_[a * m + L.cP + b] = -A[a * BS + b];
      if (L.hasR) R_[(size_t)(n - 1) * rs + a * m + L.cQ + b] = -C[(size_t)(n - 1) * bb + a * BS + b];
    }
  return eliminate<BS>(n, A, B, C, nrhs, L.cQ, m, R_.data());
}

// Pass 2: the end rows of every rank (YF, YL: bs x nrhs; PF, PL, QF, QL: bs x bs; and the local success
// flag) into all_ends_, by one MPI_Allgather. Throws NeedsFallback (on every rank) if any rank failed.
template <int BS> void SubstructuredBlockLine::gatherEnds(MPI_Comm comm, int P, const Layout& L, bool ok) {
  constexpr int bb = BS * BS;
  const int nrhs = L.nrhs, m = L.m;
  const int E = 2 * BS * nrhs + 4 * bb + 1;
  ends_.assign(E, 0.0);
  for (int side = 0; side < 2; ++side) {
    const double* row = R_.data() + (size_t)(side ? L.n - 1 : 0) * L.rs;
    for (int a = 0; a < BS; ++a) {
      for (int k = 0; k < nrhs; ++k) ends_[side * BS * nrhs + a * nrhs + k] = row[a * m + k];
      for (int b = 0; b < BS; ++b) {
        if (L.hasL) ends_[2 * BS * nrhs + side * bb + a * BS + b] = row[a * m + L.cP + b];
        if (L.hasR) ends_[2 * BS * nrhs + (2 + side) * bb + a * BS + b] = row[a * m + L.cQ + b];
      }
    }
  }
  ends_[E - 1] = ok ? 1.0 : 0.0;
  all_ends_.resize((size_t)E * P);
  MPI_Allgather(ends_.data(), E, MPI_DOUBLE, all_ends_.data(), E, MPI_DOUBLE, comm);
  bool all_ok = true;
  for (int r = 0; r < P; ++r) all_ok = all_ok && all_ends_[(size_t)r * E + E - 1] == 1.0;
  if (!all_ok) { // same decision on every rank
    ++stats_.fallbacks;
    throw NeedsFallback{};
  }
}

// Pass 3, after reducedSolve: the neighbours' rows xl (last row of the rank before) and xr (first row of the
// rank after; zero where there is none), and this rank's rows x_i = Y_i + P_i xl + Q_i xr.
template <int BS>
void SubstructuredBlockLine::finishRows(const Layout& L, int rank, int P, double* xl, double* xr, double* x) {
  const int n = L.n, nrhs = L.nrhs, m = L.m, N = 2 * P * BS;
  const int left = rank > 0 ? rank - 1 : P - 1, right = rank + 1 < P ? rank + 1 : 0;
  for (int a = 0; a < BS; ++a)
    for (int k = 0; k < nrhs; ++k) {
      xl[a * nrhs + k] = L.hasL ? zr_[(size_t)k * N + (2 * left + 1) * BS + a] : 0.0;
      xr[a * nrhs + k] = L.hasR ? zr_[(size_t)k * N + 2 * right * BS + a] : 0.0;
    }
  for (int i = 0; i < n; ++i) {
    const double* Ri = R_.data() + (size_t)i * L.rs;
    for (int a = 0; a < BS; ++a)
      for (int k = 0; k < nrhs; ++k) {
        double v = Ri[a * m + k];
        for (int b = 0; b < BS; ++b) {
          if (L.hasL) v += Ri[a * m + L.cP + b] * xl[b * nrhs + k];
          if (L.hasR) v += Ri[a * m + L.cQ + b] * xr[b * nrhs + k];
        }
        x[((size_t)i * BS + a) * nrhs + k] = v;
      }
  }
}

// Pass 4: residual of this rank's rows of the global system (x_{-1} = xl, x_n = xr), reduced over the ranks
// (one MPI_Allreduce). Throws NeedsFallback (on every rank) if it exceeds the tolerance.
template <int BS>
void SubstructuredBlockLine::checkResidual(MPI_Comm comm, const Layout& L, const double* A, const double* B,
                                           const double* C, const double* d, const double* xl,
                                           const double* xr, const double* x) {
  constexpr int bb = BS * BS;
  const int n = L.n, nrhs = L.nrhs;
  double worst[2] = {0.0, 0.0}; // max |residual|, max |d|
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < BS; ++a)
      for (int k = 0; k < nrhs; ++k) {
        double r = -d[((size_t)i * BS + a) * nrhs + k];
        worst[1] = std::max(worst[1], std::fabs(r));
        for (int b = 0; b < BS; ++b) {
          const double xm1 = i > 0 ? x[((size_t)(i - 1) * BS + b) * nrhs + k] : xl[b * nrhs + k];
          const double xp1 = i + 1 < n ? x[((size_t)(i + 1) * BS + b) * nrhs + k] : xr[b * nrhs + k];
          r += B[(size_t)i * bb + a * BS + b] * x[((size_t)i * BS + b) * nrhs + k];
          if (i > 0 || L.hasL) r += A[(size_t)i * bb + a * BS + b] * xm1;
          if (i + 1 < n || L.hasR) r += C[(size_t)i * bb + a * BS + b] * xp1;
        }
        worst[0] = std::max(worst[0], std::isfinite(r) ? std::fabs(r) : 1e300);
      }
  MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, comm);
  if (!(worst[0] <= tolerance * std::max(worst[1], 1e-300))) {
    ++stats_.fallbacks;
    throw NeedsFallback{};
  }
}

void SubstructuredBlockLine::solve(MPI_Comm comm, int bs, int nloc, const double* A, const double* B,
                                   const double* C, const double* d, bool periodic, long long first,
                                   int count, double* x) {
  try {
    if (bs == 3)
      solveImpl<3>(comm, nloc, A, B, C, d, 1, periodic, first, count, x);
    else if (bs == 1)
      solveImpl<1>(comm, nloc, A, B, C, d, 1, periodic, first, count, x);
    else
      throw std::invalid_argument("SubstructuredBlockLine: block size must be 1 or 3");
  } catch (const NeedsFallback&) { // collective decision: exact gather + pivoting band LU
    fallback_.solve(comm, bs, nloc, A, B, C, d, periodic, first, count, x);
  }
}

void SubstructuredBlockLine::solveScalar(MPI_Comm comm, int nloc, const double* abc, int ncomp,
                                         const double* d, bool periodic, long long first, int count,
                                         double* x) {
  if (ncomp < 1 || ncomp > 8) throw std::invalid_argument("SubstructuredBlockLine: 1..8 right-hand sides");
  sA_.resize(nloc);
  sB_.resize(nloc);
  sC_.resize(nloc);
  for (int i = 0; i < nloc; ++i) {
    sA_[i] = abc[3 * i];
    sB_[i] = abc[3 * i + 1];
    sC_[i] = abc[3 * i + 2];
  }
  try {
    solveImpl<1>(comm, nloc, sA_.data(), sB_.data(), sC_.data(), d, ncomp, periodic, first, count, x);
  } catch (const NeedsFallback&) {
    fallback_.solveScalar(comm, nloc, abc, ncomp, d, periodic, first, count, x);
  }
}

} // namespace suite::linalg
