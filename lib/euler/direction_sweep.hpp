// Interface fluxes of all grid lines of one direction (1D: the one line; 2D/3D: the scheme applied direction by
// direction) for the conservative finite-difference form dU_j/dt = -(h_{j+1/2} - h_{j-1/2}) / dx:
// Lax-Friedrichs flux splitting (line_options.hpp) or rf-char upwinding (rf_char.hpp), characteristic-wise rows
// with the direction's Roe eigenvectors (gas_nd.hpp), the ENO-Pade / CRWENO / WENO rows of the scheme registry,
// the Hu-Adams-Shu positivity limiter (below), and for compact schemes one batched, exact, distributed solve of
// every line of the direction (SubstructuredBlockLines): lines whose rows are all Pade (or explicit) rows take
// the scalar solve with NV right-hand sides, the others two NV x NV block systems (split fluxes f+ and f-).
// Lines split over several ranks are by default moved whole to one rank each (pencil transpose, LineTranspose:
// per batch of lines two MPI_Alltoallv) and processed there serially, bitwise as on one rank; with LineOptions::transpose_lines
// false (or fewer lines than ranks, as in 1D) the split lines are solved in place by substructuring: the
// block/scalar decision is reduced over the ranks that share a line (one Allreduce of the line flags), then per
// batch one Allgather and one Allreduce. Either way the messages per call are O(1) in the number of lines.
//
// rf-char on block lines (HyPar's way, Ghosh & Baeder 2012 sec. 4): the two block systems carry the left- and the
// right-biased rows of f itself (no splitting; Pade rows and central closures are the same in both), and after
// the solves each face picks per characteristic field (rfCombine): l_k x_left where the field's speeds are > 0,
// l_k x_right where they are < 0, else their mean plus the Lax-Friedrichs term alpha_k (u_L - u_R) / 2 with
// explicit WENO5-Z values of l_k U (HyPar solves two more systems for U). Each system keeps rows of one bias
// throughout, so it is as well conditioned and as exactly solved as the split ones. Two designs that do not work,
// measured: feeding the pick into the split systems (an upwinded field's row carrying l_k f in the f+ system and
// nothing in f-) makes a row's neighbours unknowns of another function, an O(1) inconsistency (Sod blows up);
// one system of h with each field's row of its own bias mixes left- and right-biased rows in one block row,
// which the block Thomas sweep does not solve accurately (3D explosion, 1 vs 2 ranks: 3e-5 apart).
//
// A face one of whose cells is far below the grid's flux scale (cold gas, near-vacuum) has an ill-conditioned
// characteristic basis: it is treated component-wise, its rows and its upwinding (characteristic_conditioning.hpp).
//
// Positivity (Hu, Adams & Shu, J. Comput. Phys. 242 (2013) 169; Zhang & Shu, J. Comput. Phys. 229 (2010) 8918).
// One forward-Euler stage U_j - sum_d lambda_d (h_{j+1/2} - h_{j-1/2}), lambda_d = dt/dx_d, is the convex
// combination sum_d w_d [1/2 (U_j - 2 L_d h_{j+1/2}) + 1/2 (U_j + 2 L_d h_{j-1/2})] with w_d = lambda_d A_d / S,
// S = sum_e lambda_e A_e, A_d the stage state's max |u_d| + c, and L_d = lambda_d / w_d = S / A_d (1D: L = dt/dx).
// faceFluxes' `lambda` is L_d. The limiter (limitFaces, after the compact solves: one value per face, so
// conservation and the exactness of the line solves are kept) blends each face flux with the Lax-Friedrichs flux
// of its two cells (alpha = their max |u| + c) until both half-states are admissible; then the stage is
// admissible, whatever the scheme. It can always do so when L_d alpha <= 1/2 (gas_nd.hpp, limitPositivity), i.e.
//     sigma = dt sum_d A_d / dx_d <= 1/2        (the stage's own CFL number, summed over the directions),
// up to the 1e-12 safety factor on alpha. SSP-RK3 (Shu & Osher) stages are convex combinations of such
// forward-Euler steps with the full dt, so every stage and the step keep density and pressure positive when
// sigma <= 1/2 holds at each of the three stages. The Euler run refuses -cfl above 1/2 (kPositivityCfl) with the
// limiter on; the stage speeds may still grow past those of the step's start, and a face whose Lax-Friedrichs
// half-states are not admissible (stats().unattainable_faces: possible only when sigma > 1/2) makes the run retry
// the step at half dt (apps/euler/euler_step.cpp), as does a non-positive state left by round-off. RK4 is not SSP
// and the implicit integrators are not forward-Euler combinations: there the limiter is not proven (off by
// default for the implicit ones) and only the retry protects the run.
// References: Shu, ICASE report 97-65 (1997), sec. 2.3 (flux splitting, characteristic decomposition,
// dimension-by-dimension finite differences); Ghosh & Baeder, SIAM J. Sci. Comput. 34 (2012) A1678, sec. 2.3
// (characteristic compact rows as a block-tridiagonal system: row j+1/2 of field k is multiplied by the left
// eigenvector l_k(j+1/2), then by R(j+1/2) to return to conserved unknowns, so each block row is R diag(a) L,
// R diag(b) L, R diag(c) L); Lele, J. Comput. Phys. 103 (1992) 16 (Pade rows).
#pragma once

#include "euler/compact_rows_batch.hpp"
#include "euler/gas_nd.hpp"
#include "euler/line_options.hpp"
#include "euler/line_transpose.hpp"
#include "euler/schemes.hpp"
#include "euler/weno5_line.hpp"
#include "linalg/substructured_block_lines.hpp"
#include "linalg/tridiag_distributed.hpp"

#include <mpi.h>

#include <array>
#include <vector>

namespace suite::euler {

// One line's rows for the compact solve: scalar rows (blocks false: abc, rhs with NV right-hand sides) or the
// two NV x NV block systems A[s], B[s], C[s], d[s] of the split fluxes f+ (s = 0) and f- (s = 1).
struct CompactLineRows {
  bool blocks;
  double* abc;
  double* rhs;
  double* A[2];
  double* B[2];
  double* C[2];
  double* d[2];
};

template <int NV> class DirectionSweep {
public:
  using V = typename LineGas<NV>::V;
  static constexpr int kGhost = kLineGhost;

  DirectionSweep(const SchemeInfo* scheme, const LineOptions& options);

  // q: nlines lines of xm + 2 kGhost states each (cells xs-3 .. xs+xm+2 of the line, in the line's frame,
  // ghosts filled), line after line. n: global cells along the direction; xs, xm: this rank's cells.
  // line_comm: the ranks sharing these lines, in line order (every rank passes the same nlines).
  // alpha: the Lax-Friedrichs speed for compact schemes and -local_lf false (max |u_n| + c of the direction).
  // lambda: L_d = dt/dx_d scaled for the positivity limiter, see above (<= 0: off). flux_scale: the grid's
  // largest momentum flux p + rho |u|^2 (characteristic_conditioning.hpp: faces whose characteristic basis
  // is ill-conditioned against it are treated component-wise). Output h: nlines x (xm + 1) face fluxes,
  // h[l (xm+1) + k] at x_{xs+k-1/2}. Collective on line_comm for compact schemes. Throws std::runtime_error (the
  // same on every rank of line_comm) if a line system is singular.
  void faceFluxes(MPI_Comm line_comm, const V* q, int nlines, long long n, long long xs, int xm,
                  bool periodic, double alpha, double lambda, double flux_scale, V* h);

  // ENO-Pade shock rows of nlines lines laid out as for faceFluxes, at all xm + 1 faces of each (boundary faces
  // of a non-periodic line are explicit closures: 0): shock[l (xm+1) + k] = 1 at a shock row. Only the sensor
  // (no solve, no statistics, nothing collective); all 0 for schemes without the switch.
  void shockFaces(const V* q, int nlines, long long n, long long xs, int xm, bool periodic, char* shock);

  const LineStats& stats() const { return stats_; }
  // Line solves (batched calls, or one per line with -line_solve gather) and their exact fallbacks.
  long long lineSolves() const { return opt_.gather_lines ? gather_.stats().solves : lines_.stats().solves; }
  long long linesSolved() const { return opt_.gather_lines ? gather_.stats().solves : lines_.stats().lines; }
  long long lineFallbacks() const {
    return opt_.gather_lines ? gather_.stats().lu_fallbacks : lines_.stats().fallbacks;
  }

private:
  // faceFluxes of lines held as segments on the ranks of comm (or whole, comm = MPI_COMM_SELF).
  void linesFaceFluxes(MPI_Comm comm, const V* q, int nlines, long long n, long long xs, int xm,
                       bool periodic, double alpha, double lambda, V* h);
  void transposedFaceFluxes(MPI_Comm comm, int size, const V* q, int nlines, long long n, long long xs,
                            int xm, bool periodic, double alpha, double lambda, V* h);
  // LineOptions::segmented: whole lines (comm of one rank) cut into their fluid segments (line_segments.hpp;
  // direction_sweep_segments.cpp).
  void segmentedFaceFluxes(const V* q, int nlines, long long n, bool periodic, double alpha, double lambda,
                           V* h);
  void lineExplicit(const V* q, long long n, long long xs, int xm, bool periodic, double alpha, V* h);
  bool lineNeedsBlocks(const V* q, int ncell, long long n, long long xs, int nown, bool periodic,
                       char* shock);
  bool markShockRows(const V* q, int ncell, long long n, long long xs, int nrow, bool periodic, char* shock);
  void lineCompactRows(const V* q, long long n, long long xs, int xm, int nown, bool periodic, double alpha,
                       const char* shocks, CompactLineRows out);
  void batchedSplitRows(const V* q, RowsFunction rows_fn, bool unsplit, CompactLineRows out);
  bool supersonicFace(const V* qs, const typename LineGas<NV>::Eigen& e) const;
  bool illConditioned(const V* qs) const;
  void splitRowsCall(const V* q, RowsFunction rows_fn, bool unsplit, CompactLineRows out);
  // Steps of linesFaceFluxes for compact schemes.
  void markBlockLines(MPI_Comm comm, const V* q, int nlines, long long n, long long xs, int xm, int nown,
                      bool periodic);
  void scalarLinesFaceFluxes(MPI_Comm comm, const V* q, int nlines, long long n, long long xs, int xm,
                             int nown, bool periodic, double alpha, V* h);
  void blockLinesFaceFluxes(MPI_Comm comm, const V* q, long long n, long long xs, int xm, int nown,
                            bool periodic, double alpha, V* h);
  void blockBatchRows(const V* q, long long n, long long xs, int xm, int nown, bool periodic, double alpha,
                      int c0, int cn);
  void blockBatchSolve(MPI_Comm comm, int nown, bool periodic, long long xs, int nface, int cn);
  void rfCombine(const V* q, long long n, long long xs, int xm, bool periodic, double alpha, const double* x0,
                 const double* x1, V* h);
  // rf-char upwinding in effect (characteristic rows only).
  bool rfChar() const { return opt_.rf_char && opt_.characteristic; }
  void limitFaces(const V* q, int nlines, int xm, double lambda, V* h);
  void prepareLine(const V* q, int xm, double alpha_global);

  const SchemeInfo* scheme_;
  LineOptions opt_;
  double theta_; // resolution threshold of the shock sensor (from opt_.shock_ppw)
  LineStats stats_;
  linalg::SubstructuredBlockLines lines_;
  linalg::DistributedTridiag gather_; // LineOptions::gather_lines
  std::vector<V> f_;
  std::vector<double> speed_, rho_, p_, alpha_;
  std::vector<char> sensor_work_; // enoPadeShockRows: per-cell and per-window tests of a line
  std::vector<typename LineGas<NV>::RoeState>
      rs_;                                       // per cell of the line being processed (characteristic rows)
  std::vector<std::array<double, NV>> lam_;      // its cells' rf-char speeds (RfChar::cellSpeeds)
  std::vector<int> batch_;                       // its faces whose rows go through batchedSplitRows
  std::vector<typename LineGas<NV>::Eigen> eig_; // their Roe eigensystems
  std::vector<int> faces_;                       // the faces (indices into batch_) of one splitRowsCall
  std::vector<char> supersonic_;                 // per face of batch_: supersonicFace (CRWENO5-Z rows)
  std::vector<char> componentwise_;              // per face of batch_: illConditioned (component-wise rows)
  double stage_flux_scale_ = 0.0;                // faceFluxes' flux_scale
  std::vector<double> stencil_, brow_;           // their stencils and rows (structure of arrays)
  std::vector<int> flag_, blocks_;
  std::vector<char> shock_; // per line and owned row: ENO-Pade shock row
  std::vector<double> sabc_, srhs_, sx_, bA_, bB_, bC_, bd_, bx_;
  std::vector<LineTranspose> transposes_; // one per line communicator (grid direction) used with transposes
  std::vector<double> tq_;                // whole lines received by this rank (LineTranspose::gather)
  std::vector<V> th_;                     // their face fluxes
  Weno5Line<NV> weno5_;                   // lineExplicit of schemes with WENO5 rows everywhere
  bool in_segment_ = false;               // segmentedFaceFluxes' own calls of linesFaceFluxes
  std::vector<V> seg_q_, seg_h_;          // its lines without solid cells, or one segment, and their faces
  std::vector<int> clean_;                // those lines' indices
};

extern template class DirectionSweep<3>;
extern template class DirectionSweep<4>;
extern template class DirectionSweep<5>;

} // namespace suite::euler
