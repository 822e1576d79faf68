// The face rows of one grid line for DirectionSweep (direction_sweep.hpp; methods and references there): the
// Roe eigensystem of a face from per-cell Roe states, the characteristic stencils of the split fluxes, the
// compact rows of f+ and f- and their block rows (Pade, component-wise, characteristic), and the rf-char face
// flux from the two compact solutions. Templates on the number of conserved variables; internal to
// direction_sweep.cpp.
#pragma once

#include "euler/direction_sweep.hpp"
#include "euler/rf_char.hpp"
#include "euler/weno5.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace suite::euler::line_rows {

// The Roe eigensystem of the face between cells 2 and 3 of qs[0..5], from their per-state Roe averages rs[2],
// rs[3] when given (computed once per cell: LineGas::roe(qa, qb) is roe(roeState(qa), roeState(qb)), bitwise).
template <int NV>
typename LineGas<NV>::Eigen roeEigen(const typename LineGas<NV>::V* qs,
                                     const typename LineGas<NV>::RoeState* rs, double g) {
  using G = LineGas<NV>;
  return rs ? G::roe(rs[2], rs[3], g) : G::roe(qs[2], qs[3], g);
}

// The stencils of the split fluxes at face k, characteristic-wise when e is given: wp[c][0..5] of f+, wm[c] of
// f-; unsplit (rf-char): f itself in both.
template <int NV>
void projectStencils(const typename LineGas<NV>::V* qs, const typename LineGas<NV>::V* fs, double a,
                     const typename LineGas<NV>::Eigen* e, bool unsplit, double wp[NV][6], double wm[NV][6]) {
  using G = LineGas<NV>;
  for (int m = 0; m < 6; ++m) {
    typename G::V fp, fm;
    for (int c = 0; c < NV; ++c) fp[c] = unsplit ? fs[m][c] : 0.5 * (fs[m][c] + a * qs[m][c]);
    if (e) fp = G::mul(e->L, fp);
    if (unsplit) { // f+ = f- = f: one projection
      for (int c = 0; c < NV; ++c) wp[c][m] = wm[c][m] = fp[c];
      continue;
    }
    for (int c = 0; c < NV; ++c) fm[c] = 0.5 * (fs[m][c] - a * qs[m][c]);
    if (e) fm = G::mul(e->L, fm);
    for (int c = 0; c < NV; ++c) wp[c][m] = fp[c], wm[c][m] = fm[c];
  }
}

// Characteristic (or component-wise) rows of the split fluxes at face k: rows[0][c] for f+ (left-biased),
// rows[1][c] for f- (right-biased). unsplit (rf-char): the left- and right-biased rows of f itself.
template <int NV>
void splitRows(const typename LineGas<NV>::V* qs, const typename LineGas<NV>::V* fs, double a,
               const typename LineGas<NV>::RoeState* rs, RowFunction fn, bool characteristic, double g,
               typename LineGas<NV>::Eigen* e, Row rows[2][NV], bool unsplit = false) {
  if (characteristic) *e = roeEigen<NV>(qs, rs, g);
  double wp[NV][6], wm[NV][6];
  projectStencils<NV>(qs, fs, a, characteristic ? e : nullptr, unsplit, wp, wm);
  for (int c = 0; c < NV; ++c) {
    rows[0][c] = fn(wp[c]);
    rows[1][c] = mirrorRow(fn, wm[c]);
  }
}

// The rf-char field signs and Lax-Friedrichs speeds of the face between cells 2 and 3 of qs[0..5] (rf_char.hpp).
// lam: the six cells' RfChar::cellSpeeds (computed once per cell of the line, cellSpeeds below).
template <int NV>
void rfSigns(const std::array<double, NV>* lam, const typename LineGas<NV>::Eigen& e, double alpha,
             bool local, int sgn[NV], double ac[NV]) {
  double roe[NV];
  RfChar<NV>::roeSpeeds(e, roe);
  RfChar<NV>::face(lam, roe, alpha, local, sgn, ac);
}

// RfChar::cellSpeeds of the ncell cells q into lam.
template <int NV>
void cellSpeeds(const typename LineGas<NV>::V* q, int ncell, double g,
                std::vector<std::array<double, NV>>* lam) {
  lam->resize(ncell);
  for (int m = 0; m < ncell; ++m) RfChar<NV>::cellSpeeds(q[m], g, (*lam)[m].data());
}

// LineGas::roeState of the ncell cells q into rs.
template <int NV>
void roeStates(const typename LineGas<NV>::V* q, int ncell, double g,
               std::vector<typename LineGas<NV>::RoeState>* rs) {
  rs->resize(ncell);
  for (int m = 0; m < ncell; ++m) (*rs)[m] = LineGas<NV>::roeState(q[m], g);
}

// l_c (f +- a U) / 2 of the six cells of qs, fs: the split characteristic flux of field c.
template <int NV>
void splitField(const typename LineGas<NV>::V* qs, const typename LineGas<NV>::V* fs,
                const typename LineGas<NV>::Eigen& e, int c, double a, double vp[6], double vm[6]) {
  for (int m = 0; m < 6; ++m) {
    double lf = 0.0, lu = 0.0;
    for (int j = 0; j < NV; ++j) lf += e.L[NV * c + j] * fs[m][j], lu += e.L[NV * c + j] * qs[m][j];
    vp[m] = 0.5 * (lf + a * lu);
    vm[m] = 0.5 * (lf - a * lu);
  }
}

// Zeroes block row k of the NV x NV blocks A, B, C of one split-flux system.
template <int NV> void zeroBlockRow(double* A, double* B, double* C, int k) {
  constexpr int NN = NV * NV;
  std::fill(A + NN * k, A + NN * (k + 1), 0.0);
  std::fill(B + NN * k, B + NN * (k + 1), 0.0);
  std::fill(C + NN * k, C + NN * (k + 1), 0.0);
}

// Pade row at face k: central, so the split cancels; conserved-space right-hand side. Scalar line: the row
// is linear, so the rows of f+ and f- add up to the row of f.
template <int NV>
void padeScalarRow(const typename LineGas<NV>::V* fs, RowFunction fn, int k, double* abc, double* rhs) {
  for (int c = 0; c < NV; ++c) {
    double v[6];
    for (int m = 0; m < 6; ++m) v[m] = fs[m][c];
    rhs[NV * k + c] = fn(v).r;
  }
  abc[3 * k] = 1.0 / 3.0, abc[3 * k + 1] = 1.0, abc[3 * k + 2] = 1.0 / 3.0;
}

// The same on a block line: diagonal blocks, one right-hand side per split flux. `out` is taken by value here
// and below: a copy the row functions cannot reach stays in registers across their calls.
template <int NV>
void padeBlockRow(const typename LineGas<NV>::V* qs, const typename LineGas<NV>::V* fs, double a,
                  RowFunction fn, int k, CompactLineRows out, bool unsplit) {
  constexpr int NN = NV * NV;
  for (int c = 0; c < NV; ++c) {
    double r[2];
    for (int s = 0; s < 2; ++s) {
      double v[6];
      for (int m = 0; m < 6; ++m) v[m] = unsplit ? fs[m][c] : 0.5 * (fs[m][c] + (s == 0 ? a : -a) * qs[m][c]);
      r[s] = fn(v).r;
    }
    for (int s = 0; s < 2; ++s) {
      out.A[s][NN * k + (NV + 1) * c] = 1.0 / 3.0;
      out.B[s][NN * k + (NV + 1) * c] = 1.0;
      out.C[s][NN * k + (NV + 1) * c] = 1.0 / 3.0;
      out.d[s][NV * k + c] = r[s];
    }
  }
}

// Row r of the NV x NV blocks A, B, C of one split flux from its per-field rows, component-wise: diag(a) etc.
// (characteristic rows: characteristicBlockRows).
template <int NV> void diagonalBlockRow(const Row* rows, int r, double* A, double* B, double* C) {
  for (int cc = 0; cc < NV; ++cc) {
    const bool d = r == cc;
    A[NV * r + cc] = d ? rows[r].a : 0.0;
    B[NV * r + cc] = d ? rows[r].b : 0.0;
    C[NV * r + cc] = d ? rows[r].c : 0.0;
  }
}

// Block row k of both systems from the characteristic rows of f+ and f-: R diag(a) L etc. (the sums of a
// per-system loop, with the products R_rc L_c,cc formed once for the two systems) and R r.
template <int NV>
void characteristicBlockRows(const typename LineGas<NV>::Eigen& e, const Row rows[2][NV], int k,
                             CompactLineRows out) {
  using G = LineGas<NV>;
  constexpr int NN = NV * NV;
  double rl[NV][NV][NV]; // rl[r][c][cc] = R_rc L_c,cc
  for (int r = 0; r < NV; ++r)
    for (int c = 0; c < NV; ++c)
      for (int cc = 0; cc < NV; ++cc) rl[r][c][cc] = e.R[NV * r + c] * e.L[NV * c + cc];
  for (int s = 0; s < 2; ++s) {
    typename G::V rs;
    for (int c = 0; c < NV; ++c) rs[c] = rows[s][c].r;
    const typename G::V dr = G::mul(e.R, rs);
    double *A = out.A[s] + NN * k, *B = out.B[s] + NN * k, *C = out.C[s] + NN * k;
    for (int r = 0; r < NV; ++r) {
      out.d[s][NV * k + r] = dr[r];
      double sa[NV] = {}, sb[NV] = {}, sc[NV] = {}; // each sum over c in order
      for (int c = 0; c < NV; ++c)
        for (int cc = 0; cc < NV; ++cc) {
          sa[cc] += rl[r][c][cc] * rows[s][c].a;
          sb[cc] += rl[r][c][cc] * rows[s][c].b;
          sc[cc] += rl[r][c][cc] * rows[s][c].c;
        }
      for (int cc = 0; cc < NV; ++cc)
        A[NV * r + cc] = sa[cc], B[NV * r + cc] = sb[cc], C[NV * r + cc] = sc[cc];
    }
  }
}

// Split (ENO-Pade shock, CRWENO) row or explicit closure at face k from the rows of f+ and f- (splitRows),
// characteristic-wise (eigensystem e) when `characteristic`. On a scalar line only explicit rows may reach here.
template <int NV>
void writeSplitRow(const typename LineGas<NV>::Eigen& e, const Row rows[2][NV], bool characteristic, int k,
                   CompactLineRows out) {
  using G = LineGas<NV>;
  constexpr int NN = NV * NV;
  bool explicit_row = true;
  for (int s = 0; s < 2; ++s)
    for (int c = 0; c < NV; ++c)
      explicit_row = explicit_row && rows[s][c].a == 0.0 && rows[s][c].c == 0.0 && rows[s][c].b == 1.0;
  if (out.blocks && characteristic && !explicit_row) {
    characteristicBlockRows<NV>(e, rows, k, out);
    return;
  }
  for (int s = 0; s < 2; ++s) {
    typename G::V rs;
    for (int c = 0; c < NV; ++c) rs[c] = rows[s][c].r;
    const typename G::V dr = characteristic ? G::mul(e.R, rs) : rs;
    for (int r = 0; r < NV; ++r) {
      if (!out.blocks) { // only explicit rows reach here on a scalar line
        if (!explicit_row) throw std::logic_error("DirectionSweep: compact shock row on a scalar line");
        if (s == 0) out.rhs[NV * k + r] = 0.0;
        out.rhs[NV * k + r] += dr[r];
        continue;
      }
      out.d[s][NV * k + r] = dr[r];
      if (explicit_row) { // the block row is the identity
        if (r == 0) zeroBlockRow<NV>(out.A[s], out.B[s], out.C[s], k);
        out.B[s][NN * k + (NV + 1) * r] = 1.0;
        continue;
      }
      diagonalBlockRow<NV>(rows[s], r, out.A[s] + NN * k, out.B[s] + NN * k, out.C[s] + NN * k);
    }
  }
  if (!out.blocks) out.abc[3 * k] = 0.0, out.abc[3 * k + 1] = 1.0, out.abc[3 * k + 2] = 0.0;
}

// Split (ENO-Pade shock, CRWENO) row or explicit closure at face k: rows of f+ and f-, characteristic-wise
// when `characteristic`.
template <int NV>
void splitCompactRow(const typename LineGas<NV>::V* qs, const typename LineGas<NV>::V* fs, double a,
                     const typename LineGas<NV>::RoeState* rs, RowFunction fn, bool characteristic, double g,
                     int k, CompactLineRows out, bool unsplit) {
  typename LineGas<NV>::Eigen e;
  Row rows[2][NV];
  splitRows<NV>(qs, fs, a, rs, fn, characteristic, g, &e, rows, unsplit);
  writeSplitRow<NV>(e, rows, characteristic, k, out);
}

// The face flux of rfFaceFlux at a face treated component-wise (characteristic_conditioning.hpp): every
// component as a field whose sign changes, (x0 + x1) / 2 + a (uL - uR) / 2 with the explicit WENO5-Z values
// uL, uR of the component of U and a the largest of the fields' Lax-Friedrichs speeds ac.
template <int NV>
typename LineGas<NV>::V componentwiseFaceFlux(const typename LineGas<NV>::V* qs, const double* x0,
                                              const double* x1, const double ac[NV]) {
  typename LineGas<NV>::V h;
  double a = 0.0;
  for (int c = 0; c < NV; ++c) a = std::max(a, ac[c]);
  for (int c = 0; c < NV; ++c) {
    const double uL = weno5ZValue(qs[0][c], qs[1][c], qs[2][c], qs[3][c], qs[4][c]);
    const double uR = weno5ZValue(qs[5][c], qs[4][c], qs[3][c], qs[2][c], qs[1][c]);
    h[c] = 0.5 * (x0[c] + x1[c]) + 0.5 * a * (uL - uR);
  }
  return h;
}

// rf-char face flux from the left- and right-biased compact solutions x0, x1 (conserved space) of the face
// between cells 2 and 3 of qs[0..5]: per characteristic field l_c x0 (speeds > 0), l_c x1 (< 0), else
// (l_c x0 + l_c x1) / 2 plus, when `dissipate`, the Lax-Friedrichs term alpha_c (w(l_c U) - w~(l_c U)) / 2, w
// and w~ the explicit WENO5-Z left and right values (the compact systems carry f only). componentwise: the face is
// treated component-wise (componentwiseFaceFlux; characteristic_conditioning.hpp).
template <int NV>
typename LineGas<NV>::V rfFaceFlux(const typename LineGas<NV>::V* qs,
                                   const typename LineGas<NV>::RoeState* rs,
                                   const std::array<double, NV>* lam, const double* x0, const double* x1,
                                   bool dissipate, double alpha, bool local, double g, bool componentwise) {
  using G = LineGas<NV>;
  const typename G::Eigen e = roeEigen<NV>(qs, rs, g);
  int sgn[NV];
  double ac[NV];
  rfSigns<NV>(lam, e, alpha, local, sgn, ac);
  if (componentwise) return componentwiseFaceFlux<NV>(qs, x0, x1, ac);
  typename G::V X0, X1, hc;
  for (int c = 0; c < NV; ++c) X0[c] = x0[c], X1[c] = x1[c];
  const typename G::V y0 = G::mul(e.L, X0), y1 = G::mul(e.L, X1);
  for (int c = 0; c < NV; ++c) {
    hc[c] = sgn[c] > 0 ? y0[c] : sgn[c] < 0 ? y1[c] : 0.5 * (y0[c] + y1[c]);
    if (sgn[c] != 0 || !dissipate) continue;
    double lu[6];
    for (int m = 0; m < 6; ++m) {
      lu[m] = 0.0;
      for (int j = 0; j < NV; ++j) lu[m] += e.L[NV * c + j] * qs[m][j];
    }
    const double uL = weno5ZValue(lu[0], lu[1], lu[2], lu[3], lu[4]);
    const double uR = weno5ZValue(lu[5], lu[4], lu[3], lu[2], lu[1]);
    hc[c] += 0.5 * ac[c] * (uL - uR);
  }
  return G::mul(e.R, hc);
}

} // namespace suite::euler::line_rows
