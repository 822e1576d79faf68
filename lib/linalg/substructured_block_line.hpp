// Exact parallel solve of ONE block-tridiagonal line whose block rows are spread over the ranks of a
// communicator, by substructuring (the partition method: H. H. Wang, ACM TOMS 7 (1981) 170; for block
// rows, Mattor, Williams & Hewett, Parallel Computing 21 (1995) 1769):
//   1. each rank eliminates its own rows (block Thomas, bs x bs LU with partial pivoting inside a block) for
//        T_r [Y P Q] = [d, -A_first E_first, -C_last E_last]
//      so that its rows satisfy x_i = Y_i + P_i x_left + Q_i x_right, where x_left is the last row of the rank
//      before and x_right the first row of the rank after (wrapping around on periodic lines);
//   2. the first and last rows of Y, P, Q (2 bs (nrhs + 2 bs) numbers) go to every rank in ONE
//      MPI_Allgather;
//   3. every rank solves the reduced system for the first/last rows of all ranks (2 P bs unknowns; dense LU,
//      or band LU for long non-periodic lines) and finishes its rows. The first row of the right neighbour,
//      which a face-flux line needs one past its own rows, is an unknown of the reduced system and so comes
//      for free.
//   4. the local residual of the global system is checked (one MPI_Allreduce); if a block pivot was tiny or
//      the relative residual exceeds `tolerance` (rows that are far from diagonally dominant), the line is
//      solved again by DistributedTridiag (gather + banded LU with partial pivoting), which is exact for any
//      nonsingular system.
// Per solve: O(N/P) work and two collectives of O(1) size per rank, against DistributedTridiag's O(N) work
// and O(N) gather. Results differ from a serial solve by round-off only.
#pragma once

#include "linalg/tridiag_distributed.hpp"

#include <mpi.h>

#include <vector>

namespace suite::linalg {

class SubstructuredBlockLine {
public:
  struct Stats {
    long long solves = 0, fallbacks = 0;
  };
  // Same contract as DistributedTridiag::solve: rank r holds block rows first .. first + nloc - 1 (ranks in
  // line order, nloc >= 2), blocks row-major bs x bs (bs = 1 or 3), d: nloc * bs. count must be nloc or
  // nloc + 1 (the first row of the next rank; on the last rank only for periodic lines). x: count * bs.
  void solve(MPI_Comm comm, int bs, int nloc, const double* A, const double* B, const double* C,
             const double* d, bool periodic, long long first, int count, double* x);
  // Scalar rows (abc[3 i] = a_i, b_i, c_i) shared by ncomp right-hand sides interleaved per row.
  void solveScalar(MPI_Comm comm, int nloc, const double* abc, int ncomp, const double* d, bool periodic,
                   long long first, int count, double* x);
  const Stats& stats() const { return stats_; }
  double tolerance = 1e-10;

private:
  template <int BS>
  void solveImpl(MPI_Comm comm, int nloc, const double* A, const double* B, const double* C, const double* d,
                 int nrhs, bool periodic, long long first, int count, double* x);
  template <int BS>
  bool eliminate(int n, const double* A, const double* B, const double* C, int nrhs, int mf, int m,
                 double* R);
  template <int BS> void reducedSolve(int P, int nrhs, bool periodic, std::vector<double>* z);
  // Columns of R_ (this rank's block rows of [Y P Q], see 1. above): Y in 0 .. nrhs - 1, P from cP (if hasL),
  // Q from cQ (if hasR); m columns, block row stride rs = bs m.
  struct Layout {
    int n, nrhs, cP, cQ, m, rs;
    bool hasL, hasR;
  };
  // The steps of solveImpl (1. to 4. above).
  template <int BS>
  bool eliminateLocal(const Layout& L, const double* A, const double* B, const double* C, const double* d);
  template <int BS> void gatherEnds(MPI_Comm comm, int P, const Layout& L, bool ok);
  template <int BS> void finishRows(const Layout& L, int rank, int P, double* xl, double* xr, double* x);
  template <int BS>
  void checkResidual(MPI_Comm comm, const Layout& L, const double* A, const double* B, const double* C,
                     const double* d, const double* xl, const double* xr, const double* x);

  DistributedTridiag fallback_;
  Stats stats_;
  std::vector<double> R_, G_, ends_, all_ends_, red_, zr_, sA_, sB_, sC_;
  std::vector<int> ipiv_;
};

} // namespace suite::linalg
