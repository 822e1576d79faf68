// rf-char face fluxes of one grid line for the `weno5` scheme (see weno5_line_rf.hpp), with the arithmetic of
// the rf-char definition (LineGas::flux, RfChar::cellSpeeds, LineGas::roeState / roeInto, l_c f and l_c U
// summed in the order of the components; bitwise the fluxes of that definition up to the sign of zeros),
// organised as loops over the cells, faces and reconstructions ("jobs") of the line on structure-of-arrays
// data, each a function of its own with restrict arguments that the compiler vectorises. An upwinded field
// (the sign of its speed the same at the face and its two cells, the common case) needs ONE reconstruction,
// of l_c f over the five cells on its upwind side; only a field whose sign changes needs the Lax-Friedrichs
// split l_c (f +- alpha_c U) / 2 and two. Steps: per cell the flux, u, c and the per-state Roe average; per
// face the Roe eigenvectors, the field signs and, where fields split, alpha_c; per field the projections l_c
// f (and l_c U where it splits) of the face's six cells; the WENO-Z values of all jobs in one loop; h = R
// h_c. References: as weno5_line.hpp and rf_char.hpp.
#include "euler/weno5_line_rf.hpp"

#include "core/kernel_clones.hpp" // the loops over the cells, faces and jobs of a line
#include "euler/rf_char.hpp"
#include "euler/weno5.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

namespace {
// Slots of the per-cell data cs_: the flux (0 .. NV-1), then these (q: the state, NV slots).
template <int NV> struct CellSlot {
  static constexpr int u = NV, c = NV + 1, sr = NV + 2, srv = NV + 3, srH = 2 * NV + 1, q = 2 * NV + 2,
                       count = 3 * NV + 2;
};
// Whether the split faces of a sign group are many enough to project l_c U at every face of the line (a loop
// the compiler vectorises) rather than at each split face alone.
inline bool denseSplit(int count, int nface) {
  return 8 * count > nface;
}
// Slots of the per-face data fs_: L (row-major, 0 .. NV NV - 1), then these; sgn + 0, 1, 2: the signs of the
// fields u - c, u (all the middle fields), u + c as +1, -1 or 0 (RfChar::sign).
template <int NV> struct FaceSlot {
  static constexpr int u = NV * NV, c = u + 1, H = u + 2, v2 = u + 3, vt = u + 4, sgn = vt + NV - 3,
                       count = sgn + 3;
};
// The sign slot of field c.
template <int NV> constexpr int signGroup(int c) {
  return c == 0 ? 0 : c == NV - 1 ? 2 : 1;
}
} // namespace

template <int NV>
void Weno5RfLine<NV>::faceFluxes(const V* q, int nface, double alpha, bool local_lf, double g, V* h) {
  prepareCells(q, nface + 5, g);
  faceEigen(nface, g);
  const int jcap = 2 * NV * nface;
  st_.resize((size_t)5 * jcap);
  target_.resize((size_t)NV * nface);
  groupAlpha<0>(nface, alpha, local_lf);
  groupAlpha<1>(nface, alpha, local_lf);
  groupAlpha<2>(nface, alpha, local_lf);
  ndense_ = nsplit_ = 0;
  for (int c = 0; c < NV; ++c) block_[c] = denseSplit(gsplit_[signGroup<NV>(c)], nface) ? ndense_++ : -1;
  projectField<0>(nface); // the fields in turn (NV = 3, 4, 5)
  projectField<1>(nface);
  if constexpr (NV > 4) projectField<NV - 3>(nface);
  if constexpr (NV > 3) projectField<NV - 2>(nface);
  projectField<NV - 1>(nface);
  wenoValues((NV + ndense_) * nface + nsplit_);
  combine(nface, h);
}

// Per cell m of the cell-major states x (x[j ncell + m]) into cs: the flux (LineGas::flux), u and c
// (RfChar::cellSpeeds), the per-state Roe average (LineGas::roeState).
template <int NV>
SUITE_KERNEL void cellData(int ncell, double g, const double* __restrict x, double* __restrict cs) {
  using S = CellSlot<NV>;
#pragma GCC ivdep // the rows of cs are disjoint
  for (int m = 0; m < ncell; ++m) {
    auto q = [x, ncell, m](int j) { return x[j * ncell + m]; };
    double s = q(1) * q(1);
    for (int t = 2; t < NV - 1; ++t) s += q(t) * q(t);
    const double rho = q(0), u = q(1) / rho, p = (g - 1.0) * (q(NV - 1) - 0.5 * s / rho), sr = std::sqrt(rho);
    cs[m] = q(1);
    cs[ncell + m] = q(1) * u + p;
    for (int t = 2; t < NV - 1; ++t) cs[t * ncell + m] = q(t) * u;
    cs[(NV - 1) * ncell + m] = (q(NV - 1) + p) * u;
    cs[S::u * ncell + m] = u;
    cs[S::c * ncell + m] = std::sqrt(std::abs(g * p / rho));
    cs[S::sr * ncell + m] = sr;
    for (int c = 0; c < NV - 2; ++c) cs[(S::srv + c) * ncell + m] = sr * q(c + 1) / rho;
    cs[S::srH * ncell + m] = sr * ((q(NV - 1) + p) / rho);
  }
}

template <int NV> void Weno5RfLine<NV>::prepareCells(const V* q, int ncell, double g) {
  using S = CellSlot<NV>;
  ncell_ = ncell;
  cs_.resize((size_t)S::count * ncell);
  double* x = &cs_[(size_t)S::q * ncell];
  for (int m = 0; m < ncell; ++m)
    for (int j = 0; j < NV; ++j) x[j * ncell + m] = q[m][j];
  cellData<NV>(ncell, g, x, cs_.data());
}

// Per face k (cells k + 2, k + 3): LineGas::roeInto's L and the quantities of its R.
template <int NV>
SUITE_KERNEL void faceData(int nface, int nc, double g, double c2min, const double* __restrict cs,
                           double* __restrict fs) {
  using S = CellSlot<NV>;
  using F = FaceSlot<NV>;
  const int last = NV - 1;
  auto L = [fs, nface](int r, int col, int k) -> double& { return fs[(r * NV + col) * nface + k]; };
#pragma GCC ivdep // the rows of fs are disjoint
  for (int k = 0; k < nface; ++k) {
    const int a = k + 2, b = k + 3;
    const double w = 1.0 / (cs[S::sr * nc + a] + cs[S::sr * nc + b]);
    double vel[NV - 2];
    for (int c = 0; c < NV - 2; ++c) vel[c] = (cs[(S::srv + c) * nc + a] + cs[(S::srv + c) * nc + b]) * w;
    const double H = (cs[S::srH * nc + a] + cs[S::srH * nc + b]) * w, u = vel[0];
    double v2 = 0.0;
    for (int c = 0; c < NV - 2; ++c) v2 += vel[c] * vel[c];
    const double c2 = std::max((g - 1.0) * (H - 0.5 * v2), c2min), c = std::sqrt(c2);
    const double b1 = (g - 1.0) / c2, b2 = 0.5 * b1 * v2;
    L(0, 0, k) = 0.5 * (b2 + u / c), L(0, 1, k) = -0.5 * (b1 * u + 1.0 / c), L(0, last, k) = 0.5 * b1;
    L(1, 0, k) = 1.0 - b2, L(1, 1, k) = b1 * u, L(1, last, k) = -b1;
    L(last, 0, k) = 0.5 * (b2 - u / c), L(last, 1, k) = -0.5 * (b1 * u - 1.0 / c);
    L(last, last, k) = 0.5 * b1;
    for (int t = 2; t < last; ++t) {
      L(0, t, k) = L(last, t, k) = -0.5 * b1 * vel[t - 1];
      L(1, t, k) = b1 * vel[t - 1];
      L(t, 0, k) = -vel[t - 1], L(t, t, k) = 1.0;
      fs[(F::vt + t - 2) * nface + k] = vel[t - 1];
    }
    fs[F::u * nface + k] = u, fs[F::c * nface + k] = c, fs[F::H * nface + k] = H, fs[F::v2 * nface + k] = v2;
  }
}

// The signs (RfChar::sign, without branches) of the fields u - c, u, u + c at each face (faceData's u, c) and
// its two cells.
template <int NV>
SUITE_KERNEL void faceSigns(int nface, int nc, const double* __restrict cs, double* __restrict fs) {
  using S = CellSlot<NV>;
  using F = FaceSlot<NV>;
  auto sign = [](double a, double b, double c) {
    const bool pos = (a > 0.0) & (b > 0.0) & (c > 0.0), neg = (a < 0.0) & (b < 0.0) & (c < 0.0);
    const double p = pos ? 1.0 : 0.0, n = neg ? 1.0 : 0.0;
    return p - n;
  };
  const double *uc = &cs[S::u * nc + 2], *cc = &cs[S::c * nc + 2], *uf = &fs[F::u * nface],
               *cf = &fs[F::c * nface];
  double* __restrict sg = &fs[F::sgn * nface];
#pragma GCC ivdep // the rows of sg are disjoint from each other and from uf, cf
  for (int k = 0; k < nface; ++k) {
    sg[k] = sign(uc[k] - cc[k], uf[k] - cf[k], uc[k + 1] - cc[k + 1]);
    sg[nface + k] = sign(uc[k], uf[k], uc[k + 1]);
    sg[2 * nface + k] = sign(uc[k] + cc[k], uf[k] + cf[k], uc[k + 1] + cc[k + 1]);
  }
}

template <int NV> void Weno5RfLine<NV>::faceEigen(int nface, double g) {
  fs_.resize((size_t)FaceSlot<NV>::count * nface);
  // c2min: LineGas::roeInto's floor on c^2, an argument so that GCC does not specialise the loop for it (and
  // vectorises it)
  faceData<NV>(nface, ncell_, g, 1e-300, cs_.data(), fs_.data());
  faceSigns<NV>(nface, ncell_, cs_.data(), fs_.data());
}

// The Lax-Friedrichs speed of sign group GRP at face k (RfChar::face: alpha_c = (1 + 1e-12) max |lambda_c|
// over the face and its six cells), from the cells' u, c (uc, cc) and the face's (uf, cf).
template <int GRP>
inline double faceAlpha(int k, const double* uc, const double* cc, const double* uf, const double* cf) {
  auto speed = [](double u, double c) { return GRP == 0 ? u - c : GRP == 2 ? u + c : u; };
  double a = std::abs(speed(uf[k], cf[k]));
#pragma GCC unroll 6
  for (int m = 0; m < 6; ++m) a = std::max(a, std::abs(speed(uc[k + m], cc[k + m])));
  return a * (1.0 + 1e-12);
}

// ac[k] = faceAlpha at every face.
template <int GRP>
SUITE_KERNEL void faceAlphas(int nface, const double* __restrict uc, const double* __restrict cc,
                             const double* __restrict uf, const double* __restrict cf,
                             double* __restrict ac) {
  for (int k = 0; k < nface; ++k) ac[k] = faceAlpha<GRP>(k, uc, cc, uf, cf);
}

// The weights (ws, wp, wn) of splitStencils from the signs sg: (1/2, 0, 0) where 0, (0, 1, 0) where > 0, (0,
// 0, 1) where < 0.
SUITE_KERNEL void splitWeights(int nface, const double* __restrict sg, double* __restrict ws,
                               double* __restrict wp, double* __restrict wn) {
  for (int k = 0; k < nface; ++k) {
    ws[k] = sg[k] == 0.0 ? 0.5 : 0.0;
    wp[k] = sg[k] > 0.0 ? 1.0 : 0.0;
    wn[k] = sg[k] < 0.0 ? 1.0 : 0.0;
  }
}

// The split faces of sign group GRP (count gsplit_[GRP]) and, if any, their Lax-Friedrichs speeds (faceAlpha;
// alpha when !local_lf) into row 0 of the group's ac_ (every face when the group is split densely, else the
// split ones), and then the weights of splitStencils into rows 1, 2, 3.
template <int NV>
template <int GRP>
void Weno5RfLine<NV>::groupAlpha(int nface, double alpha, bool local_lf) {
  using F = FaceSlot<NV>;
  using S = CellSlot<NV>;
  const double* sg = &fs_[(size_t)(F::sgn + GRP) * nface];
  int count = 0;
  for (int k = 0; k < nface; ++k) count += sg[k] == 0.0;
  gsplit_[GRP] = count;
  if (count == 0) return;
  ac_.resize((size_t)12 * nface);
  double* ac = &ac_[(size_t)4 * GRP * nface];
  const bool dense = denseSplit(count, nface);
  if (dense) splitWeights(nface, sg, ac + nface, ac + 2 * nface, ac + 3 * nface);
  if (!local_lf) {
    std::fill(ac, ac + nface, alpha);
    return;
  }
  const int nc = ncell_;
  const double *uc = &cs_[(size_t)S::u * nc], *cc = &cs_[(size_t)S::c * nc];
  const double *uf = &fs_[(size_t)F::u * nface], *cf = &fs_[(size_t)F::c * nface];
  if (dense) {
    faceAlphas<GRP>(nface, uc, cc, uf, cf, ac);
    return;
  }
  for (int k = 0; k < nface; ++k)
    if (sg[k] == 0.0) ac[k] = faceAlpha<GRP>(k, uc, cc, uf, cf);
}

// l_C f (and, with U, l_C U) of cells k .. k + 5: L the face-major L of field C, f and qs the cell-major
// fluxes and states.
template <int NV, int C, bool U>
inline void projectCells(const double* __restrict L, const double* __restrict f, const double* __restrict qs,
                         int nface, int nc, int k, double* lf, double* lu) {
#pragma GCC unroll 6
  for (int m = 0; m < 6; ++m) lf[m] = lu[m] = 0.0;
#pragma GCC unroll 5
  for (int j = 0; j < NV; ++j)
    if (!LineGas<NV>::leftZero(C, j)) {
      const double l = L[j * nface + k];
#pragma GCC unroll 6
      for (int m = 0; m < 6; ++m) lf[m] += l * f[j * nc + k + m];
      if (U)
#pragma GCC unroll 6
        for (int m = 0; m < 6; ++m) lu[m] += l * qs[j * nc + k + m];
    }
}

// Field C at every face: l_C f of its six cells, the upwind five into row i of st (st[i jcap + k]: f+ order
// for sign sg >= 0, mirrored for sign < 0).
template <int NV, int C>
SUITE_KERNEL void upwindStencils(int nface, int nc, size_t jcap, const double* __restrict L,
                                 const double* __restrict f, const double* __restrict sg,
                                 double* __restrict st, double* __restrict spare) {
  for (int k = 0; k < nface; ++k) {
    double lf[6], lu[6];
    projectCells<NV, C, false>(L, f, nullptr, nface, nc, k, lf, lu);
    const bool up = sg[k] >= 0.0;
#pragma GCC unroll 5
    for (int i = 0; i < 5; ++i) st[i * jcap + k] = up ? lf[i] : lf[5 - i];
    spare[k] = up ? lf[5] : lf[0]; // unused: so that GCC computes both ends before the choice and vectorises
  }
}

// Field C at every face: l_C f and l_C U of the six cells; into row i of st ws l_C (f + alpha U) + wp (l_C f,
// left-biased) + wn (l_C f, right-biased), into sm l_C (f - alpha U) / 2 mirrored, with the speeds alpha =
// ac[k] and the weights (ws, wp, wn) = ac[nface + k], ac[2 nface + k], ac[3 nface + k] of groupAlpha: (1/2,
// 0, 0) at the split faces, (0, 1, 0) or (0, 0, 1) at the upwinded ones (exact, and without the branches that
// GCC would not vectorise).
template <int NV, int C>
SUITE_KERNEL void splitStencils(int nface, int nc, size_t jcap, const double* __restrict L,
                                const double* __restrict f, const double* __restrict qs,
                                const double* __restrict ac, double* __restrict st, double* __restrict sm) {
#pragma GCC ivdep // the rows i jcap + k of st and sm are disjoint (jcap >= nface)
  for (int k = 0; k < nface; ++k) {
    double lf[6], lu[6];
    projectCells<NV, C, true>(L, f, qs, nface, nc, k, lf, lu);
    const double a = ac[k], ws = ac[nface + k], wp = ac[2 * nface + k], wn = ac[3 * nface + k];
#pragma GCC unroll 5
    for (int i = 0; i < 5; ++i) {
      st[i * jcap + k] = ws * (lf[i] + a * lu[i]) + wp * lf[i] + wn * lf[5 - i];
      sm[i * jcap + k] = 0.5 * (lf[5 - i] - a * lu[5 - i]);
    }
  }
}

// One split face k of field C (the group has few): as splitStencils, the f+ stencil into st[i jcap + k], the
// f- one into sm[i jcap].
template <int NV, int C>
void splitFace(int k, int nface, int nc, size_t jcap, const double* L, const double* f, const double* qs,
               double a, double* st, double* sm) {
  double lf[6], lu[6];
  projectCells<NV, C, true>(L, f, qs, nface, nc, k, lf, lu);
  for (int i = 0; i < 5; ++i) {
    st[i * jcap + k] = 0.5 * (lf[i] + a * lu[i]);
    sm[i * jcap] = 0.5 * (lf[5 - i] - a * lu[5 - i]);
  }
}

// Field C: its upwind stencils into jobs C nface + k (f+ order for sign > 0, mirrored for sign < 0); at the
// split faces l_C (f + alpha U) / 2 into that job and l_C (f - alpha U) / 2 (mirrored) into a job of its own:
// when the group has many split faces in one loop (l_C U at every face) into the field's block of jobs (NV +
// block_[C]) nface + k, otherwise face by face into the next job of the tail (target_: the job it adds to).
template <int NV> template <int C> void Weno5RfLine<NV>::projectField(int nface) {
  const int nc = ncell_, grp = signGroup<NV>(C);
  const size_t jcap = (size_t)2 * NV * nface;
  const double* f = cs_.data();
  const double* qs = &cs_[(size_t)CellSlot<NV>::q * nc];
  const double* L = &fs_[(size_t)NV * C * nface];
  const double* sg = &fs_[(size_t)(FaceSlot<NV>::sgn + grp) * nface];
  double* st = &st_[(size_t)C * nface];
  if (block_[C] >= 0) {
    double* sm = &st_[(size_t)(NV + block_[C]) * nface];
    splitStencils<NV, C>(nface, nc, jcap, L, f, qs, &ac_[(size_t)4 * grp * nface], st, sm);
    return;
  }
  spare_.resize(nface);
  upwindStencils<NV, C>(nface, nc, jcap, L, f, sg, st, spare_.data());
  if (gsplit_[grp] == 0) return;
  for (int k = 0; k < nface; ++k)
    if (sg[k] == 0.0) {
      double* sm = &st_[(size_t)(NV + ndense_) * nface + nsplit_];
      target_[nsplit_++] = C * nface + k;
      splitFace<NV, C>(k, nface, nc, jcap, L, f, qs, ac_[(size_t)4 * grp * nface + k], st, sm);
    }
}

// w[n] = the WENO-Z value of job n (elements v[i jcap + n]), n < njob.
SUITE_KERNEL void wenoZValues(int njob, size_t jcap, const double* __restrict v, double* __restrict w) {
  for (int n = 0; n < njob; ++n)
    w[n] = weno5ZValue(v[n], v[jcap + n], v[2 * jcap + n], v[3 * jcap + n], v[4 * jcap + n]);
}

template <int NV> void Weno5RfLine<NV>::wenoValues(int njob) {
  w_.resize(njob);
  wenoZValues(njob, st_.size() / 5, st_.data(), w_.data());
}

// h[k NV + i] = (R h_c)_i at face k, h_c[c] = w[c nface + k] (LineGas::roeInto's R, its structural zeros
// skipped, summed in column order as LineGas::mul).
template <int NV>
SUITE_KERNEL void rightEigenProduct(int nface, const double* __restrict w, const double* __restrict fs,
                                    double* __restrict h) {
  using F = FaceSlot<NV>;
  const int last = NV - 1;
  for (int k = 0; k < nface; ++k) {
    double hc[NV], vt[NV];
    for (int c = 0; c < NV; ++c) hc[c] = w[c * nface + k];
    for (int t = 2; t < last; ++t) vt[t] = fs[(F::vt + t - 2) * nface + k];
    const double u = fs[F::u * nface + k], c = fs[F::c * nface + k], H = fs[F::H * nface + k];
    const double v2 = fs[F::v2 * nface + k];
    double* hk = h + (size_t)NV * k;
    hk[0] = hc[0] + hc[1] + hc[last];
    hk[1] = (u - c) * hc[0] + u * hc[1] + (u + c) * hc[last];
    for (int t = 2; t < last; ++t) hk[t] = vt[t] * hc[0] + vt[t] * hc[1] + hc[t] + vt[t] * hc[last];
    double e = (H - u * c) * hc[0] + 0.5 * v2 * hc[1];
    for (int t = 2; t < last; ++t) e += vt[t] * hc[t];
    hk[last] = e + (H + u * c) * hc[last];
  }
}

// The f- values added to their jobs, then h = R h_c.
template <int NV> void Weno5RfLine<NV>::combine(int nface, V* h) {
  double* w = w_.data();
  for (int c = 0; c < NV; ++c) // the f- values of a field's block: weight 2 ws = 1 at the split faces, else 0
    if (block_[c] >= 0) {
      const double* ws = &ac_[(size_t)(4 * signGroup<NV>(c) + 1) * nface];
      const double* wm = &w[(size_t)(NV + block_[c]) * nface];
      for (int k = 0; k < nface; ++k) w[c * nface + k] += (2.0 * ws[k]) * wm[k];
    }
  for (int s = 0; s < nsplit_; ++s) w[target_[s]] += w[(NV + ndense_) * nface + s];
  rightEigenProduct<NV>(nface, w, fs_.data(), h[0].data());
}

template class Weno5RfLine<3>;
template class Weno5RfLine<4>;
template class Weno5RfLine<5>;

} // namespace suite::euler
