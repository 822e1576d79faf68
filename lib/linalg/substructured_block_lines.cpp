// Batched substructured (partition-method) solve of many distributed block-tridiagonal lines; see the header
// for the method and its references (Wang 1981; Mattor, Williams & Hewett 1995).
//
// Per line and rank, with T_r this rank's rows (A_0 and C_{n-1}, the couplings to the neighbours, removed):
//   pass 1 (lineEnds): block Thomas sweep down the rows for T_r [Y P Q] = [d, -A_0 E_0, -C_{n-1} E_{n-1}],
//     keeping only the end rows: the last rows come out of the forward sweep, the first rows are accumulated
//     during the same sweep as x_0 = sum_i W_i R_i (R_i: forward-reduced rows, W_0 = I, W_{i+1} = -W_i G_i
//     with G_i = Bh_i^{-1} C_i: the back substitution unrolled), so nothing per row is stored;
//   reduced solve (reducedSolve): the 2 P bs unknowns F_r, L_r (first/last rows of every rank) from
//     F_r = YF_r + PF_r L_{r-1} + QF_r F_{r+1}, L_r = YL_r + PL_r L_{r-1} + QL_r F_{r+1};
//   pass 2 (lineSolve): block Thomas again with d_0 -= A_0 x_left, d_{n-1} -= C_{n-1} x_right; its work
//     arrays hold one line (n bs^2 numbers).
// Spike columns and W are flushed below 1e-200 (subnormal arithmetic is ~100x slower); once they are zero
// their updates are skipped.
#include "linalg/substructured_block_lines.hpp"

#include "linalg/block_kernels.hpp"
#include "linalg/block_thomas_lanes.hpp"
#include "linalg/lapack.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace suite::linalg {
namespace {

using detail::addProduct;
using detail::flushSpikes;
using detail::SmallLU;
using detail::subtractProduct;

constexpr double kFailed = 1e300; // residual recorded for a line whose substructured solve broke down

template <int N> inline bool anyNonzero(const double* v) {
  for (int e = 0; e < N; ++e)
    if (v[e] != 0.0) return true;
  return false;
}

// Dense LU with partial pivoting of the n x n column-major matrix a, applied to the n x nrhs column-major b
// (overwritten by the solution). In-house rather than LAPACK dgesv: the systems are small (n <= ~50) and
// solved once per line, where a threaded BLAS may spawn threads per call (measured: 30x slower with
// OpenBLAS on a loaded machine). False on an exactly zero (or non-finite) pivot.
bool denseSolve(int n, double* a, int nrhs, double* b) {
  for (int k = 0; k < n; ++k) {
    int p = k;
    double* ck = a + (size_t)k * n;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(ck[i]) > std::fabs(ck[p])) p = i;
    if (!(std::fabs(ck[p]) > 0.0) || !std::isfinite(ck[p])) return false;
    if (p != k) {
      for (int j = 0; j < n; ++j) std::swap(a[(size_t)j * n + k], a[(size_t)j * n + p]);
      for (int j = 0; j < nrhs; ++j) std::swap(b[(size_t)j * n + k], b[(size_t)j * n + p]);
    }
    const double inv = 1.0 / ck[k];
    for (int i = k + 1; i < n; ++i) ck[i] *= inv;
    for (int j = k + 1; j < n; ++j) {
      double* cj = a + (size_t)j * n;
      const double f = cj[k];
      if (f != 0.0)
        for (int i = k + 1; i < n; ++i) cj[i] -= f * ck[i];
    }
    for (int j = 0; j < nrhs; ++j) {
      double* bj = b + (size_t)j * n;
      const double f = bj[k];
      if (f != 0.0)
        for (int i = k + 1; i < n; ++i) bj[i] -= f * ck[i];
    }
  }
  for (int j = 0; j < nrhs; ++j) {
    double* bj = b + (size_t)j * n;
    for (int k = n - 1; k >= 0; --k) {
      bj[k] /= a[(size_t)k * n + k];
      const double f = bj[k];
      const double* ck = a + (size_t)k * n;
      for (int i = 0; i < k; ++i) bj[i] -= f * ck[i];
    }
  }
  return true;
}

// Rows of one line: block row i at A + i * ms (ms = bs * bs for block rows; 3 for scalar rows, with
// A = abc, B = abc + 1, C = abc + 2), right-hand side d + i * bs * nrhs (row-major bs x nrhs).
struct LineRows {
  const double *A, *B, *C, *d;
  int ms;
};

// Pass 1: the end rows of Y, P and Q, written to e = [YF, YL (bs x nrhs), PF, PL, QF, QL (bs x bs)].
// work: 3 bs nrhs doubles. False if a block pivot was tiny.
template <int BS, int NR>
bool lineEnds(int n, int nrhs, const LineRows& L, bool hasL, bool hasR, double* work, double* e) {
  constexpr int bb = BS * BS;
  const int nc = NR > 0 ? NR : nrhs, ny = BS * nc;
  double *ry = work, *ryp = work + ny, *accY = work + 2 * ny;
  double G[bb] = {}, Bh[bb] = {}, rp[bb] = {}, tmp[bb] = {}, accP[bb] = {}, W[bb] = {}, rq[bb] = {};
  bool pAlive = hasL, wAlive = true;
  for (int e2 = 0; e2 < bb; ++e2) rq[e2] = 0.0;
  for (int i = 0; i < n; ++i) {
    const double *Ai = L.A + (size_t)i * L.ms, *Bi = L.B + (size_t)i * L.ms, *Ci = L.C + (size_t)i * L.ms;
    const double* di = L.d + (size_t)i * ny;
    for (int k = 0; k < bb; ++k) Bh[k] = Bi[k];
    for (int k = 0; k < ny; ++k) ry[k] = di[k];
    if (i == 0) {
      for (int k = 0; k < bb; ++k) rp[k] = hasL ? -Ai[k] : 0.0;
    } else {
      subtractProduct<BS, BS>(Ai, G, BS, Bh);
      subtractProduct<BS, NR>(Ai, ryp, nc, ry, nc);
      if (pAlive) {
        for (int k = 0; k < bb; ++k) tmp[k] = 0.0;
        subtractProduct<BS, BS>(Ai, rp, BS, tmp);
        for (int k = 0; k < bb; ++k) rp[k] = tmp[k];
      }
    }
    SmallLU<BS> lu;
    if (!lu.factor(Bh)) return false;
    lu.template solveFast<NR>(ry, nc, nc);
    if (pAlive) {
      lu.template solveFast<BS>(rp, BS);
      flushSpikes<BS>(rp, 0, BS, BS);
      pAlive = anyNonzero<bb>(rp);
    }
    if (i + 1 < n) {
      for (int k = 0; k < bb; ++k) G[k] = Ci[k];
      lu.template solveFast<BS>(G, BS);
    } else if (hasR) {
      for (int k = 0; k < bb; ++k) rq[k] = -Ci[k];
      lu.template solveFast<BS>(rq, BS);
    }
    // First row: x_0 = sum_i W_i R_i.
    if (i == 0) {
      for (int k = 0; k < ny; ++k) accY[k] = ry[k];
      for (int k = 0; k < bb; ++k) accP[k] = rp[k];
    } else if (wAlive) {
      addProduct<BS, NR>(W, ry, nc, accY, nc);
      if (pAlive) addProduct<BS, BS>(W, rp, BS, accP);
    }
    if (i + 1 < n && wAlive) { // W_{i+1} = -W_i G_i
      if (i == 0) {
        for (int k = 0; k < bb; ++k) W[k] = -G[k];
      } else {
        for (int k = 0; k < bb; ++k) tmp[k] = 0.0;
        subtractProduct<BS, BS>(W, G, BS, tmp);
        for (int k = 0; k < bb; ++k) W[k] = tmp[k];
      }
      flushSpikes<BS>(W, 0, BS, BS);
      wAlive = anyNonzero<bb>(W);
    }
    std::swap(ry, ryp); // ryp: this row's forward-reduced values
  }
  double *YF = e, *YL = e + ny, *PF = YL + ny, *PL = PF + bb, *QF = PL + bb, *QL = QF + bb;
  for (int k = 0; k < ny; ++k) YF[k] = accY[k], YL[k] = ryp[k];
  for (int k = 0; k < bb; ++k) PF[k] = accP[k], PL[k] = rp[k], QL[k] = rq[k], QF[k] = 0.0;
  if (wAlive && hasR) addProduct<BS, BS>(W, rq, BS, QF);
  return true;
}

// Pass 2: block Thomas for the rows of this rank with the neighbour values xl (x_{-1}) and xr (x_n), each
// bs x nrhs, moved to the right-hand side (when hasL / hasR). x: n rows of bs x nrhs; G: (n - 1) bs^2 work.
template <int BS, int NR>
bool lineSolve(int n, int nrhs, const LineRows& L, bool hasL, bool hasR, const double* xl, const double* xr,
               double* G, double* x) {
  constexpr int bb = BS * BS;
  const int nc = NR > 0 ? NR : nrhs, ny = BS * nc;
  for (int i = 0; i < n; ++i) {
    const double *Ai = L.A + (size_t)i * L.ms, *Bi = L.B + (size_t)i * L.ms, *Ci = L.C + (size_t)i * L.ms;
    const double* di = L.d + (size_t)i * ny;
    double* y = x + (size_t)i * ny;
    double Bh[bb];
    for (int k = 0; k < bb; ++k) Bh[k] = Bi[k];
    for (int k = 0; k < ny; ++k) y[k] = di[k];
    if (i == 0 && hasL) subtractProduct<BS, NR>(Ai, xl, nc, y, nc);
    if (i + 1 == n && hasR) subtractProduct<BS, NR>(Ci, xr, nc, y, nc);
    if (i > 0) {
      subtractProduct<BS, BS>(Ai, G + (size_t)(i - 1) * bb, BS, Bh);
      subtractProduct<BS, NR>(Ai, y - ny, nc, y, nc);
    }
    SmallLU<BS> lu;
    if (!lu.factor(Bh)) return false;
    lu.template solveFast<NR>(y, nc, nc);
    if (i + 1 < n) {
      double* Gi = G + (size_t)i * bb;
      for (int k = 0; k < bb; ++k) Gi[k] = Ci[k];
      lu.template solveFast<BS>(Gi, BS);
    }
  }
  for (int i = n - 2; i >= 0; --i)
    subtractProduct<BS, NR>(G + (size_t)i * bb, x + (size_t)(i + 1) * ny, nc, x + (size_t)i * ny, nc);
  return true;
}

// Max |residual| of this rank's rows of the global line (x_{-1} = xl, x_n = xr) and max |d|, into out[0..1].
template <int BS, int NR>
void lineResidual(int n, int nrhs, const LineRows& L, bool hasL, bool hasR, const double* xl,
                  const double* xr, const double* x, double* out) {
  const int nc = NR > 0 ? NR : nrhs, ny = BS * nc;
  double worst = 0.0, dmax = 0.0;
  for (int i = 0; i < n; ++i) {
    const double *Ai = L.A + (size_t)i * L.ms, *Bi = L.B + (size_t)i * L.ms, *Ci = L.C + (size_t)i * L.ms;
    const double* di = L.d + (size_t)i * ny;
    const double* xi = x + (size_t)i * ny;
    const double* xm = i > 0 ? xi - ny : (hasL ? xl : nullptr);
    const double* xp = i + 1 < n ? xi + ny : (hasR ? xr : nullptr);
    for (int a = 0; a < BS; ++a)
      for (int k = 0; k < nc; ++k) {
        double r = -di[a * nc + k];
        dmax = std::max(dmax, std::fabs(r));
        for (int b = 0; b < BS; ++b) {
          r += Bi[a * BS + b] * xi[b * nc + k];
          if (xm) r += Ai[a * BS + b] * xm[b * nc + k];
          if (xp) r += Ci[a * BS + b] * xp[b * nc + k];
        }
        worst = std::max(worst, std::isfinite(r) ? std::fabs(r) : kFailed);
      }
  }
  out[0] = worst;
  out[1] = dmax;
}

} // namespace

// Reduced system of one line: unknown blocks ordered F_0, L_0, F_1, L_1, ... (bs x nrhs each);
//   F_r - PF_r L_{r-1} - QF_r F_{r+1} = YF_r,  L_r - PL_r L_{r-1} - QL_r F_{r+1} = YL_r.
// ends: rank r's end rows at ends + r * rank_stride. z: the solution, column-major N x nrhs, N = 2 P bs.
// Dense LU (denseSolve) up to reduced_dense_max unknowns, else band LU (dgbsv, 3 bs - 1 sub- and
// super-diagonals); the wrap-around couplings of periodic lines (P > 1) then go into a Woodbury correction
//   M = M0 + U V^T,  V^T z = (L_{P-1}, F_0):  z = Z - Zu (I + V^T Zu)^{-1} V^T Z,  M0 [Z Zu] = [y U].
// False if LAPACK met an exactly singular pivot.
template <int BS>
bool SubstructuredBlockLines::reducedSolve(int P, int nrhs, bool periodic, const double* ends,
                                           std::size_t rank_stride, int E, double* z) {
  constexpr int bb = BS * BS;
  (void)E;
  const int N = 2 * P * BS, ny = BS * nrhs;
  const bool banded = N > reduced_dense_max, wood = banded && periodic && P > 1;
  const int kl = 3 * BS - 1, ku = kl, ldab = 2 * kl + ku + 1;
  const int nw = wood ? 2 * BS : 0, ncol = nrhs + nw;
  red_.assign(banded ? (size_t)ldab * N : (size_t)N * N, 0.0);
  zu_.assign((size_t)N * ncol, 0.0);
  auto at = [&](int row, int col) -> double& {
    return banded ? red_[(size_t)(kl + ku + row - col) + (size_t)col * ldab] : red_[(size_t)col * N + row];
  };
  for (int r = 0; r < P; ++r) {
    const double* e = ends + (size_t)r * rank_stride;
    const double *yF = e, *yL = e + ny, *PF = yL + ny, *PL = PF + bb, *QF = PL + bb, *QL = QF + bb;
    const int left = r > 0 ? r - 1 : (periodic ? P - 1 : -1);
    const int right = r + 1 < P ? r + 1 : (periodic ? 0 : -1);
    const bool wrapL = wood && r == 0, wrapR = wood && r == P - 1;
    for (int side = 0; side < 2; ++side) {
      const double *y = side ? yL : yF, *Pm = side ? PL : PF, *Qm = side ? QL : QF;
      for (int a = 0; a < BS; ++a) {
        const int row = (2 * r + side) * BS + a;
        at(row, row) += 1.0;
        for (int b = 0; b < BS; ++b) {
          if (left >= 0) {
            if (wrapL)
              zu_[(size_t)(nrhs + b) * N + row] -= Pm[a * BS + b];
            else
              at(row, (2 * left + 1) * BS + b) -= Pm[a * BS + b];
          }
          if (right >= 0) {
            if (wrapR)
              zu_[(size_t)(nrhs + BS + b) * N + row] -= Qm[a * BS + b];
            else
              at(row, 2 * right * BS + b) -= Qm[a * BS + b];
          }
        }
        for (int k = 0; k < nrhs; ++k) zu_[(size_t)k * N + row] = y[a * nrhs + k];
      }
    }
  }
  ipiv_.resize(std::max(N, 2 * BS));
  int info = 0;
  if (banded)
    dgbsv_(&N, &kl, &ku, &ncol, red_.data(), &ldab, ipiv_.data(), zu_.data(), &N, &info);
  else if (!denseSolve(N, red_.data(), ncol, zu_.data()))
    info = 1;
  if (info != 0) return false;
  if (!wood) {
    std::copy(zu_.begin(), zu_.begin() + (size_t)N * nrhs, z);
    return true;
  }
  const int m = 2 * BS;
  auto idx = [&](int j) { return j < BS ? (2 * P - 1) * BS + j : j - BS; }; // the columns of L_{P-1}, F_0
  s_.assign((size_t)m * (m + nrhs), 0.0);
  double *S = s_.data(), *t = S + (size_t)m * m;
  for (int j = 0; j < m; ++j) {
    for (int c = 0; c < m; ++c)
      S[j + (size_t)c * m] = (j == c ? 1.0 : 0.0) + zu_[(size_t)(nrhs + c) * N + idx(j)];
    for (int k = 0; k < nrhs; ++k) t[j + (size_t)k * m] = zu_[(size_t)k * N + idx(j)];
  }
  if (!denseSolve(m, S, nrhs, t)) return false;
  for (int k = 0; k < nrhs; ++k)
    for (int row = 0; row < N; ++row) {
      double v = zu_[(size_t)k * N + row];
      for (int c = 0; c < m; ++c) v -= zu_[(size_t)(nrhs + c) * N + row] * t[c + (size_t)k * m];
      z[(size_t)k * N + row] = v;
    }
  return true;
}

double* SubstructuredBlockLines::laneWork(int bs, int n) {
  lanes_.resize((size_t)blockThomasLanesWork(bs, n) / kThomasLanes);
  return reinterpret_cast<double*>(lanes_.data());
}

// Pass 2 of lines l0 .. l0 + batch - 1 (batch 1, or kThomasLanes lines solved at once when every one of their
// reduced solves succeeded; bitwise the one-line solves): per line the reduced solve, its neighbour values
// x_left, x_right, the line solve with them moved to the right-hand side, the residual; x: line l0's solution.
template <int BS, int NR, class Rows>
void SubstructuredBlockLines::secondPass(const Shape& s, int l0, int batch, const Rows& rows, double* x,
                                         std::size_t xstride) {
  constexpr int bb = BS * BS;
  const int ny = BS * s.nrhs, E = 2 * ny + 4 * bb + 1, N = 2 * s.P * BS;
  const bool hasL = s.hasL(), hasR = s.hasR();
  const int left = s.rank > 0 ? s.rank - 1 : s.P - 1, right = s.rank + 1 < s.P ? s.rank + 1 : 0;
  const std::size_t rank_stride = (size_t)s.nlines * E;
  neighbours_.resize((size_t)2 * kThomasLanes * ny);
  z_.resize((size_t)N * s.nrhs);
  bool ok[kThomasLanes], all = true;
  for (int k = 0; k < batch; ++k) {
    const double* e0 = all_ends_.data() + (size_t)(l0 + k) * E;
    double *xl = neighbours_.data() + (size_t)2 * k * ny, *xr = xl + ny;
    ok[k] = true;
    for (int r = 0; r < s.P; ++r) ok[k] = ok[k] && e0[r * rank_stride + E - 1] == 1.0;
    ok[k] = ok[k] && reducedSolve<BS>(s.P, s.nrhs, s.periodic, e0, rank_stride, E, z_.data());
    all = all && ok[k];
    if (ok[k])
      for (int a = 0; a < BS; ++a)
        for (int c = 0; c < s.nrhs; ++c) {
          xl[a * s.nrhs + c] = hasL ? z_[(size_t)c * N + (2 * left + 1) * BS + a] : 0.0;
          xr[a * s.nrhs + c] = hasR ? z_[(size_t)c * N + 2 * right * BS + a] : 0.0;
        }
  }
  bool lanes = false;
  if (batch == kThomasLanes && all) {
    LaneLine q[kThomasLanes];
    for (int k = 0; k < kThomasLanes; ++k) {
      const LineRows L = rows(l0 + k);
      const double* xl = neighbours_.data() + (size_t)2 * k * ny;
      q[k] = {L.A, L.B, L.C, L.d, L.ms, x + k * xstride, hasL ? xl : nullptr, hasR ? xl + ny : nullptr};
    }
    lanes = blockThomasLanes(BS, s.n, q, laneWork(BS, s.n));
    stats_.lane_batches += lanes;
  }
  for (int k = 0; k < batch; ++k) {
    const LineRows L = rows(l0 + k);
    double *xline = x + k * xstride, *xl = neighbours_.data() + (size_t)2 * k * ny, *xr = xl + ny;
    if (ok[k] && !lanes) ok[k] = lineSolve<BS, NR>(s.n, s.nrhs, L, hasL, hasR, xl, xr, G_.data(), xline);
    if (!ok[k]) {
      res_[2 * (size_t)(l0 + k)] = kFailed;
      continue;
    }
    lineResidual<BS, NR>(s.n, s.nrhs, L, hasL, hasR, xl, xr, xline, &res_[2 * (size_t)(l0 + k)]);
    if (s.count == s.n + 1) std::copy(xr, xr + ny, xline + (size_t)s.n * ny);
  }
}

// One rank, open lines: block Thomas (lineSolve) and the residual of every line, four lines at a time where
// NR = 1 (blockThomasLanes, bitwise the one-line solves; a rejected pivot sends its four lines one by one). A
// remainder of two or three lines goes through the four lanes too, the spare lanes repeating its first line
// into scratch: the two systems of a 1D line (its left- and right-biased rows) then cost about one
// (measured: Sod N = 2048, enopade6: solved one line at a time, lineSolve<3,1> takes 25% of the run).
template <int BS, int NR, class Rows>
void SubstructuredBlockLines::plainSweeps(const Shape& s, const Rows& rows, double* x, std::size_t xstride) {
  const auto one = [&](int l) {
    const LineRows L = rows(l);
    double* xline = x + l * xstride;
    if (lineSolve<BS, NR>(s.n, s.nrhs, L, false, false, nullptr, nullptr, G_.data(), xline))
      lineResidual<BS, NR>(s.n, s.nrhs, L, false, false, nullptr, nullptr, xline, &res_[2 * (size_t)l]);
    else
      res_[2 * (size_t)l] = kFailed;
  };
  int l = 0;
  if constexpr (laned<BS, NR>())
    for (; s.nlines - l >= 2; l += kThomasLanes) {
      const int real = std::min(kThomasLanes, s.nlines - l); // lanes k >= real: spares
      spare_.resize(real < kThomasLanes ? (size_t)s.count * BS * s.nrhs : 0);
      LaneLine q[kThomasLanes];
      for (int k = 0; k < kThomasLanes; ++k) {
        const LineRows L = rows(k < real ? l + k : l);
        q[k] = {L.A, L.B, L.C, L.d, L.ms, k < real ? x + (l + k) * xstride : spare_.data()};
      }
      const bool ok = blockThomasLanes(BS, s.n, q, laneWork(BS, s.n));
      stats_.lane_batches += ok;
      for (int k = 0; k < real; ++k)
        if (ok)
          lineResidual<BS, NR>(s.n, s.nrhs, rows(l + k), false, false, nullptr, nullptr, q[k].x,
                               &res_[2 * (size_t)(l + k)]);
        else
          one(l + k);
    }
  for (; l < s.nlines; ++l) one(l);
}

// Pass 1: the end rows of every line into ends_ (lineEnds), four lines at a time where NR = 1
// (blockEndsLanes, bitwise lineEnds; a rejected pivot sends its four lines one by one).
template <int BS, int NR, class Rows>
void SubstructuredBlockLines::firstPass(const Shape& s, const Rows& rows) {
  const int ny = BS * s.nrhs, E = 2 * ny + 4 * BS * BS + 1;
  const bool hasL = s.hasL(), hasR = s.hasR();
  ends_.assign((size_t)s.nlines * E, 0.0);
  const auto ends = [&](int l) {
    double* e = ends_.data() + (size_t)l * E;
    e[E - 1] = lineEnds<BS, NR>(s.n, s.nrhs, rows(l), hasL, hasR, work_.data(), e) ? 1.0 : 0.0;
  };
  int l = 0;
  if constexpr (laned<BS, NR>())
    for (; l + kThomasLanes <= s.nlines; l += kThomasLanes) {
      LaneLine q[kThomasLanes];
      double* e[kThomasLanes];
      for (int k = 0; k < kThomasLanes; ++k) {
        const LineRows L = rows(l + k);
        q[k] = {L.A, L.B, L.C, L.d, L.ms, nullptr};
        e[k] = ends_.data() + (size_t)(l + k) * E;
      }
      const bool ok = blockEndsLanes(BS, s.n, q, hasL, hasR, laneWork(BS, s.n), e);
      stats_.lane_batches += ok;
      for (int k = 0; k < kThomasLanes; ++k)
        if (ok)
          e[k][E - 1] = 1.0;
        else
          ends(l + k);
    }
  for (; l < s.nlines; ++l) ends(l);
}

template <int BS, int NR>
void SubstructuredBlockLines::solveImpl(MPI_Comm comm, int nlines, int n, const double* A, const double* B,
                                        const double* C, int ms, const double* d, int nrhs, bool periodic,
                                        int count, double* x) {
  constexpr int bb = BS * BS;
  int rank = 0, P = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &P);
  const int ny = BS * nrhs;
  const std::size_t lstride = (size_t)n * ms, dstride = (size_t)n * ny, xstride = (size_t)count * ny;
  auto rows = [&](int l) {
    return LineRows{A + l * lstride, B + l * lstride, C + l * lstride, d + l * dstride, ms};
  };
  G_.resize((size_t)n * bb);
  work_.resize((size_t)3 * ny); // lineEnds
  res_.assign((size_t)2 * nlines, 0.0);

  const Shape shape{P, rank, n, nrhs, nlines, count, periodic};
  if (P == 1 && !periodic) { // plain block Thomas
    plainSweeps<BS, NR>(shape, rows, x, xstride);
  } else {
    const int E = 2 * ny + 4 * bb + 1; // YF, YL, PF, PL, QF, QL, success flag
    if ((long long)nlines * E > INT_MAX)
      throw std::invalid_argument("SubstructuredBlockLines: too many lines for one MPI_Allgather (" +
                                  std::to_string(nlines) + ")");
    firstPass<BS, NR>(shape, rows);
    all_ends_.resize((size_t)P * nlines * E);
    if (P == 1)
      std::copy(ends_.begin(), ends_.end(), all_ends_.begin());
    else
      MPI_Allgather(ends_.data(), nlines * E, MPI_DOUBLE, all_ends_.data(), nlines * E, MPI_DOUBLE, comm);
    for (int l = 0; l < nlines;) {
      const int batch = laned<BS, NR>() && l + kThomasLanes <= nlines ? kThomasLanes : 1;
      secondPass<BS, NR>(shape, l, batch, rows, x + l * xstride, xstride);
      l += batch;
    }
    if (P > 1) MPI_Allreduce(MPI_IN_PLACE, res_.data(), 2 * nlines, MPI_DOUBLE, MPI_MAX, comm);
  }
  fail_.clear();
  for (int l = 0; l < nlines; ++l)
    if (!(res_[2 * (size_t)l] <= tolerance * std::max(res_[2 * (size_t)l + 1], 1e-300))) fail_.push_back(l);
}

namespace {
void checkArguments(MPI_Comm comm, int nlines, int nloc, bool periodic, int count) {
  int rank = 0, P = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &P);
  const bool hasR = rank + 1 < P || periodic;
  if (nlines < 0) throw std::invalid_argument("SubstructuredBlockLines: nlines must be >= 0");
  if (nloc < 2)
    throw std::invalid_argument(
        "SubstructuredBlockLines: needs >= 2 block rows per rank (nloc = " + std::to_string(nloc) + ")");
  if (count != nloc && !(count == nloc + 1 && hasR))
    throw std::invalid_argument("SubstructuredBlockLines: count must be nloc, or nloc + 1 where a next row "
                                "exists (not on the last rank of an open line)");
}
} // namespace

// Rows of the failing lines, gathered to every rank: per rank, line by line, row by row [A, B, C, d]
// (3 bs^2 + bs nrhs numbers). Each global line (nb block rows) is then solved by dgbsv: open lines in their
// natural order (2 bs - 1 sub- and super-diagonals), periodic lines with block row i at position
// pos(i) = 2 i (i <= (nb - 1) / 2) or 2 (nb - 1 - i) + 1, which puts every coupling, the wrap-around included,
// within two block positions (3 bs - 1 sub- and super-diagonals).
void SubstructuredBlockLines::fallbackLines(MPI_Comm comm, int bs, int nrhs, int nloc, const double* A,
                                            const double* B, const double* C, int ms, const double* d,
                                            bool periodic, int count, double* x) {
  long long offset = 0;
  const long long nb = gatherFailingRows(comm, bs, nrhs, nloc, A, B, C, ms, d, &offset);
  const long long N = nb * bs;
  if (N > INT_MAX / 8) throw std::runtime_error("SubstructuredBlockLines: line too long for the fallback");
  for (int f = 0; f < (int)fail_.size(); ++f) solveFailingLine(f, bs, nrhs, nb, periodic, offset, count, x);
}

// This rank's rows of the lines in fail_ into send_ (see fallbackLines for the layout).
void SubstructuredBlockLines::packFailingRows(int bs, int nrhs, int nloc, const double* A, const double* B,
                                              const double* C, int ms, const double* d) {
  const int bb = bs * bs, ny = bs * nrhs, per_row = 3 * bb + ny, nfail = (int)fail_.size();
  send_.resize((size_t)nfail * nloc * per_row);
  for (int f = 0; f < nfail; ++f) {
    const size_t l = fail_[f];
    for (int i = 0; i < nloc; ++i) {
      const size_t row = l * nloc + i;
      double* s = send_.data() + ((size_t)f * nloc + i) * per_row;
      for (int k = 0; k < bb; ++k)
        s[k] = A[row * ms + k], s[bb + k] = B[row * ms + k], s[2 * bb + k] = C[row * ms + k];
      for (int k = 0; k < ny; ++k) s[3 * bb + k] = d[row * ny + k];
    }
  }
}

// The rows of the lines in fail_ of every rank into recv_ (one MPI_Allgather of the row counts into nlocs_,
// one MPI_Allgatherv). Returns the global block rows of a line, *offset: this rank's first.
long long SubstructuredBlockLines::gatherFailingRows(MPI_Comm comm, int bs, int nrhs, int nloc,
                                                     const double* A, const double* B, const double* C,
                                                     int ms, const double* d, long long* offset) {
  int rank = 0, P = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &P);
  const int bb = bs * bs, ny = bs * nrhs, per_row = 3 * bb + ny;
  nlocs_.assign(P, nloc);
  if (P > 1) MPI_Allgather(&nloc, 1, MPI_INT, nlocs_.data(), 1, MPI_INT, comm);
  long long nb = 0;
  for (int r = 0; r < P; ++r) {
    if (r == rank) *offset = nb;
    nb += nlocs_[r];
  }
  const int nfail = (int)fail_.size();
  if ((long long)nfail * nb * per_row > INT_MAX)
    throw std::runtime_error("SubstructuredBlockLines: " + std::to_string(nfail) +
                             " lines need the gathered fallback solve, too many for one MPI_Allgatherv");
  packFailingRows(bs, nrhs, nloc, A, B, C, ms, d);
  if (P > 1) {
    counts_.resize(P);
    displs_.resize(P);
    for (int r = 0, at = 0; r < P; ++r) {
      counts_[r] = nfail * nlocs_[r] * per_row;
      displs_[r] = at;
      at += counts_[r];
    }
    recv_.resize((size_t)nfail * nb * per_row);
    MPI_Allgatherv(send_.data(), (int)send_.size(), MPI_DOUBLE, recv_.data(), counts_.data(), displs_.data(),
                   MPI_DOUBLE, comm);
  } else {
    recv_ = send_;
  }
  return nb;
}

namespace {
// Position of global block row i of a fallback line of nb block rows in its band system (see fallbackLines).
long long bandPos(long long i, long long nb, bool periodic) {
  return periodic ? (2 * i <= nb - 1 ? 2 * i : 2 * (nb - 1 - i) + 1) : i;
}
} // namespace

// The band system (band_: kl = ku sub- and super-diagonals, LAPACK band storage; rhs_: column-major right-hand
// sides) of failing line fail_[f] from its rows gathered in recv_.
void SubstructuredBlockLines::assembleFailingLine(int f, int bs, int nrhs, long long nb, bool periodic,
                                                  int kl) {
  const int P = (int)nlocs_.size(), nfail = (int)fail_.size();
  const int bb = bs * bs, per_row = 3 * bb + bs * nrhs, n = (int)(nb * bs), ku = kl, ldab = 2 * kl + ku + 1;
  band_.assign((size_t)ldab * n, 0.0);
  rhs_.assign((size_t)n * nrhs, 0.0);
  auto add = [&](long long pi, long long pj, const double* M) {
    for (int a = 0; a < bs; ++a)
      for (int b = 0; b < bs; ++b) {
        const long long row = pi * bs + a, col = pj * bs + b;
        band_[(size_t)(kl + ku + row - col) + (size_t)col * ldab] += M[a * bs + b];
      }
  };
  long long i = 0; // global block row; rank r's data start at nfail * (rows before r) * per_row
  for (int r = 0; r < P; ++r) {
    const double* base = recv_.data() + ((size_t)nfail * i + (size_t)f * nlocs_[r]) * per_row;
    for (int k = 0; k < nlocs_[r]; ++k, ++i) {
      const double* s = base + (size_t)k * per_row;
      const long long p = bandPos(i, nb, periodic);
      add(p, p, s + bb);
      if (i > 0 || periodic) add(p, bandPos((i - 1 + nb) % nb, nb, periodic), s);
      if (i + 1 < nb || periodic) add(p, bandPos((i + 1) % nb, nb, periodic), s + 2 * bb);
      for (int a = 0; a < bs; ++a)
        for (int c = 0; c < nrhs; ++c) rhs_[(size_t)c * n + p * bs + a] = s[3 * bb + a * nrhs + c];
    }
  }
}

// Band LU (dgbsv, partial pivoting) of failing line fail_[f] (nb block rows); this rank's count solution rows,
// from global block row offset, into x. Throws std::runtime_error if the line is singular.
void SubstructuredBlockLines::solveFailingLine(int f, int bs, int nrhs, long long nb, bool periodic,
                                               long long offset, int count, double* x) {
  const int ny = bs * nrhs, n = (int)(nb * bs), kl = periodic ? 3 * bs - 1 : 2 * bs - 1, ku = kl;
  const int ldab = 2 * kl + ku + 1;
  assembleFailingLine(f, bs, nrhs, nb, periodic, kl);
  ipiv_.resize(n);
  int info = 0;
  dgbsv_(&n, &kl, &ku, &nrhs, band_.data(), &ldab, ipiv_.data(), rhs_.data(), &n, &info);
  if (info != 0)
    throw std::runtime_error("SubstructuredBlockLines: line " + std::to_string(fail_[f]) +
                             " is singular (exact fallback solve, LAPACK dgbsv info " + std::to_string(info) +
                             ")");
  double* xl = x + (size_t)fail_[f] * count * ny;
  for (int k = 0; k < count; ++k) {
    const long long g = (offset + k) % nb, p = bandPos(g, nb, periodic);
    for (int a = 0; a < bs; ++a)
      for (int c = 0; c < nrhs; ++c) xl[(size_t)k * ny + a * nrhs + c] = rhs_[(size_t)c * n + p * bs + a];
  }
}

void SubstructuredBlockLines::solve(MPI_Comm comm, int bs, int nlines, int nloc, const double* A,
                                    const double* B, const double* C, const double* d, bool periodic,
                                    long long first, int count, double* x) {
  if (bs < 1 || bs > 5) throw std::invalid_argument("SubstructuredBlockLines: block size must be 1..5");
  checkArguments(comm, nlines, nloc, periodic, count);
  ++stats_.solves;
  stats_.lines += nlines;
  const int ms = bs * bs;
  switch (bs) {
  case 1:
    solveImpl<1, 1>(comm, nlines, nloc, A, B, C, ms, d, 1, periodic, count, x);
    break;
  case 2:
    solveImpl<2, 1>(comm, nlines, nloc, A, B, C, ms, d, 1, periodic, count, x);
    break;
  case 3:
    solveImpl<3, 1>(comm, nlines, nloc, A, B, C, ms, d, 1, periodic, count, x);
    break;
  case 4:
    solveImpl<4, 1>(comm, nlines, nloc, A, B, C, ms, d, 1, periodic, count, x);
    break;
  default:
    solveImpl<5, 1>(comm, nlines, nloc, A, B, C, ms, d, 1, periodic, count, x);
    break;
  }
  // Collective decision (same lines on every rank): exact gather + pivoting band LU.
  (void)first;
  stats_.fallbacks += (long long)fail_.size();
  if (!fail_.empty()) fallbackLines(comm, bs, 1, nloc, A, B, C, ms, d, periodic, count, x);
}

void SubstructuredBlockLines::solveScalar(MPI_Comm comm, int nlines, int nloc, const double* abc, int nrhs,
                                          const double* d, bool periodic, long long first, int count,
                                          double* x) {
  if (nrhs < 1) throw std::invalid_argument("SubstructuredBlockLines: nrhs must be >= 1");
  checkArguments(comm, nlines, nloc, periodic, count);
  ++stats_.solves;
  stats_.lines += nlines;
  const double *a = abc, *b = abc + 1, *c = abc + 2;
  switch (nrhs) {
  case 1:
    solveImpl<1, 1>(comm, nlines, nloc, a, b, c, 3, d, 1, periodic, count, x);
    break;
  case 3:
    solveImpl<1, 3>(comm, nlines, nloc, a, b, c, 3, d, 3, periodic, count, x);
    break;
  case 4:
    solveImpl<1, 4>(comm, nlines, nloc, a, b, c, 3, d, 4, periodic, count, x);
    break;
  case 5:
    solveImpl<1, 5>(comm, nlines, nloc, a, b, c, 3, d, 5, periodic, count, x);
    break;
  default:
    solveImpl<1, 0>(comm, nlines, nloc, a, b, c, 3, d, nrhs, periodic, count, x);
    break;
  }
  (void)first;
  stats_.fallbacks += (long long)fail_.size();
  if (!fail_.empty()) fallbackLines(comm, 1, nrhs, nloc, a, b, c, 3, d, periodic, count, x);
}

} // namespace suite::linalg
