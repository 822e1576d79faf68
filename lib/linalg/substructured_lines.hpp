// Exact parallel solve of many independent tridiagonal lines distributed over the ranks of a communicator,
// by substructuring (the partition method of H. H. Wang, ACM TOMS 7 (1981) 170; Sun, Zhang & Ni, 1989):
//   1. each rank solves its block of every line for the right-hand side and the two coupling columns,
//        T_r [y v w] = [d, -a_first e_1, -c_last e_m]     (LAPACK dgtsv: partial pivoting, so rows that are
//                                                          not diagonally dominant do not break the solve);
//   2. the first and last (y, v, w) of every line go to every rank in ONE MPI_Allgather per solve, whatever
//   the
//      number of lines (O(1) messages per rank in the line count);
//   3. each rank solves the reduced system of every line (2 unknowns per rank, banded; periodic lines through
//   a
//      rank-2 Woodbury correction) and finishes x = y + x_left v + x_right w.
// Exact (no iteration, no truncation) at every rank count; the result differs from a serial solve by
// round-off.
#pragma once

#include <petscsys.h>

#include <vector>

namespace suite::linalg {

class SubstructuredLines {
public:
  // comm: the ranks that share the lines, in line order (rank r holds rows after those of rank r-1).
  // Every rank holds the same nlines lines with nloc >= 1 rows each, stored line by line:
  // a, b, c, d are nlines * nloc values, a = sub-, b = main, c = super-diagonal. a of a line's global first
  // row and c of its global last row couple to the other end when periodic and are ignored otherwise. On
  // return d holds the solution. Errors collectively if a rank's local block is exactly singular.
  PetscErrorCode solve(MPI_Comm comm, int nlines, int nloc, const double* a, const double* b, const double* c,
                       double* d, bool periodic);

private:
  PetscErrorCode localSolves(MPI_Comm comm, int nlines, int nloc, const double* a, const double* b,
                             const double* c, double* d, bool first_rank, bool last_rank, bool periodic);
  int reducedSolve(int P, const double* ends, int line, int nlines, bool periodic, double* u);

  std::vector<double> dl_, dm_, du_, rhs_, v_, w_, ends_, all_ends_, ab_, red_;
  std::vector<int> ipiv_;
};

} // namespace suite::linalg
