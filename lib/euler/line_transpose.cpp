// Pencil transpose of the lines of one grid direction (see line_transpose.hpp).
#include "euler/line_transpose.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

namespace suite::euler {

LineTranspose::LineTranspose(MPI_Comm comm, long long n, long long xs, int xm, int ghost)
    : comm_(comm), ghost_(ghost), n_(n) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
  std::vector<long long> seg(2 * (size_t)size_);
  const long long mine[2] = {xs, xm};
  MPI_Allgather(mine, 2, MPI_LONG_LONG, seg.data(), 2, MPI_LONG_LONG, comm);
  xs_.resize(size_);
  xm_.resize(size_);
  long long next = 0;
  bool tiled = true;
  for (int r = 0; r < size_; ++r) {
    xs_[r] = seg[2 * r];
    xm_[r] = (int)seg[2 * r + 1];
    tiled = tiled && xs_[r] == next && xm_[r] >= 1;
    next = xs_[r] + xm_[r];
  }
  if (!tiled || next != n)
    throw std::invalid_argument("LineTranspose: the segments of the ranks do not tile the line of " +
                                std::to_string(n) + " cells in rank order");
}

// to_owner: every rank's segments of each line go to the line's owner (gather); else the owner's face values
// of each segment go back to the segment's rank (scatter). Fills the counts and displacements (in doubles) and
// runs the MPI_Alltoallv; send_ is packed and recv_ unpacked by the callers. Nothing is sent to this rank itself.
void LineTranspose::exchange(int width, int count, bool to_owner) {
  if ((long long)count * (n_ + 2 * ghost_ + 1) * width > INT_MAX)
    throw std::invalid_argument("LineTranspose: batch of " + std::to_string(count) +
                                " lines too large for one MPI_Alltoallv");
  scount_.assign(size_, 0);
  rcount_.assign(size_, 0);
  for (int r = 0; r < size_; ++r) {
    if (r == rank_) continue; // this rank's own share is copied directly, not sent to itself
    if (to_owner) {
      scount_[r] = linesOf(r, count) * cellsSent(rank_);
      rcount_[r] = owned(count) * cellsSent(r);
    } else {
      scount_[r] = owned(count) * (xm_[r] + 1);
      rcount_[r] = linesOf(r, count) * (xm_[rank_] + 1);
    }
    scount_[r] *= width;
    rcount_[r] *= width;
  }
  sdispl_.assign(size_, 0);
  rdispl_.assign(size_, 0);
  for (int r = 1; r < size_; ++r) {
    sdispl_[r] = sdispl_[r - 1] + scount_[r - 1];
    rdispl_[r] = rdispl_[r - 1] + rcount_[r - 1];
  }
  recv_.resize((size_t)rdispl_[size_ - 1] + rcount_[size_ - 1]);
  MPI_Alltoallv(send_.data(), scount_.data(), sdispl_.data(), MPI_DOUBLE, recv_.data(), rcount_.data(),
                rdispl_.data(), MPI_DOUBLE, comm_);
}

void LineTranspose::gather(const double* q, int width, int count, std::vector<double>* full) {
  const int g = ghost_, P = size_, own = owned(count);
  const size_t stored = (size_t)(xm_[rank_] + 2 * g) * width, seg = (size_t)cellsSent(rank_) * width;
  const size_t lo = (size_t)firstSent(rank_) * width;
  send_.resize((size_t)(count - own) * seg);
  double* s = send_.data();
  for (int r = 0; r < P; ++r) // destination r: lines r, r + P, ...
    if (r != rank_)
      for (int j = r; j < count; j += P, s += seg) std::copy_n(q + j * stored + lo, seg, s);
  exchange(width, count, true);
  const size_t line = (size_t)(n_ + 2 * g) * width;
  full->resize((size_t)own * line);
  for (int r = 0; r < P; ++r) {
    const size_t rseg = (size_t)cellsSent(r) * width;
    double* dst = full->data() + (size_t)(xs_[r] + firstSent(r)) * width;
    if (r == rank_) { // this rank's segments of its own lines
      for (int k = 0; k < own; ++k)
        std::copy_n(q + (size_t)(rank_ + k * P) * stored + lo, rseg, dst + k * line);
      continue;
    }
    const double* src = recv_.data() + rdispl_[r];
    for (int k = 0; k < own; ++k, src += rseg) std::copy_n(src, rseg, dst + k * line);
  }
}

void LineTranspose::scatter(const double* hfull, int width, int count, double* h) {
  const int P = size_, own = owned(count);
  const size_t line = (size_t)(n_ + 1) * width;
  size_t total = 0;
  for (int r = 0; r < P; ++r)
    if (r != rank_) total += (size_t)own * (xm_[r] + 1) * width;
  send_.resize(total);
  double* s = send_.data();
  for (int r = 0; r < P; ++r) {
    if (r == rank_) continue;
    const size_t faces = (size_t)(xm_[r] + 1) * width;
    for (int k = 0; k < own; ++k, s += faces)
      std::copy_n(hfull + k * line + (size_t)xs_[r] * width, faces, s);
  }
  exchange(width, count, false);
  const size_t faces = (size_t)(xm_[rank_] + 1) * width;
  for (int k = 0; k < own; ++k) // the faces of this rank's own lines
    std::copy_n(hfull + k * line + (size_t)xs_[rank_] * width, faces, h + (size_t)(rank_ + k * P) * faces);
  for (int r = 0; r < P; ++r) {
    if (r == rank_) continue;
    const double* src = recv_.data() + rdispl_[r];
    for (int j = r; j < count; j += P, src += faces) std::copy_n(src, faces, h + j * faces);
  }
}

} // namespace suite::euler
