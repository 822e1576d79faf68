// Block Thomas sweeps on four lines at once, one per lane (see block_thomas_lanes.hpp): thomasLanes (the
// one-rank sweep, pass 2) and endsLanes (pass 1). Every step mirrors the one-line code it must match bit for
// bit: lineSolve<BS, 1> and lineEnds<BS, 1> (substructured_block_lines.cpp) for the sweeps, SmallLU<BS>::factor
// / solveFast (block_kernels.hpp) for the diagonal blocks, subtractProduct / addProduct for the products,
// flushSpikes; the loops keep their order of operations per element. (Sharing the one-line code, generic in
// the number type, would turn its pivot branches into selects there too.)
#include "linalg/block_thomas_lanes.hpp"

#include "core/kernel_clones.hpp"

#include <cstdint>

namespace suite::linalg {
namespace {

using V = double __attribute__((vector_size(32)));  // one double of each of the four lines
using M = int64_t __attribute__((vector_size(32))); // lane masks (all bits set: true) and pivot indices
using VU = double __attribute__((vector_size(32), aligned(8))); // four consecutive doubles of one line

#define THOMAS_INLINE inline __attribute__((always_inline))

THOMAS_INLINE V absOf(V x) { // the sign bit cleared, as fabs
  const M mask = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};
  return (V)((M)x & mask);
}

// The 4 x 4 transpose of r (row l: four consecutive doubles of line l) into out (out[k]: double k of every
// line), and back (the transpose is its own inverse): two shuffle stages.
THOMAS_INLINE void transpose4(const V* r, V* out) {
  const V t0 = __builtin_shuffle(r[0], r[1], M{0, 4, 2, 6}),
          t1 = __builtin_shuffle(r[0], r[1], M{1, 5, 3, 7});
  const V t2 = __builtin_shuffle(r[2], r[3], M{0, 4, 2, 6}),
          t3 = __builtin_shuffle(r[2], r[3], M{1, 5, 3, 7});
  out[0] = __builtin_shuffle(t0, t2, M{0, 1, 4, 5});
  out[1] = __builtin_shuffle(t1, t3, M{0, 1, 4, 5});
  out[2] = __builtin_shuffle(t0, t2, M{2, 3, 6, 7});
  out[3] = __builtin_shuffle(t1, t3, M{2, 3, 6, 7});
}

// out[j] = (p[0][j], .., p[3][j]) for j < len.
THOMAS_INLINE void loadLanes(const double* const* p, long long len, V* out) {
  long long j = 0;
  for (; j + 4 <= len; j += 4) {
    V r[kThomasLanes];
    for (int l = 0; l < kThomasLanes; ++l) r[l] = *reinterpret_cast<const VU*>(p[l] + j);
    transpose4(r, out + j);
  }
  for (; j < len; ++j) out[j] = V{p[0][j], p[1][j], p[2][j], p[3][j]};
}

// p[l][j] = in[j][l] for j < len.
THOMAS_INLINE void storeLanes(const V* in, long long len, double* const* p) {
  long long j = 0;
  for (; j + 4 <= len; j += 4) {
    V r[kThomasLanes];
    transpose4(in + j, r);
    for (int l = 0; l < kThomasLanes; ++l) *reinterpret_cast<VU*>(p[l] + j) = r[l];
  }
  for (; j < len; ++j)
    for (int l = 0; l < kThomasLanes; ++l) p[l][j] = in[j][l];
}

// Block row i of `member` (A, B or C) of the four lines: out[e] holds entry e of every line.
template <int bb>
THOMAS_INLINE void loadBlock(const LaneLine* L, const double* LaneLine::*member, int i, V* out) {
  const double* p[kThomasLanes];
  for (int l = 0; l < kThomasLanes; ++l) p[l] = (L[l].*member) + (long long)i * L[l].ms;
  for (int e = 0; e + 4 <= bb; e += 4) {
    V r[kThomasLanes];
    for (int l = 0; l < kThomasLanes; ++l) r[l] = *reinterpret_cast<const VU*>(p[l] + e);
    transpose4(r, out + e);
  }
  for (int e = bb / 4 * 4; e < bb; ++e) out[e] = V{p[0][e], p[1][e], p[2][e], p[3][e]};
}

// SmallLU<BS>::factor on the four blocks in lu (overwritten by their LU factors, rows exchanged as there),
// the pivot rows in piv, the reciprocals of the pivots in inv; false when a lane's pivot is rejected.
template <int BS> THOMAS_INLINE bool factorLanes(V* lu, M* piv, V* inv) {
  V scale = {0, 0, 0, 0};
  for (int e = 0; e < BS * BS; ++e) {
    const V a = absOf(lu[e]);
    scale = scale < a ? a : scale; // std::max(scale, |M_e|): a NaN entry leaves scale as it is
  }
  M rejected = {0, 0, 0, 0};
  for (int k = 0; k < BS; ++k) {
    M p = {k, k, k, k};
    V best = absOf(lu[k * BS + k]);
    for (int i = k + 1; i < BS; ++i) { // the first largest magnitude, as the strict > of the one-line search
      const V a = absOf(lu[i * BS + k]);
      const M larger = a > best;
      p = larger ? M{i, i, i, i} : p;
      best = larger ? a : best;
    }
    piv[k] = p;
    rejected |= ~(best > 1e-14 * scale); // also a NaN pivot
    for (int i = k + 1; i < BS; ++i) {   // exchange rows k and p where p = i
      const M swap = p == M{i, i, i, i};
      for (int j = 0; j < BS; ++j) {
        const V rk = lu[k * BS + j], ri = lu[i * BS + j];
        lu[k * BS + j] = swap ? ri : rk;
        lu[i * BS + j] = swap ? rk : ri;
      }
    }
    for (int i = k + 1; i < BS; ++i) {
      const V l = lu[i * BS + k] /= lu[k * BS + k];
      for (int j = k + 1; j < BS; ++j) lu[i * BS + j] -= l * lu[k * BS + j];
    }
  }
  for (int k = 0; k < BS; ++k) inv[k] = 1.0 / lu[k * BS + k];
  for (int l = 0; l < kThomasLanes; ++l)
    if (rejected[l]) return false;
  return true;
}

// SmallLU<BS>::solveFast<NC> on the four blocks: X is BS rows of NC lane-columns.
template <int BS, int NC> THOMAS_INLINE void solveLanes(const V* lu, const M* piv, const V* inv, V* X) {
  for (int k = 0; k < BS; ++k)
    for (int i = k + 1; i < BS; ++i) {
      const M swap = piv[k] == M{i, i, i, i};
      for (int c = 0; c < NC; ++c) {
        const V xk = X[k * NC + c], xi = X[i * NC + c];
        X[k * NC + c] = swap ? xi : xk;
        X[i * NC + c] = swap ? xk : xi;
      }
    }
  for (int i = 1; i < BS; ++i)
    for (int k = 0; k < i; ++k)
      for (int c = 0; c < NC; ++c) X[i * NC + c] -= lu[i * BS + k] * X[k * NC + c];
  for (int i = BS - 1; i >= 0; --i) {
    for (int k = i + 1; k < BS; ++k)
      for (int c = 0; c < NC; ++c) X[i * NC + c] -= lu[i * BS + k] * X[k * NC + c];
    for (int c = 0; c < NC; ++c) X[i * NC + c] *= inv[i];
  }
}

// Y (BS x NC) -= Mx (BS x BS) X (BS x NC), as subtractProduct<BS, NC>.
template <int BS, int NC> THOMAS_INLINE void subtractLanes(const V* Mx, const V* X, V* Y) {
  for (int a = 0; a < BS; ++a)
    for (int b = 0; b < BS; ++b) {
      const V v = Mx[a * BS + b];
      for (int c = 0; c < NC; ++c) Y[a * NC + c] -= v * X[b * NC + c];
    }
}

// Y (BS x NC) += Mx (BS x BS) X (BS x NC), as addProduct<BS, NC>.
template <int BS, int NC> THOMAS_INLINE void addLanes(const V* Mx, const V* X, V* Y) {
  for (int a = 0; a < BS; ++a)
    for (int b = 0; b < BS; ++b) {
      const V v = Mx[a * BS + b];
      for (int c = 0; c < NC; ++c) Y[a * NC + c] += v * X[b * NC + c];
    }
}

// The forward sweep of row i (lineSolve<BS, 1>): Bh = B_i - A_i G_{i-1}, y_i = Bh^-1 (d_i - A_i y_{i-1}),
// G_i = Bh^-1 C_i (not on the last row).
template <int BS> THOMAS_INLINE bool forwardRow(int n, int i, const LaneLine* L, V* G, V* Y) {
  constexpr int bb = BS * BS;
  V Bh[bb], *y = Y + i * BS; // y: d_i on entry
  loadBlock<bb>(L, &LaneLine::B, i, Bh);
  if (i > 0) {
    V A[bb];
    loadBlock<bb>(L, &LaneLine::A, i, A);
    subtractLanes<BS, BS>(A, G + (i - 1) * bb, Bh);
    subtractLanes<BS, 1>(A, Y + (i - 1) * BS, y);
  }
  M piv[BS];
  V inv[BS];
  if (!factorLanes<BS>(Bh, piv, inv)) return false;
  solveLanes<BS, 1>(Bh, piv, inv, y);
  if (i + 1 < n) {
    V* Gi = G + i * bb;
    loadBlock<bb>(L, &LaneLine::C, i, Gi);
    solveLanes<BS, BS>(Bh, piv, inv, Gi);
  }
  return true;
}

// y -= (block row i of `member`) x for the four lines' neighbour values x (`side`: xl or xr), as lineSolve
// moves them to the right-hand side before the sweep reaches the row.
template <int BS>
THOMAS_INLINE void neighbourTerm(const LaneLine* L, const double* LaneLine::*member,
                                 const double* LaneLine::*side, int i, V* y) {
  V Mx[BS * BS], x[BS];
  loadBlock<BS * BS>(L, member, i, Mx);
  for (int a = 0; a < BS; ++a) x[a] = V{(L[0].*side)[a], (L[1].*side)[a], (L[2].*side)[a], (L[3].*side)[a]};
  subtractLanes<BS, 1>(Mx, x, y);
}

template <int BS> THOMAS_INLINE bool thomasLanes(int n, const LaneLine* L, double* work) {
  constexpr int bb = BS * BS;
  V *G = reinterpret_cast<V*>(work), *Y = G + (long long)n * bb;
  const double* d[kThomasLanes] = {L[0].d, L[1].d, L[2].d, L[3].d};
  loadLanes(d, (long long)n * BS, Y);
  if (L[0].xl) neighbourTerm<BS>(L, &LaneLine::A, &LaneLine::xl, 0, Y);
  if (L[0].xr) neighbourTerm<BS>(L, &LaneLine::C, &LaneLine::xr, n - 1, Y + (n - 1) * BS);
  for (int i = 0; i < n; ++i)
    if (!forwardRow<BS>(n, i, L, G, Y)) return false;
  for (int i = n - 2; i >= 0; --i) subtractLanes<BS, 1>(G + i * bb, Y + (i + 1) * BS, Y + i * BS);
  double* const x[kThomasLanes] = {L[0].x, L[1].x, L[2].x, L[3].x};
  storeLanes(Y, (long long)n * BS, x);
  return true;
}

// X (BS x NC) = alive ? Xnew : X, lane by lane: a spike that died in a lane (all zero) keeps its value there,
// as the one-line sweep skips its updates.
template <int N> THOMAS_INLINE void keepWhereDead(M alive, const V* fresh, V* x) {
  for (int e = 0; e < N; ++e) x[e] = alive ? fresh[e] : x[e];
}

// A lane mask: which lanes of the BS x BS block x hold a nonzero entry (anyNonzero of the one-line sweep).
template <int N> THOMAS_INLINE M nonzeroLanes(const V* x) {
  M any = {0, 0, 0, 0};
  for (int e = 0; e < N; ++e) any |= x[e] != 0.0;
  return any;
}

THOMAS_INLINE bool anyLane(M m) {
  return m[0] || m[1] || m[2] || m[3];
}

// flushSpikes: entries below 1e-200 in magnitude set to zero.
template <int N> THOMAS_INLINE void flushLanes(V* x) {
  for (int e = 0; e < N; ++e) x[e] = absOf(x[e]) < 1e-200 ? V{0, 0, 0, 0} : x[e];
}

// The spikes of pass 1 (lineEnds of substructured_block_lines.cpp) at row i: rp (the left spike P, reduced),
// W (the unrolled back substitution), their lane masks of being alive, and the accumulated first rows.
template <int BS> struct EndsLanes {
  V G[BS * BS] = {}, rp[BS * BS] = {}, W[BS * BS] = {}, rq[BS * BS] = {}, accP[BS * BS] = {};
  V accY[BS] = {}, ryp[BS] = {};
  M pAlive, wAlive = {-1, -1, -1, -1};
};

// Row i of pass 1 on four lines (lineEnds, row by row in the same order; the updates of a spike that died in a
// lane are computed and discarded there). ry: d_i on entry.
template <int BS>
THOMAS_INLINE bool endsRow(int n, int i, const LaneLine* L, bool hasR, V* ry, EndsLanes<BS>* s) {
  constexpr int bb = BS * BS;
  V Bh[bb], tmp[bb];
  loadBlock<bb>(L, &LaneLine::B, i, Bh);
  if (i == 0) {
    if (anyLane(s->pAlive)) { // hasL: -A_0
      loadBlock<bb>(L, &LaneLine::A, 0, tmp);
      for (int e = 0; e < bb; ++e) s->rp[e] = -tmp[e];
    }
  } else {
    V A[bb];
    loadBlock<bb>(L, &LaneLine::A, i, A);
    subtractLanes<BS, BS>(A, s->G, Bh);
    subtractLanes<BS, 1>(A, s->ryp, ry);
    if (anyLane(s->pAlive)) {
      for (int e = 0; e < bb; ++e) tmp[e] = V{0, 0, 0, 0};
      subtractLanes<BS, BS>(A, s->rp, tmp);
      keepWhereDead<bb>(s->pAlive, tmp, s->rp);
    }
  }
  M piv[BS];
  V inv[BS];
  if (!factorLanes<BS>(Bh, piv, inv)) return false;
  solveLanes<BS, 1>(Bh, piv, inv, ry);
  if (anyLane(s->pAlive)) {
    for (int e = 0; e < bb; ++e) tmp[e] = s->rp[e];
    solveLanes<BS, BS>(Bh, piv, inv, tmp);
    flushLanes<bb>(tmp);
    keepWhereDead<bb>(s->pAlive, tmp, s->rp);
    s->pAlive &= nonzeroLanes<bb>(s->rp);
  }
  if (i + 1 < n) {
    loadBlock<bb>(L, &LaneLine::C, i, s->G);
    solveLanes<BS, BS>(Bh, piv, inv, s->G);
  } else if (hasR) {
    loadBlock<bb>(L, &LaneLine::C, i, s->rq);
    for (int e = 0; e < bb; ++e) s->rq[e] = -s->rq[e];
    solveLanes<BS, BS>(Bh, piv, inv, s->rq);
  }
  return true;
}

// The first rows x_0 = sum_i W_i R_i accumulated after row i, and W_{i+1} = -W_i G_i (lineEnds).
template <int BS> THOMAS_INLINE void endsAccumulate(int n, int i, const V* ry, EndsLanes<BS>* s) {
  constexpr int bb = BS * BS;
  V tmp[bb];
  if (i == 0) {
    for (int a = 0; a < BS; ++a) s->accY[a] = ry[a];
    for (int e = 0; e < bb; ++e) s->accP[e] = s->rp[e];
  } else if (anyLane(s->wAlive)) {
    V y[BS];
    for (int a = 0; a < BS; ++a) y[a] = s->accY[a];
    addLanes<BS, 1>(s->W, ry, y);
    keepWhereDead<BS>(s->wAlive, y, s->accY);
    const M both = s->wAlive & s->pAlive;
    if (anyLane(both)) {
      for (int e = 0; e < bb; ++e) tmp[e] = s->accP[e];
      addLanes<BS, BS>(s->W, s->rp, tmp);
      keepWhereDead<bb>(both, tmp, s->accP);
    }
  }
  if (i + 1 < n && anyLane(s->wAlive)) {
    if (i == 0) {
      for (int e = 0; e < bb; ++e) s->W[e] = -s->G[e];
    } else {
      for (int e = 0; e < bb; ++e) tmp[e] = V{0, 0, 0, 0};
      subtractLanes<BS, BS>(s->W, s->G, tmp);
      keepWhereDead<bb>(s->wAlive, tmp, s->W);
    }
    flushLanes<bb>(s->W);
    s->wAlive &= nonzeroLanes<bb>(s->W);
  }
}

// Pass 1 on four lines: the end rows [YF, YL, PF, PL, QF, QL] of each into out[l] (lineEnds' layout).
template <int BS>
THOMAS_INLINE bool endsLanes(int n, const LaneLine* L, bool hasL, bool hasR, double* work,
                             double* const* out) {
  constexpr int bb = BS * BS;
  V* D = reinterpret_cast<V*>(work);
  const double* d[kThomasLanes] = {L[0].d, L[1].d, L[2].d, L[3].d};
  loadLanes(d, (long long)n * BS, D);
  EndsLanes<BS> s;
  s.pAlive = hasL ? M{-1, -1, -1, -1} : M{0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    V* ry = D + i * BS;
    if (!endsRow<BS>(n, i, L, hasR, ry, &s)) return false;
    endsAccumulate<BS>(n, i, ry, &s);
    for (int a = 0; a < BS; ++a) s.ryp[a] = ry[a];
  }
  V QF[bb] = {};
  if (hasR && anyLane(s.wAlive)) {
    V tmp[bb] = {};
    addLanes<BS, BS>(s.W, s.rq, tmp);
    keepWhereDead<bb>(s.wAlive, tmp, QF);
  }
  for (int l = 0; l < kThomasLanes; ++l) {
    double *YF = out[l], *YL = YF + BS, *PF = YL + BS, *PL = PF + bb, *QFl = PL + bb, *QL = QFl + bb;
    for (int a = 0; a < BS; ++a) YF[a] = s.accY[a][l], YL[a] = s.ryp[a][l];
    for (int e = 0; e < bb; ++e)
      PF[e] = s.accP[e][l], PL[e] = s.rp[e][l], QFl[e] = QF[e][l], QL[e] = hasR ? s.rq[e][l] : 0.0;
  }
  return true;
}

SUITE_KERNEL bool thomasLanes3(int n, const LaneLine* L, double* w) {
  return thomasLanes<3>(n, L, w);
}
SUITE_KERNEL bool thomasLanes4(int n, const LaneLine* L, double* w) {
  return thomasLanes<4>(n, L, w);
}
SUITE_KERNEL bool thomasLanes5(int n, const LaneLine* L, double* w) {
  return thomasLanes<5>(n, L, w);
}
SUITE_KERNEL bool endsLanes3(int n, const LaneLine* L, bool hl, bool hr, double* w, double* const* out) {
  return endsLanes<3>(n, L, hl, hr, w, out);
}
SUITE_KERNEL bool endsLanes4(int n, const LaneLine* L, bool hl, bool hr, double* w, double* const* out) {
  return endsLanes<4>(n, L, hl, hr, w, out);
}
SUITE_KERNEL bool endsLanes5(int n, const LaneLine* L, bool hl, bool hr, double* w, double* const* out) {
  return endsLanes<5>(n, L, hl, hr, w, out);
}

} // namespace

bool blockThomasLanes(int bs, int n, const LaneLine* lines, double* work) {
  switch (bs) {
  case 3:
    return thomasLanes3(n, lines, work);
  case 4:
    return thomasLanes4(n, lines, work);
  case 5:
    return thomasLanes5(n, lines, work);
  default:
    return false;
  }
}

bool blockEndsLanes(int bs, int n, const LaneLine* lines, bool hasL, bool hasR, double* work,
                    double* const* ends) {
  switch (bs) {
  case 3:
    return endsLanes3(n, lines, hasL, hasR, work, ends);
  case 4:
    return endsLanes4(n, lines, hasL, hasR, work, ends);
  case 5:
    return endsLanes5(n, lines, hasL, hasR, work, ends);
  default:
    return false;
  }
}

} // namespace suite::linalg
