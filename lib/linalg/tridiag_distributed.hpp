// Exact distributed solve of one (block-)tridiagonal line system whose rows are spread over the ranks of a
// communicator: the rows are gathered to every rank (MPI_Allgatherv) and the whole line is solved redundantly
// with BlockTridiagSolver (verified block Thomas, banded LU fallback, Woodbury for periodic lines). Exact at
// every rank count, with results bitwise independent of the decomposition; the cost is O(N) per rank, which
// is the right trade in 1D (the gather volume equals one line of the solution).
#pragma once

#include "linalg/tridiag.hpp"

#include <mpi.h>

#include <vector>

namespace suite::linalg {

class DistributedTridiag {
public:
  // Rows are ordered by rank (rank r holds global block rows offset_r .. offset_r + nloc_r - 1).
  // bs x bs blocks A, B, C (row-major, nloc blocks each) and d (nloc * bs). After the call x holds the
  // solution of global block rows first .. first + count - 1 (indices taken modulo the global row count when
  // periodic).
  void solve(MPI_Comm comm, int bs, int nloc, const double* A, const double* B, const double* C,
             const double* d, bool periodic, long long first, int count, double* x);
  // Scalar rows (abc[3 i] = a_i, b_i, c_i) shared by ncomp independent right-hand sides interleaved per row
  // (d[i * ncomp + k]); verified Thomas / cyclic Thomas, LU fallback. x: count * ncomp values, same layout.
  void solveScalar(MPI_Comm comm, int nloc, const double* abc, int ncomp, const double* d, bool periodic,
                   long long first, int count, double* x);
  const BlockTridiagSolver::Stats& stats() const { return solver_.stats(); }

private:
  void gather(MPI_Comm comm, int per_row, int nloc, const double* local, std::vector<double>* global);
  BlockTridiagSolver solver_;
  std::vector<int> counts_, displs_;
  std::vector<double> send_, all_, A_, B_, C_, d_;
};

} // namespace suite::linalg
