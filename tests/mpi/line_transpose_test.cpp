// Pencil transpose of grid lines (lib/euler/line_transpose): every rank holds a segment (uneven: rank r has
// 3 + (5 r) % 7 cells) of the same lines, stored with 3 ghost cells on each side, the values being a known
// function of (line, cell, component). gather() must deliver to each rank exactly the whole lines it owns
// (round-robin: lines r, r + P, ...) with the domain-end ghosts of the first and last ranks; scatter() of
// per-face values of those lines must return to every rank the faces of its own segment. Both checked exactly
// (the values are copied, never computed), for 0, 1, P - 1, P and 37 lines; plus the refusal of segments that
// do not tile the line. Run at 1 to 4 ranks.
#include "euler/line_transpose.hpp"

#include <petscsys.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

constexpr int kGhost = 3, kWidth = 4;

// Value of component c of stored cell m (m = 0 is the first left ghost, so cell index m - kGhost) of line l.
double cellValue(int l, long long m, int c) {
  return 1e6 * l + 10.0 * m + c;
}
double faceValue(int l, long long k, int c) {
  return -1e6 * l - 10.0 * k - c - 0.5;
}

struct Layout {
  int rank = 0, size = 1;
  long long n = 0, xs = 0;
  int xm = 0;
};

Layout layout() {
  Layout L;
  MPI_Comm_rank(PETSC_COMM_WORLD, &L.rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &L.size);
  for (int r = 0; r < L.size; ++r) {
    const int m = 3 + (5 * r) % 7;
    if (r == L.rank) L.xs = L.n, L.xm = m;
    L.n += m;
  }
  return L;
}

void roundTrip(int nlines) {
  const Layout L = layout();
  suite::euler::LineTranspose tr(PETSC_COMM_WORLD, L.n, L.xs, L.xm, kGhost);
  EXPECT_TRUE(tr.matches(PETSC_COMM_WORLD, L.n, L.xs, L.xm));
  EXPECT_FALSE(tr.matches(PETSC_COMM_WORLD, L.n + 1, L.xs, L.xm));
  const int ncell = L.xm + 2 * kGhost;
  std::vector<double> q((size_t)nlines * ncell * kWidth);
  for (int l = 0; l < nlines; ++l)
    for (int m = 0; m < ncell; ++m)
      for (int c = 0; c < kWidth; ++c) q[((size_t)l * ncell + m) * kWidth + c] = cellValue(l, L.xs + m, c);
  std::vector<double> full;
  tr.gather(q.data(), kWidth, nlines, &full);
  const int own = tr.owned(nlines);
  int expect_own = 0;
  for (int l = L.rank; l < nlines; l += L.size) ++expect_own;
  ASSERT_EQ(own, expect_own);
  const long long fcell = L.n + 2 * kGhost;
  ASSERT_EQ(full.size(), (size_t)own * fcell * kWidth);
  long long bad = 0;
  for (int k = 0; k < own; ++k) {
    const int l = L.rank + k * L.size; // global line of the k-th owned line
    for (long long m = 0; m < fcell; ++m)
      for (int c = 0; c < kWidth; ++c)
        bad += full[((size_t)k * fcell + m) * kWidth + c] != cellValue(l, m, c);
  }
  EXPECT_EQ(bad, 0) << "gather: wrong cells";

  std::vector<double> hfull((size_t)own * (L.n + 1) * kWidth);
  for (int k = 0; k < own; ++k)
    for (long long f = 0; f <= L.n; ++f)
      for (int c = 0; c < kWidth; ++c)
        hfull[((size_t)k * (L.n + 1) + f) * kWidth + c] = faceValue(L.rank + k * L.size, f, c);
  std::vector<double> h((size_t)nlines * (L.xm + 1) * kWidth, 0.0);
  tr.scatter(hfull.data(), kWidth, nlines, h.data());
  bad = 0;
  for (int l = 0; l < nlines; ++l)
    for (int f = 0; f <= L.xm; ++f)
      for (int c = 0; c < kWidth; ++c)
        bad += h[((size_t)l * (L.xm + 1) + f) * kWidth + c] != faceValue(l, L.xs + f, c);
  EXPECT_EQ(bad, 0) << "scatter: wrong faces";
}

TEST(LineTranspose, RoundTripAnyLineCount) {
  int P = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  for (int nlines : {0, 1, P - 1, P, 37}) {
    SCOPED_TRACE("nlines " + std::to_string(nlines));
    roundTrip(nlines);
  }
}

TEST(LineTranspose, RefusesSegmentsThatDoNotTile) {
  const Layout L = layout();
  // every rank claims one cell more than it has: the segments overlap (or, at 1 rank, overrun the line)
  EXPECT_THROW(suite::euler::LineTranspose(PETSC_COMM_WORLD, L.n, L.xs, L.xm + 1, kGhost),
               std::invalid_argument);
}

} // namespace
