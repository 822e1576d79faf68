// Interface fluxes of all lines of one grid direction (see direction_sweep.hpp for the method and
// references).
#include "euler/direction_sweep.hpp"

#include "core/error_handler.hpp"
#include "euler/characteristic_conditioning.hpp"
#include "euler/crweno5.hpp"
#include "euler/enopade6.hpp"
#include "euler/line_rows.hpp"
#include "euler/line_segments.hpp"
#include "euler/rf_char.hpp"
#include "euler/weno5.hpp"

#include <petsclog.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace suite::euler {

using namespace line_rows; // the face rows of a line (line_rows.hpp)

namespace {
// -log_view stage of the compact line solves (nested inside the app's per-direction stages).
PetscLogStage lineSolveStage() {
  static PetscLogStage stage = -1;
  if (stage < 0 && PetscLogStageRegister("Euler line solves", &stage)) stage = -1;
  return stage;
}
struct StageScope {
  bool on;
  StageScope() : on(lineSolveStage() >= 0 && !PetscLogStagePush(lineSolveStage())) {}
  ~StageScope() {
    if (on) (void)PetscLogStagePop();
  }
};

// -log_view events of the pencil transposes (LineTranspose::gather, LineTranspose::scatter) and of the positivity
// limiter (limitFaces).
PetscLogEvent sweepEvent(int which) {
  static const std::array<PetscLogEvent, 3> ev = [] {
    std::array<PetscLogEvent, 3> e = {-1, -1, -1};
    PetscClassId cls = 0;
    if (PetscClassIdRegister("Euler lines", &cls) || PetscLogEventRegister("LineTransposeGath", cls, &e[0]) ||
        PetscLogEventRegister("LineTransposeScat", cls, &e[1]) ||
        PetscLogEventRegister("PositivityLimit", cls, &e[2]))
      e = {-1, -1, -1};
    return e;
  }();
  return ev[which];
}
struct EventScope {
  PetscLogEvent ev;
  explicit EventScope(PetscLogEvent e) : ev(e) {
    if (ev >= 0) (void)PetscLogEventBegin(ev, 0, 0, 0, 0);
  }
  ~EventScope() {
    if (ev >= 0) (void)PetscLogEventEnd(ev, 0, 0, 0, 0);
  }
};

// Fault injection for the reliability tests: with SUITE_FAULT_LINE_SOLVE_RANK=R in the environment, the whole-line
// solves of MPI_COMM_WORLD rank R fail (as a singular line would), to check that the job stops cleanly.
bool faultInjected() {
  static const int rank = [] {
    const char* s = std::getenv("SUITE_FAULT_LINE_SOLVE_RANK");
    return s ? std::atoi(s) : -1;
  }();
  if (rank < 0) return false;
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  return me == rank;
}

inline bool boundaryFace(bool periodic, long long iface, long long n) {
  return !periodic && (iface == 0 || iface == n);
}
} // namespace

template <int NV> void DirectionSweep<NV>::prepareLine(const V* q, int xm, double alpha_global) {
  using G = LineGas<NV>;
  const double g = opt_.gamma;
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  const bool local = opt_.local_lf && !scheme_->compact; // compact rows need one alpha along the line
  f_.resize(ncell);
  speed_.resize(ncell);
  for (int m = 0; m < ncell; ++m) {
    f_[m] = G::flux(q[m], g);
    if (local) speed_[m] = G::maxSpeed(q[m], g);
  }
  alpha_.resize(nface);
  for (int k = 0; k < nface; ++k) {
    double a = alpha_global;
    if (local) {
      a = 0.0;
      for (int m = 0; m < 6; ++m) a = std::max(a, speed_[k + m]);
      a *= 1.0 + 1e-12;
    }
    alpha_[k] = a;
  }
}

template <int NV>
void DirectionSweep<NV>::lineExplicit(const V* q, long long n, long long xs, int xm, bool periodic,
                                      double alpha, V* h) {
  using G = LineGas<NV>;
  const double g = opt_.gamma;
  if (scheme_->state_riemann) { // muscl2: no flux splitting
    for (int k = 0; k <= xm; ++k) h[k] = G::muscl2(q + k + 1, g);
    return;
  }
  if (scheme_->shock_row == weno5Row && scheme_->boundary_shock == weno5Row) { // the same rows, vectorised
    stats_.componentwise_faces += weno5_.faceFluxes(q, xm + 1, alpha, opt_.local_lf, opt_.characteristic,
                                                    opt_.rf_char, g, stage_flux_scale_, h);
    return;
  }
  prepareLine(q, xm, alpha);
  const int ncell = xm + 2 * kGhost;
  if (opt_.characteristic) roeStates<NV>(q, ncell, g, &rs_);
  if (rfChar()) cellSpeeds<NV>(q, ncell, g, &lam_);
  for (int k = 0; k <= xm; ++k) {
    const bool boundary = boundaryFace(periodic, xs + k, n);
    const RowFunction fn = boundary ? scheme_->boundary_shock : scheme_->shock_row;
    // a face treated component-wise (illConditioned) is split by Lax-Friedrichs, as with -characteristic false
    const bool ch = opt_.characteristic && !illConditioned(q + k);
    stats_.componentwise_faces += opt_.characteristic && !ch;
    typename G::Eigen e;
    Row rows[2][NV];
    splitRows<NV>(q + k, f_.data() + k, alpha_[k], ch ? rs_.data() + k : nullptr, fn, ch, g, &e, rows,
                  rfChar() && ch);
    V hc;
    for (int c = 0; c < NV; ++c) hc[c] = rows[0][c].r / rows[0][c].b + rows[1][c].r / rows[1][c].b;
    if (rfChar() && ch) { // rf-char: the upwind row of l_c f, or the split rows where the sign changes
      int sgn[NV];
      double ac[NV];
      rfSigns<NV>(lam_.data() + k, e, alpha, opt_.local_lf, sgn, ac);
      for (int c = 0; c < NV; ++c) {
        hc[c] = sgn[c] > 0 ? rows[0][c].r / rows[0][c].b : rows[1][c].r / rows[1][c].b;
        if (sgn[c] != 0) continue;
        double vp[6], vm[6];
        splitField<NV>(q + k, f_.data() + k, e, c, ac[c], vp, vm);
        const Row rp = fn(vp), rm = mirrorRow(fn, vm);
        hc[c] = rp.r / rp.b + rm.r / rm.b;
      }
    }
    h[k] = ch ? G::mul(e.R, hc) : hc;
  }
}

template <int NV>
DirectionSweep<NV>::DirectionSweep(const SchemeInfo* scheme, const LineOptions& options)
    : scheme_(scheme), opt_(options), theta_(shockResolutionRatio(options.shock_ppw)) {}

// The ENO-Pade sensor (enopade6.hpp) on rows 0 .. nrow-1 of a line of ncell cells (row k reads cells
// k .. k+5): shock[k], never at a boundary face; returns whether any row is a shock row.
template <int NV>
bool DirectionSweep<NV>::markShockRows(const V* q, int ncell, long long n, long long xs, int nrow,
                                       bool periodic, char* shock) {
  using G = LineGas<NV>;
  rho_.resize(ncell);
  p_.resize(ncell);
  for (int m = 0; m < ncell; ++m) {
    rho_[m] = q[m][0];
    p_[m] = G::pressure(q[m], opt_.gamma);
  }
  enoPadeShockRows(rho_.data(), p_.data(), nrow, opt_.shock_threshold, theta_, &sensor_work_, shock);
  bool any = false;
  for (int k = 0; k < nrow; ++k) {
    shock[k] = shock[k] && !boundaryFace(periodic, xs + k, n);
    any = any || shock[k];
  }
  return any;
}

// Marks the shock rows of a line (shock[k] for its nown owned rows; boundary rows are explicit closures, never
// shock rows here) and returns whether any is a compact shock row, i.e. the line needs the block solve.
template <int NV>
bool DirectionSweep<NV>::lineNeedsBlocks(const V* q, int ncell, long long n, long long xs, int nown,
                                         bool periodic, char* shock) {
  if (!scheme_->hybrid) { // CRWENO rows everywhere
    for (int k = 0; k < nown; ++k) shock[k] = !boundaryFace(periodic, xs + k, n);
    return true;
  }
  const bool any = markShockRows(q, ncell, n, xs, nown, periodic, shock);
  stats_.sensor_rows += nown;
  for (int k = 0; k < nown; ++k) stats_.shock_rows += shock[k];
  return any;
}

template <int NV>
void DirectionSweep<NV>::shockFaces(const V* q, int nlines, long long n, long long xs, int xm, bool periodic,
                                    char* shock) {
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  for (int l = 0; l < nlines; ++l) {
    char* sl = shock + (size_t)l * nface;
    if (scheme_->hybrid)
      markShockRows(q + (size_t)l * ncell, ncell, n, xs, nface, periodic, sl);
    else
      std::fill(sl, sl + nface, 0);
    if (opt_.segmented) // rows reaching into a solid obstacle: its wall rows are closures, never shock rows
      for (int k = 0; k < nface; ++k)
        for (int m = 0; m < 6; ++m) sl[k] = q[(size_t)l * ncell + k + m][0] == kSolidSentinel ? 0 : sl[k];
  }
}

template <int NV>
void DirectionSweep<NV>::lineCompactRows(const V* q, long long n, long long xs, int xm, int nown,
                                         bool periodic, double alpha, const char* shocks,
                                         CompactLineRows out) {
  prepareLine(q, xm, alpha);
  const bool unsplit = out.blocks && rfChar(); // rf-char: the two systems of f (rfCombine picks per field)
  const bool roe = out.blocks && opt_.characteristic;
  if (roe) roeStates<NV>(q, xm + 2 * kGhost, opt_.gamma, &rs_);
  const RowsFunction batched = roe ? batchedRows(scheme_->shock_row) : nullptr;
  batch_.clear();
  for (int k = 0; k < nown; ++k) {
    const bool boundary = boundaryFace(periodic, xs + k, n);
    const V* qs = q + k;
    const V* fs = f_.data() + k;
    const double a = alpha_[k];
    const bool shock = boundary ? !scheme_->hybrid : shocks[k] != 0;
    const RowFunction fn = boundary ? (shock ? scheme_->boundary_shock : scheme_->boundary_smooth)
                                    : (shock ? scheme_->shock_row : scheme_->smooth_row);
    if (out.blocks && !(shock && !boundary)) // rows that set only diagonals (Pade, explicit closures)
      for (int s = 0; s < 2; ++s) zeroBlockRow<NV>(out.A[s], out.B[s], out.C[s], k);
    if (!shock && !boundary && !out.blocks)
      padeScalarRow<NV>(fs, fn, k, out.abc, out.rhs);
    else if (!shock && !boundary)
      padeBlockRow<NV>(qs, fs, a, fn, k, out, unsplit);
    else if (batched && !boundary) // an interior shock row: with the others below
      batch_.push_back(k);
    else // boundary closures (and scalar lines' rows): component-wise too where illConditioned
      splitCompactRow<NV>(qs, fs, a, roe ? rs_.data() + k : nullptr, fn,
                          opt_.characteristic && !illConditioned(qs), opt_.gamma, k, out, unsplit);
  }
  if (!batch_.empty()) batchedSplitRows(q, batched, unsplit, out);
}

// The interior shock rows of the faces batch_ of a block line (lineCompactRows, characteristic rows): per face
// its Roe eigensystem and projected stencils (as splitRows), the rows of all of them in one call of the
// scheme's batched row function (compact_rows_batch.hpp: bitwise its RowFunction's), then the block rows
// (writeSplitRow). Stencil lane (2 j + s) NV + c: face j of the call, f+ (s = 0) or mirrored f- (s = 1), field
// c. With rf-char, the hybrid's faces where every field is upwinded the same way (supersonicFace) take the
// CRWENO5-Z rows (crweno5Row: WENO-Z weights, p = 2) instead (a second call).
template <int NV>
void DirectionSweep<NV>::batchedSplitRows(const V* q, RowsFunction rows_fn, bool unsplit,
                                          CompactLineRows out) {
  const int nb = (int)batch_.size();
  eig_.resize(nb);
  for (int j = 0; j < nb; ++j) eig_[j] = roeEigen<NV>(q + batch_[j], rs_.data() + batch_[j], opt_.gamma);
  componentwise_.assign(nb, 0);
  for (int j = 0; j < nb; ++j) {
    componentwise_[j] = illConditioned(q + batch_[j]);
    stats_.componentwise_faces += componentwise_[j];
  }
  supersonic_.assign(nb, 0); // per face: 1 when its rows are CRWENO5-Z rows
  if (scheme_->hybrid && rfChar())
    for (int j = 0; j < nb; ++j) supersonic_[j] = supersonicFace(q + batch_[j], eig_[j]);
  for (char pass : {0, 1}) {
    faces_.clear(); // indices j into batch_ of this call's faces
    for (int j = 0; j < nb; ++j)
      if (supersonic_[j] == pass) faces_.push_back(j);
    if (!faces_.empty()) splitRowsCall(q, pass ? batchedRows(crweno5Row) : rows_fn, unsplit, out);
  }
}

// Whether rf-char upwinds every field of the face between cells 2 and 3 of the stencil qs the same way (the
// signs of u - c and u + c at both cells and of the face's Roe speeds e all agree: a supersonic face). There
// every characteristic wave runs downstream, and the central CU6 part of the ENO-Pade row, whose downwind
// candidate reaches against all of them, carries the errors that the near-vacuum rarefactions' start-up
// leaves in their supersonic parts (docs/euler_extremes.md: with the ENO-Pade row there, L1(rho) is 0.5-0.7%
// above crweno5 on the four near-vacuum cases); the row is the CRWENO5-Z row there.
template <int NV>
bool DirectionSweep<NV>::supersonicFace(const V* qs, const typename LineGas<NV>::Eigen& e) const {
  using RF = RfChar<NV>;
  double a[NV], b[NV], roe[NV];
  RF::cellSpeeds(qs[2], opt_.gamma, a);
  RF::cellSpeeds(qs[3], opt_.gamma, b);
  RF::roeSpeeds(e, roe);
  const int slow = RF::sign(a[0], roe[0], b[0]), fast = RF::sign(a[NV - 1], roe[NV - 1], b[NV - 1]);
  return slow != 0 && slow == fast;
}

// Whether the face between cells 2 and 3 of the stencil qs is treated component-wise: the smaller of its cells'
// pressures is too low against this stage's flux scale for its characteristic basis
// (characteristic_conditioning.hpp).
template <int NV> bool DirectionSweep<NV>::illConditioned(const V* qs) const {
  using G = LineGas<NV>;
  const double p = std::min(G::pressure(qs[2], opt_.gamma), G::pressure(qs[3], opt_.gamma));
  return characteristicIllConditioned(stage_flux_scale_, p);
}

// The rows of the faces faces_ (indices into batch_, eigensystems eig_) by one call of rows_fn.
template <int NV>
void DirectionSweep<NV>::splitRowsCall(const V* q, RowsFunction rows_fn, bool unsplit, CompactLineRows out) {
  const int nb = (int)faces_.size(), lanes = 2 * NV * nb;
  stencil_.resize((size_t)6 * lanes);
  brow_.resize((size_t)4 * lanes);
  for (int i = 0; i < nb; ++i) {
    const int j = faces_[i], k = batch_[j];
    double wp[NV][6], wm[NV][6];
    projectStencils<NV>(q + k, f_.data() + k, alpha_[k], componentwise_[j] ? nullptr : &eig_[j], unsplit, wp,
                        wm);
    for (int c = 0; c < NV; ++c)
      for (int m = 0; m < 6; ++m) {
        stencil_[(size_t)m * lanes + 2 * NV * i + c] = wp[c][m];
        stencil_[(size_t)m * lanes + (2 * i + 1) * NV + c] = wm[c][5 - m]; // mirrorRow's stencil
      }
  }
  rows_fn(lanes, stencil_.data(), brow_.data());
  for (int i = 0; i < nb; ++i) {
    Row rows[2][NV];
    for (int s = 0; s < 2; ++s)
      for (int c = 0; c < NV; ++c) {
        const size_t l = (size_t)(2 * i + s) * NV + c;
        const double a = brow_[l], c3 = brow_[2 * (size_t)lanes + l];
        rows[s][c] = {s == 0 ? a : c3, brow_[(size_t)lanes + l], s == 0 ? c3 : a,
                      brow_[3 * (size_t)lanes + l]};
      }
    writeSplitRow<NV>(eig_[faces_[i]], rows, !componentwise_[faces_[i]], batch_[faces_[i]], out);
  }
}

template <int NV>
void DirectionSweep<NV>::faceFluxes(MPI_Comm comm, const V* q, int nlines, long long n, long long xs, int xm,
                                    bool periodic, double alpha, double lambda, double flux_scale, V* h) {
  ++stats_.evaluations;
  stage_flux_scale_ = flux_scale;
  int size = 1;
  MPI_Comm_size(comm, &size);
  // nlines is the same on every rank of comm, so all take the same branch.
  const bool in_place = !scheme_->compact || opt_.gather_lines || !opt_.transpose_lines || nlines < size;
  if (size == 1 || (in_place && !opt_.segmented))
    linesFaceFluxes(comm, q, nlines, n, xs, xm, periodic, alpha, lambda, h);
  else
    transposedFaceFluxes(comm, size, q, nlines, n, xs, xm, periodic, alpha, lambda, h);
}

// faceFluxes of lines split over the `size` ranks of comm: whole lines moved to one rank each (LineTranspose),
// processed there serially, face fluxes moved back.
template <int NV>
void DirectionSweep<NV>::transposedFaceFluxes(MPI_Comm comm, int size, const V* q, int nlines, long long n,
                                              long long xs, int xm, bool periodic, double alpha,
                                              double lambda, V* h) {
  LineTranspose* tr = nullptr;
  for (LineTranspose& t : transposes_)
    if (t.matches(comm, n, xs, xm)) tr = &t;
  if (!tr) tr = &transposes_.emplace_back(comm, n, xs, xm, kGhost);
  // Batches of whole lines of about batch_bytes of state per rank (the same count on every rank).
  const double line_bytes = sizeof(V) * (double)(n + 2 * kGhost + 1) / size;
  const double limit = (double)INT_MAX / ((double)(n + 2 * kGhost + 1) * NV);
  const int chunk = (int)std::max(1.0, std::min(limit, std::floor((double)opt_.batch_bytes / line_bytes)));
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  for (int l0 = 0; l0 < nlines; l0 += chunk) {
    const int cn = std::min(chunk, nlines - l0), own = tr->owned(cn);
    {
      EventScope ev(sweepEvent(0));
      tr->gather(&q[(size_t)l0 * ncell][0], NV, cn, &tq_);
    }
    th_.resize((size_t)own * (n + 1));
    // A failure (a singular line) is this rank's alone here: agree on it before the next collective, so that
    // every rank of the line communicator throws and none waits in the return exchange.
    std::string failure;
    try {
      if (faultInjected())
        throw std::runtime_error("line solve failure injected by SUITE_FAULT_LINE_SOLVE_RANK");
      linesFaceFluxes(MPI_COMM_SELF, reinterpret_cast<const V*>(tq_.data()), own, n, 0, (int)n, periodic,
                      alpha, lambda, th_.data());
    } catch (const std::exception& e) {
      failure = e.what();
    }
    if (suite::agreeOnFailure(comm, &failure) != 0 && failure.empty())
      failure = "MPI error agreeing on a failure";
    if (!failure.empty()) throw std::runtime_error(failure);
    EventScope ev(sweepEvent(1));
    // (a rank that owns none of the chunk's lines has an empty th_: no element to take the address of)
    tr->scatter(reinterpret_cast<const double*>(th_.data()), NV, cn, &h[(size_t)l0 * nface][0]);
  }
}

template <int NV>
void DirectionSweep<NV>::linesFaceFluxes(MPI_Comm comm, const V* q, int nlines, long long n, long long xs,
                                         int xm, bool periodic, double alpha, double lambda, V* h) {
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  if (opt_.segmented && !in_segment_) { // whole lines here (one rank, or after the transpose)
    segmentedFaceFluxes(q, nlines, n, periodic, alpha, lambda, h);
    return;
  }
  if (!scheme_->compact) {
    for (int l = 0; l < nlines; ++l)
      lineExplicit(q + (size_t)l * ncell, n, xs, xm, periodic, alpha, h + (size_t)l * nface);
  } else {
    const int nown = xm + ((!periodic && xs + xm == n) ? 1 : 0);
    markBlockLines(comm, q, nlines, n, xs, xm, nown, periodic);
    scalarLinesFaceFluxes(comm, q, nlines, n, xs, xm, nown, periodic, alpha, h);
    blockLinesFaceFluxes(comm, q, n, xs, xm, nown, periodic, alpha, h);
  }
  if (opt_.positivity && lambda > 0.0) limitFaces(q, nlines, xm, lambda, h);
}

// Whether the six cells qs[0..5] of a row hold one state to 1e-12 relative (density and energy each to its own
// largest value, the momenta to sqrt(rho E), so that a gas at rest counts despite round-off momenta): there the
// ENO-Pade row's weights are the Pade weights to ~1e-18 (beta_k ~ (1e-12 q)^2 against epsilon ~ 1e-6 q^2,
// weno5.hpp), so the row is the Pade row (crweno_cu6.hpp) and is assembled as one, without the characteristic
// projection and the weights: a round-off change that saves most of a shocked line's row cost where the line is
// at rest (the 3D explosion at 64^3: ENO-Pade / WENO5 cost 3.04 with this shortcut, 3.17 without,
// docs/euler_nd.md).
template <int NV> static bool uniformStencil(const typename LineGas<NV>::V* qs) {
  double scale[NV] = {}, diff[NV] = {};
  for (int m = 0; m < 6; ++m)
    for (int c = 0; c < NV; ++c) {
      scale[c] = std::max(scale[c], std::abs(qs[m][c]));
      diff[c] = std::max(diff[c], std::abs(qs[m][c] - qs[0][c]));
    }
  const double momentum = std::sqrt(scale[0] * scale[NV - 1]); // the scale of rho u: sqrt(rho E)
  for (int c = 0; c < NV; ++c)
    if (diff[c] > 1e-12 * (c == 0 || c == NV - 1 ? scale[c] : std::max(scale[c], momentum))) return false;
  return true;
}

// Marks the shock rows of every line (shock_) and the lines that need the block solve (flag_, agreed over the
// ranks of the line; blocks_: their indices).
template <int NV>
void DirectionSweep<NV>::markBlockLines(MPI_Comm comm, const V* q, int nlines, long long n, long long xs,
                                        int xm, int nown, bool periodic) {
  const int ncell = xm + 2 * kGhost;
  flag_.resize(nlines);
  shock_.resize((size_t)nlines * nown);
  for (int l = 0; l < nlines; ++l)
    flag_[l] =
        lineNeedsBlocks(q + (size_t)l * ncell, ncell, n, xs, nown, periodic, &shock_[(size_t)l * nown]);
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size > 1) MPI_Allreduce(MPI_IN_PLACE, flag_.data(), nlines, MPI_INT, MPI_LOR, comm);
  blocks_.clear();
  for (int l = 0; l < nlines; ++l)
    if (flag_[l]) blocks_.push_back(l);
  if (scheme_->hybrid) // a line with a shock row anywhere (on any rank) gets ENO-Pade rows on every row
    for (int l : blocks_) {
      const V* ql = q + (size_t)l * ncell;
      for (int k = 0; k < nown; ++k)
        shock_[(size_t)l * nown + k] = !boundaryFace(periodic, xs + k, n) && !uniformStencil<NV>(ql + k);
    }
}

// Face fluxes of the lines not in blocks_: scalar rows with NV right-hand sides, all in one batched solve.
template <int NV>
void DirectionSweep<NV>::scalarLinesFaceFluxes(MPI_Comm comm, const V* q, int nlines, long long n,
                                               long long xs, int xm, int nown, bool periodic, double alpha,
                                               V* h) {
  const int ncell = xm + 2 * kGhost, nface = xm + 1, ns = nlines - (int)blocks_.size();
  sabc_.resize((size_t)3 * nown * ns);
  srhs_.resize((size_t)NV * nown * ns);
  int is = 0;
  for (int l = 0; l < nlines; ++l)
    if (!flag_[l]) {
      const CompactLineRows out = {
          false, &sabc_[(size_t)3 * nown * is], &srhs_[(size_t)NV * nown * is], {}, {}, {}, {}};
      lineCompactRows(q + (size_t)l * ncell, n, xs, xm, nown, periodic, alpha, &shock_[(size_t)l * nown],
                      out);
      ++is;
    }
  sx_.resize((size_t)ns * nface * NV);
  if (ns > 0) {
    StageScope stage;
    if (!opt_.gather_lines)
      lines_.solveScalar(comm, ns, nown, sabc_.data(), NV, srhs_.data(), periodic, xs, nface, sx_.data());
    else // comparison path: every line gathered to every rank, one exchange per line
      for (int l = 0; l < ns; ++l)
        gather_.solveScalar(comm, nown, &sabc_[(size_t)3 * nown * l], NV, &srhs_[(size_t)NV * nown * l],
                            periodic, xs, nface, &sx_[(size_t)NV * nface * l]);
  }
  is = 0;
  for (int l = 0; l < nlines; ++l)
    if (!flag_[l]) {
      const double* x = &sx_[(size_t)is++ * nface * NV];
      V* hl = h + (size_t)l * nface;
      for (int k = 0; k < nface; ++k)
        for (int c = 0; c < NV; ++c) hl[k][c] = x[NV * k + c];
    }
}

// Face fluxes of the lines in blocks_ (two NV x NV systems each), in batches of at most opt_.batch_bytes of
// rows: the same batches on every rank of the line, so the message count is ceil(block rows / budget),
// independent of how the lines are split over the ranks, and memory stays bounded whatever the number of
// shocked lines. The batch size must be the same on every rank of the line (it is the line count of a
// collective), so it comes from the global line length and the rank count, not from this rank's rows (the
// last rank of an open line owns one row more; uneven splits differ too): about batch_bytes per rank.
template <int NV>
void DirectionSweep<NV>::blockLinesFaceFluxes(MPI_Comm comm, const V* q, long long n, long long xs, int xm,
                                              int nown, bool periodic, double alpha, V* h) {
  constexpr int NN = NV * NV;
  const int nb = (int)blocks_.size(), nface = xm + 1;
  int nranks = 1;
  MPI_Comm_size(comm, &nranks);
  const double line_bytes = sizeof(double) * 2.0 * (double)(n + 1) / nranks * (3 * NN + NV);
  const int chunk = (int)std::max(1.0, std::min(1e9, std::floor((double)opt_.batch_bytes / line_bytes)));
  for (int c0 = 0; c0 < nb; c0 += chunk) {
    const int cn = std::min(chunk, nb - c0);
    blockBatchRows(q, n, xs, xm, nown, periodic, alpha, c0, cn);
    StageScope stage; // until the end of this batch
    blockBatchSolve(comm, nown, periodic, xs, nface, cn);
    for (int ib = 0; ib < cn; ++ib) {
      const double* x0 = &bx_[(size_t)(2 * ib) * nface * NV];
      const double* x1 = &bx_[(size_t)(2 * ib + 1) * nface * NV];
      const int l = blocks_[c0 + ib];
      V* hl = h + (size_t)l * nface;
      if (rfChar()) {
        rfCombine(q + (size_t)l * (xm + 2 * kGhost), n, xs, xm, periodic, alpha, x0, x1, hl);
        continue;
      }
      for (int k = 0; k < nface; ++k)
        for (int c = 0; c < NV; ++c) hl[k][c] = x0[NV * k + c] + x1[NV * k + c];
    }
  }
}

// rf-char face fluxes h[0 .. xm] of one block line (q: its cells) from the solutions x0, x1 of its systems (the
// left- and right-biased rows of f): per characteristic field, Lax-Friedrichs dissipation for the fields of
// mixed sign at the split faces (every interior face of a block line; WENO closures); at the central closures of
// enopade6 h = (x0 + x1) / 2 (both are central there).
template <int NV>
void DirectionSweep<NV>::rfCombine(const V* q, long long n, long long xs, int xm, bool periodic, double alpha,
                                   const double* x0, const double* x1, V* h) {
  const int ncell = xm + 2 * kGhost;
  roeStates<NV>(q, ncell, opt_.gamma, &rs_);
  cellSpeeds<NV>(q, ncell, opt_.gamma, &lam_);
  for (int k = 0; k <= xm; ++k) {
    // Every interior face of the hybrid's block lines is split (markBlockLines: ENO-Pade rows, and at uniform
    // stencils Pade rows, which are those rows to round-off; averaging at the latter instead would switch the
    // face flux on a threshold and turn round-off into 1e-9 differences between rank counts); boundary faces are
    // explicit closures.
    const bool split = !scheme_->hybrid || !boundaryFace(periodic, xs + k, n);
    if (!split) {
      for (int c = 0; c < NV; ++c) h[k][c] = 0.5 * (x0[NV * k + c] + x1[NV * k + c]);
      continue;
    }
    h[k] = rfFaceFlux<NV>(q + k, rs_.data() + k, lam_.data() + k, x0 + NV * k, x1 + NV * k, true, alpha,
                          opt_.local_lf, opt_.gamma, illConditioned(q + k));
  }
}

// Rows of the block lines blocks_[c0 .. c0 + cn - 1] into bA_, bB_, bC_, bd_ (systems 2 ib and 2 ib + 1: the
// f+ and f- systems of line blocks_[c0 + ib]).
template <int NV>
void DirectionSweep<NV>::blockBatchRows(const V* q, long long n, long long xs, int xm, int nown,
                                        bool periodic, double alpha, int c0, int cn) {
  constexpr int NN = NV * NV;
  const int ncell = xm + 2 * kGhost;
  bA_.resize((size_t)2 * cn * nown * NN);
  bB_.resize(bA_.size());
  bC_.resize(bA_.size());
  bd_.resize((size_t)2 * cn * nown * NV);
  for (int ib = 0; ib < cn; ++ib) {
    const CompactLineRows out = {
        true,
        nullptr,
        nullptr,
        {&bA_[(size_t)(2 * ib) * nown * NN], &bA_[(size_t)(2 * ib + 1) * nown * NN]},
        {&bB_[(size_t)(2 * ib) * nown * NN], &bB_[(size_t)(2 * ib + 1) * nown * NN]},
        {&bC_[(size_t)(2 * ib) * nown * NN], &bC_[(size_t)(2 * ib + 1) * nown * NN]},
        {&bd_[(size_t)(2 * ib) * nown * NV], &bd_[(size_t)(2 * ib + 1) * nown * NV]}};
    const int l = blocks_[c0 + ib];
    lineCompactRows(q + (size_t)l * ncell, n, xs, xm, nown, periodic, alpha, &shock_[(size_t)l * nown], out);
  }
}

// Solves the 2 cn block systems of a batch (blockBatchRows) into bx_.
template <int NV>
void DirectionSweep<NV>::blockBatchSolve(MPI_Comm comm, int nown, bool periodic, long long xs, int nface,
                                         int cn) {
  constexpr int NN = NV * NV;
  bx_.resize((size_t)2 * cn * nface * NV);
  if (!opt_.gather_lines)
    lines_.solve(comm, NV, 2 * cn, nown, bA_.data(), bB_.data(), bC_.data(), bd_.data(), periodic, xs, nface,
                 bx_.data());
  else if constexpr (NV == 3) // comparison path (1D): each system gathered to every rank
    for (int m = 0; m < 2 * cn; ++m) {
      const size_t o = (size_t)m * nown * NN;
      gather_.solve(comm, NV, nown, &bA_[o], &bB_[o], &bC_[o], &bd_[(size_t)m * nown * NV], periodic, xs,
                    nface, &bx_[(size_t)m * nface * NV]);
    }
  else
    throw std::invalid_argument("gathered line solves (-line_solve gather) are 1D only");
}

// Hu-Adams-Shu positivity limiter on the face fluxes h of nlines lines (lambda = dt/dx scaled, see the header):
// each face flux h_{j+1/2} is blended with the Lax-Friedrichs flux of its two cells, with alpha = max(|u| + c)
// of these two cells, the least alpha of the guarantee (gas_nd.hpp), until U_j - 2 lambda h and
// U_{j+1} + 2 lambda h have positive density and pressure. One value per face: conservative, and applied after
// the compact solves, so they stay exact. Faces whose Lax-Friedrichs sides are not positive (possible only above
// the CFL bound) are counted in stats_.unattainable_faces.
template <int NV> void DirectionSweep<NV>::limitFaces(const V* q, int nlines, int xm, double lambda, V* h) {
  using G = LineGas<NV>;
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  const double g = opt_.gamma;
  EventScope ev(sweepEvent(2));
  for (int l = 0; l < nlines; ++l) {
    const V* ql = q + (size_t)l * ncell;
    V* hl = h + (size_t)l * nface;
    for (int k = 0; k < nface; ++k) {
      if (G::sidesPositive(ql[k + 2], ql[k + 3], lambda, g, hl[k])) continue; // the limiter would keep h
      const double a = std::max(G::maxSpeed(ql[k + 2], g), G::maxSpeed(ql[k + 3], g)) * (1.0 + 1e-12);
      bool attainable = true;
      if (G::limitPositivity(ql[k + 2], ql[k + 3], a, lambda, g, &hl[k], &attainable) < 1.0)
        ++stats_.limited_faces;
      if (!attainable) ++stats_.unattainable_faces;
    }
  }
}

template class DirectionSweep<3>;
template class DirectionSweep<4>;
template class DirectionSweep<5>;

} // namespace suite::euler
