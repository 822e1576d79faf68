// Pencil transpose of the grid lines of one direction, the alternative to a substructured (partition-method)
// solve with a batched reduced system for lines that cross rank boundaries. The P ranks of a line
// communicator each hold a segment of every one of the same nlines lines;
// one MPI_Alltoallv moves the segments so that each rank holds about nlines / P WHOLE lines (lines j = r, r + P,
// r + 2P, ... of a batch on rank r: round-robin, so that lines with shocks, which cost more, spread evenly),
// the ranks process them serially, exactly as one rank would, and a second MPI_Alltoallv returns to every rank
// the face values of its segments. Per call: 2 collectives whatever the number of lines; volume per rank:
// (P - 1) / P of its cells out and as many faces back. Results are bitwise those of a one-rank run.
// The pencil decomposition of spectral codes (e.g. Pekurovsky, SIAM J. Sci. Comput. 34 (2012) C192) applied
// to the lines of a compact scheme.
#pragma once

#include <mpi.h>

#include <vector>

namespace suite::euler {

class LineTranspose {
public:
  // Collective on comm (one MPI_Allgather of the segments). comm: the ranks sharing the lines, ranked in line
  // order. This rank holds cells xs .. xs + xm - 1 of each line of n cells, stored with `ghost` cells on each side
  // (the layout of DirectionSweep::faceFluxes). Throws std::invalid_argument (on every rank) if the segments do
  // not tile 0 .. n - 1 in rank order.
  LineTranspose(MPI_Comm comm, long long n, long long xs, int xm, int ghost);

  // Whether this object was set up for these arguments (the same on every rank of comm for one grid direction).
  bool matches(MPI_Comm comm, long long n, long long xs, int xm) const {
    return comm == comm_ && n == n_ && xs == xs_[rank_] && xm == xm_[rank_];
  }
  // Whole lines this rank receives out of a batch of `count` lines (the same count on every rank).
  int owned(int count) const { return linesOf(rank_, count); }
  long long lineLength() const { return n_; }

  // q: `count` local lines of (xm + 2 ghost) x width doubles -> full: owned(count) lines of (n + 2 ghost) x width.
  void gather(const double* q, int width, int count, std::vector<double>* full);
  // hfull: owned(count) lines of (n + 1) x width face values -> h: `count` lines of (xm + 1) x width (faces
  // xs .. xs + xm of each line).
  void scatter(const double* hfull, int width, int count, double* h);

private:
  int linesOf(int r, int count) const { return count > r ? (count - r + size_ - 1) / size_ : 0; }
  // The cells of rank r's stored line that go into the whole line: its own, plus the domain-end ghosts on the
  // first and last rank; they start at stored cell firstSent(r) and fill cells xs_r + firstSent(r) ... of the
  // whole stored line (both start with `ghost` cells).
  int firstSent(int r) const { return r == 0 ? 0 : ghost_; }
  int cellsSent(int r) const { return xm_[r] + (r == 0 ? ghost_ : 0) + (r == size_ - 1 ? ghost_ : 0); }
  void exchange(int width, int count, bool to_owner);

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1, ghost_ = 0;
  long long n_ = 0;
  std::vector<long long> xs_;
  std::vector<int> xm_;
  std::vector<double> send_, recv_;
  std::vector<int> scount_, sdispl_, rcount_, rdispl_;
};

} // namespace suite::euler
