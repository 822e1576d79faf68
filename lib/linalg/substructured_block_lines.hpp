// Exact parallel solve of MANY independent block-tridiagonal lines that share one communicator (all lines of
// one direction of a distributed grid), by substructuring (partition method: H. H. Wang, ACM TOMS 7 (1981)
// 170; block rows: Mattor, Williams & Hewett, Parallel Computing 21 (1995) 1769), batched so that the number
// of messages per solve does not depend on the number of lines:
//   1. every rank eliminates its rows of every line locally (one block Thomas sweep that keeps only the first
//      and last rows of Y, P, Q in T_r [Y P Q] = [d, -A_0 E_0, -C_{n-1} E_{n-1}]);
//   2. the end rows of ALL lines go to every rank of the line communicator in ONE MPI_Allgather;
//   3. every rank solves the reduced systems of all lines (2 P bs unknowns each: dense LU, or band LU) and
//      finishes its rows by a second block Thomas solve with d_0 -= A_0 x_left, d_{n-1} -= C_{n-1} x_right,
//      so no per-row spike columns are stored: work arrays O(nloc bs^2) for one line, plus the gathered end
//      rows, P nlines (2 bs nrhs + 4 bs^2 + 1) doubles (bs 5, 128^2 lines, P = 8: 116 MB);
//   4. one MPI_Allreduce of the per-line residuals of the global systems; lines whose residual exceeds
//      `tolerance` or that met a tiny pivot (the same lines on every rank; rare: rows far from diagonally
//      dominant) are solved again exactly: their rows are gathered to every rank in ONE MPI_Allgatherv (plus
//      one MPI_Allgather of the row counts) and each such global line is solved by band LU with partial
//      pivoting (LAPACK dgbsv; periodic lines in the folded order 0, N-1, 1, N-2, ... that keeps the
//      wrap-around couplings inside a band of 3 bs - 1).
// Per solve, whatever the number of lines: 1 MPI_Allgather + 1 MPI_Allreduce (+ 2 collectives when some line
// falls back). Cost: about 3x a serial block Thomas solve of the same rows (2.7x the flops: the spike
// columns and the first rows in pass 1, then pass 2), see scripts/bench/src/bench_block_lines.cpp.
// Results differ from a serial solve by round-off only.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace suite::linalg {

class SubstructuredBlockLines {
public:
  struct Stats {
    long long solves = 0, lines = 0, fallbacks = 0;
    long long lane_batches = 0; // sweeps (one-rank, pass 1, pass 2) made on four lines at once
  };
  // comm: the ranks that share the lines, ranked in line order (rank r holds the rows after rank r-1's).
  // Every rank passes the same nlines lines; this rank holds nloc >= 2 consecutive block rows of each,
  // global rows first .. first + nloc - 1 (first: this rank's offset on the line, same for all lines; nloc
  // may differ between ranks).
  // Line l's rows are stored contiguously: block row i of line l at A + (l * nloc + i) * bs * bs (row-major
  // bs x bs, bs in 1..5), right-hand side at d + (l * nloc + i) * bs. A of a line's global first row and C
  // of its global last row couple the two ends when periodic and are ignored otherwise.
  // count = nloc or nloc + 1: the solution rows returned, x + (l * count + i) * bs; row nloc (count = nloc + 1)
  // is the first row of the next rank (on the last rank: the global first row when periodic; not allowed
  // when not periodic). x must not overlap d. Collective on comm. Bad arguments (bs, nloc < 2, count) throw
  // std::invalid_argument before any communication.
  void solve(MPI_Comm comm, int bs, int nlines, int nloc, const double* A, const double* B, const double* C,
             const double* d, bool periodic, long long first, int count, double* x);
  // Scalar rows shared by nrhs right-hand sides: abc + 3 (l * nloc + i) = (a, b, c) of row i of line l,
  // d + (l * nloc + i) * nrhs; x + (l * count + i) * nrhs. Same contract otherwise.
  void solveScalar(MPI_Comm comm, int nlines, int nloc, const double* abc, int nrhs, const double* d,
                   bool periodic, long long first, int count, double* x);
  // solves: calls; lines: lines solved; fallbacks: lines re-solved by the exact fallback.
  const Stats& stats() const { return stats_; }
  // Relative residual (max |T x - d| / max |d| over a whole global line) above which a line is re-solved by
  // the exact fallback. It bounds the backward error, not the forward error: for lines that are not
  // diagonally dominant the accepted solution may be less accurate than the pivoting fallback's by the
  // growth in block Thomas (measured: up to ~15x on random lines with condition numbers ~1e4).
  double tolerance = 1e-10;
  // Reduced systems (2 P bs unknowns per line, P = communicator size) of at most this many unknowns are
  // solved by dense LU, larger ones by band LU (periodic lines: band LU of the open system plus a rank-2 bs
  // Woodbury correction for the wrap-around couplings). 0 forces the band path (tests).
  int reduced_dense_max = 48;

private:
  template <int BS, int NR>
  void solveImpl(MPI_Comm comm, int nlines, int nloc, const double* A, const double* B, const double* C,
                 int ms, const double* d, int nrhs, bool periodic, int count, double* x);
  template <int BS>
  bool reducedSolve(int P, int nrhs, bool periodic, const double* ends, std::size_t rank_stride, int E,
                    double* z);
  // The shape of one substructured solve (pass 2 reads it).
  struct Shape {
    int P, rank, n, nrhs, nlines, count;
    bool periodic;
    bool hasL() const { return rank > 0 || periodic; } // a neighbour row before this rank's rows
    bool hasR() const { return rank + 1 < P || periodic; }
  };
  // Whether the sweeps of block size BS with NR right-hand sides go four lines at a time
  // (block_thomas_lanes.hpp: one right-hand side, bs 3 to 5).
  template <int BS, int NR> static constexpr bool laned() { return NR == 1 && BS >= 3; }
  double* laneWork(int bs, int n); // the lanes' work for lines of n rows, 32-byte aligned
  template <int BS, int NR, class Rows>
  void plainSweeps(const Shape& s, const Rows& rows, double* x, std::size_t xstride);
  template <int BS, int NR, class Rows> void firstPass(const Shape& s, const Rows& rows);
  template <int BS, int NR, class Rows>
  void secondPass(const Shape& s, int l0, int batch, const Rows& rows, double* x, std::size_t xstride);

  // Exact solve of the lines in fail_ (see 4. above); throws std::runtime_error (on every rank) if one of
  // them is singular.
  void fallbackLines(MPI_Comm comm, int bs, int nrhs, int nloc, const double* A, const double* B,
                     const double* C, int ms, const double* d, bool periodic, int count, double* x);
  // Its steps: rows of the failing lines to every rank (recv_), then per line band assembly and dgbsv.
  long long gatherFailingRows(MPI_Comm comm, int bs, int nrhs, int nloc, const double* A, const double* B,
                              const double* C, int ms, const double* d, long long* offset);
  void packFailingRows(int bs, int nrhs, int nloc, const double* A, const double* B, const double* C, int ms,
                       const double* d);
  void assembleFailingLine(int f, int bs, int nrhs, long long nb, bool periodic, int kl);
  void solveFailingLine(int f, int bs, int nrhs, long long nb, bool periodic, long long offset, int count,
                        double* x);

  Stats stats_;
  std::vector<double> ends_, all_ends_, res_, G_, work_, red_, z_, zu_, s_, send_, recv_, band_, rhs_;
  std::vector<int> ipiv_, counts_, displs_, nlocs_;
  std::vector<int> fail_; // lines to re-solve by the fallback (identical on every rank), increasing
  struct alignas(32) LaneQuad {
    double v[4];
  };
  std::vector<LaneQuad> lanes_;    // work of the four-line block Thomas (block_thomas_lanes.hpp)
  std::vector<double> neighbours_; // pass 2: the values beyond the ends (xl, xr) of up to four lines
  std::vector<double> spare_;      // the solution of a spare lane (plainSweeps)
};

} // namespace suite::linalg
