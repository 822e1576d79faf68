// Batched substructured block-tridiagonal line solves (lib/linalg/substructured_block_lines) against a dense
// LU of every global line, assembled on every rank from the same pseudo-random rows: block sizes 1 to 5,
// scalar rows with 1, 3, 4, 5 and 7 right-hand sides, periodic and open lines, count = nloc and nloc + 1,
// uneven rows per rank (rank r holds base + (5 r) % 7 rows, base >= 2), batches that mix strongly dominant,
// dominant and not dominant lines with lines that are far from diagonally dominant (a zero diagonal block:
// the substructured elimination must give up and the exact fallback must solve them), 1 and 300 lines, the
// band/Woodbury reduced solve and the gathered band-LU fallback for every line. Tolerance: 1e-12 of the
// largest solution entry of each line, except for the not dominant random lines, whose condition numbers
// (up to ~1e4) make any two exact solvers differ by more: for them the residual of the global system is
// checked against the solver's criterion. Run at 1 to 4 ranks.
#include "linalg/substructured_block_lines.hpp"

#include <petscsys.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// Kinds of lines: off-diagonal blocks scaled by 0.3 (strongly dominant), 0.7 (dominant), 1.0 (not dominant
// on many rows; random, so condition numbers up to ~1e4), and "far": off-diagonal scale 0.5 and a zero
// diagonal block in global row 0 (block Thomas without pivoting across rows breaks down at the first row of
// rank 0, at every rank count; the line itself is well conditioned).
enum Kind { kStrong = 0, kDominant = 1, kWeak = 2, kFar = 3 };

struct Config {
  int bs = 3;              // block size
  int nrhs = 1;            // right-hand sides; > 1 or scalar = true: solveScalar (bs must be 1)
  bool scalar = false;     // use solveScalar
  int nlines = 5;          // lines in the batch
  bool periodic = false;   // periodic lines
  bool withNext = false;   // count = nloc + 1 where a next row exists
  int base = 2;            // rank r holds base + (5 r) % 7 rows
  std::vector<int> kinds;  // kind of line l: kinds[l % kinds.size()]
  int denseMax = -1;       // reduced_dense_max (-1: default)
  double tolerance = -1.0; // solver tolerance (< 0: default; 0 sends every line to the fallback)
  unsigned seed = 1;
};

struct Outcome {
  double err = 0.0;                         // max over lines of max |x - x_dense| / max |x_dense|
  double errKind[4] = {0.0, 0.0, 0.0, 0.0}; // the same per kind of line
  double res = 0.0; // max over lines of the backward error |T x - d| / (|T| |x| + |d|) (max-norms, global)
  long long fallbacks = 0, solves = 0, lines = 0;
  int far = 0, weak = 0; // lines of these kinds in the batch
};

Outcome run(const Config& cfg) {
  int P = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  std::vector<int> offset(P + 1, 0);
  for (int r = 0; r < P; ++r) offset[r + 1] = offset[r] + cfg.base + (5 * r) % 7;
  const int nb = offset[P], bs = cfg.bs, bb = bs * bs, nr = cfg.nrhs;
  const int first = offset[rank], n = offset[rank + 1] - first;
  const bool hasNext = rank + 1 < P || cfg.periodic;
  const int count = cfg.withNext && hasNext ? n + 1 : n;

  // Global lines, identical on every rank.
  std::mt19937_64 gen(cfg.seed + 101u * bs + 7u * nr + (cfg.periodic ? 3u : 0u));
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const size_t L = cfg.nlines;
  std::vector<double> A(L * nb * bb), B(A.size()), C(A.size()), d(L * nb * bs * nr);
  Outcome out;
  for (size_t l = 0; l < L; ++l) {
    const int kind = cfg.kinds[l % cfg.kinds.size()];
    out.far += kind == kFar;
    out.weak += kind == kWeak;
    const double off = kind == kStrong ? 0.3 : kind == kDominant ? 0.7 : kind == kWeak ? 1.0 : 0.5;
    for (int i = 0; i < nb; ++i)
      for (int e = 0; e < bb; ++e) {
        const bool diag = e % (bs + 1) == 0;
        const size_t k = (l * nb + i) * bb + e;
        A[k] = off * (diag ? 0.5 + 0.3 * U(gen) : 0.2 * U(gen));
        C[k] = off * (diag ? 0.4 + 0.3 * U(gen) : 0.2 * U(gen));
        B[k] = (kind == kFar && i == 0) ? 0.0 : (diag ? 1.0 + 0.1 * U(gen) : 0.3 * U(gen));
      }
    for (int e = 0; e < nb * bs * nr; ++e) d[l * nb * bs * nr + e] = U(gen);
  }

  // This rank's rows, line by line.
  std::vector<double> a((size_t)L * n * bb), b(a.size()), c(a.size()), dl(L * n * bs * nr),
      x(L * count * bs * nr, 0.0);
  for (size_t l = 0; l < L; ++l) {
    for (int i = 0; i < n * bb; ++i) {
      a[l * n * bb + i] = A[(l * nb + first) * bb + i];
      b[l * n * bb + i] = B[(l * nb + first) * bb + i];
      c[l * n * bb + i] = C[(l * nb + first) * bb + i];
    }
    for (int i = 0; i < n * bs * nr; ++i) dl[l * n * bs * nr + i] = d[(l * nb + first) * bs * nr + i];
  }
  suite::linalg::SubstructuredBlockLines solver;
  if (cfg.denseMax >= 0) solver.reduced_dense_max = cfg.denseMax;
  if (cfg.tolerance >= 0.0) solver.tolerance = cfg.tolerance;

  for (int rep = 0; rep < 2; ++rep) { // twice: the work arrays are reused
    std::fill(x.begin(), x.end(), 0.0);
    if (cfg.scalar) {
      std::vector<double> abc(3 * L * n);
      for (size_t k = 0; k < L * n; ++k) abc[3 * k] = a[k], abc[3 * k + 1] = b[k], abc[3 * k + 2] = c[k];
      solver.solveScalar(PETSC_COMM_WORLD, (int)L, n, abc.data(), nr, dl.data(), cfg.periodic, first, count,
                         x.data());
    } else {
      solver.solve(PETSC_COMM_WORLD, bs, (int)L, n, a.data(), b.data(), c.data(), dl.data(), cfg.periodic,
                   first, count, x.data());
    }
  }

  // The whole solution of every line on every rank (for the residual of the global systems).
  std::vector<int> counts(P), displs(P);
  for (int r = 0; r < P; ++r)
    counts[r] = (int)L * (offset[r + 1] - offset[r]) * bs * nr, displs[r] = (int)L * offset[r] * bs * nr;
  std::vector<double> mine(L * n * bs * nr), all(L * nb * bs * nr);
  for (size_t l = 0; l < L; ++l)
    std::copy(x.begin() + l * count * bs * nr, x.begin() + (l * count + n) * bs * nr,
              mine.begin() + l * n * bs * nr);
  MPI_Allgatherv(mine.data(), (int)mine.size(), MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, PETSC_COMM_WORLD);

  // Dense reference of each line, lines shared out over the ranks (line l on rank l % P), against the
  // gathered solution; every rank also checks its extra row (count = nloc + 1) against the gathered one.
  const int N = nb * bs;
  auto global = [&](size_t l, int g, int p, int k) { // gathered solution, global block row g
    int r = 0;
    while (offset[r + 1] <= g) ++r;
    const int rows = offset[r + 1] - offset[r];
    return all[displs[r] + ((l * rows + (g - offset[r])) * bs + p) * nr + k];
  };
  for (size_t l = 0; l < L; ++l) {
    const int kind = cfg.kinds[l % cfg.kinds.size()];
    if (count == n + 1) {
      double diff = 0.0, scale = 0.0;
      for (int p = 0; p < bs; ++p)
        for (int k = 0; k < nr; ++k) {
          const double v = x[((l * count + n) * bs + p) * nr + k], w = global(l, (first + n) % nb, p, k);
          diff = std::max(diff, std::isfinite(v) ? std::abs(v - w) : 1e300);
        }
      for (int g = 0; g < nb; ++g)
        for (int p = 0; p < bs; ++p)
          for (int k = 0; k < nr; ++k) scale = std::max(scale, std::abs(global(l, g, p, k)));
      out.err = std::max(out.err, diff / scale);
      out.errKind[kind] = std::max(out.errKind[kind], diff / scale);
    }
    if ((int)(l % P) != rank) continue;
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(N, N), D(N, nr), Xs(N, nr);
    for (int i = 0; i < nb; ++i)
      for (int p = 0; p < bs; ++p) {
        for (int q = 0; q < bs; ++q) {
          const size_t k = (l * nb + i) * bb + p * bs + q;
          T(i * bs + p, i * bs + q) += B[k];
          if (i > 0 || cfg.periodic) T(i * bs + p, ((i - 1 + nb) % nb) * bs + q) += A[k];
          if (i + 1 < nb || cfg.periodic) T(i * bs + p, ((i + 1) % nb) * bs + q) += C[k];
        }
        for (int k = 0; k < nr; ++k) {
          D(i * bs + p, k) = d[((l * nb + i) * bs + p) * nr + k];
          Xs(i * bs + p, k) = global(l, i, p, k);
        }
      }
    const Eigen::MatrixXd X = T.partialPivLu().solve(D);
    const double scale = X.cwiseAbs().maxCoeff();
    const double lineErr = Xs.allFinite() ? (Xs - X).cwiseAbs().maxCoeff() / scale : 1e300;
    out.err = std::max(out.err, lineErr);
    out.errKind[kind] = std::max(out.errKind[kind], lineErr);
    // Normwise backward error (max-norms): scale invariant, ~eps for a backward-stable solve.
    const double res =
        (T * Xs - D).cwiseAbs().maxCoeff() /
        (T.cwiseAbs().rowwise().sum().maxCoeff() * Xs.cwiseAbs().maxCoeff() + D.cwiseAbs().maxCoeff());
    out.res = std::max(out.res, std::isfinite(res) ? res : 1e300);
  }
  MPI_Allreduce(MPI_IN_PLACE, &out.err, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &out.res, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, out.errKind, 4, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  out.fallbacks = solver.stats().fallbacks / 2;
  out.solves = solver.stats().solves;
  out.lines = solver.stats().lines;
  return out;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", v);
  return buf;
}

std::string describe(const Config& c, const Outcome& o) {
  return "backward error " + sci(o.res) + ", error per kind (strong, dominant, weak, far) " +
         sci(o.errKind[0]) + " " + sci(o.errKind[1]) + " " + sci(o.errKind[2]) + " " + sci(o.errKind[3]) +
         ", fallbacks " + std::to_string(o.fallbacks) + "; " + "bs " + std::to_string(c.bs) + ", nrhs " +
         std::to_string(c.nrhs) + (c.scalar ? " (scalar)" : "") + ", " + (c.periodic ? "periodic" : "open") +
         (c.withNext ? ", count nloc+1" : ", count nloc") + ", nlines " + std::to_string(c.nlines) +
         ", dense_max " + std::to_string(c.denseMax);
}

TEST(SubstructuredBlockLines, BlockSizesOneToFive) {
  for (int bs = 1; bs <= 5; ++bs)
    for (bool periodic : {false, true})
      for (bool withNext : {false, true}) {
        Config c;
        c.bs = bs, c.periodic = periodic, c.withNext = withNext, c.nlines = 6,
        c.kinds = std::vector<int>({kStrong, kDominant});
        const Outcome o = run(c);
        EXPECT_LE(o.err, 1e-12) << describe(c, o);
        EXPECT_EQ(o.fallbacks, 0) << describe(c, o) << ": dominant lines must not need the fallback";
        EXPECT_EQ(o.solves, 2);
        EXPECT_EQ(o.lines, 2 * c.nlines);
      }
}

TEST(SubstructuredBlockLines, ScalarRowsSharedByRightHandSides) {
  for (int nrhs : {1, 3, 4, 5, 7}) // 7: the generic (not unrolled) column count
    for (bool periodic : {false, true})
      for (bool withNext : {false, true}) {
        Config c;
        c.bs = 1, c.nrhs = nrhs, c.scalar = true, c.periodic = periodic, c.withNext = withNext, c.nlines = 6;
        c.kinds = std::vector<int>({kStrong, kDominant});
        const Outcome o = run(c);
        EXPECT_LE(o.err, 1e-12) << describe(c, o);
        EXPECT_EQ(o.fallbacks, 0) << describe(c, o);
      }
}

TEST(SubstructuredBlockLines, MixedDominanceFallsBackOnlyWhereNeeded) {
  for (int variant = 0; variant < 3; ++variant)
    for (bool periodic : {false, true}) {
      Config c;
      c.bs = variant == 0 ? 4 : variant == 1 ? 5 : 1;
      c.nrhs = variant == 2 ? 5 : 1;
      c.scalar = variant == 2;
      c.periodic = periodic, c.withNext = true, c.nlines = 300, c.base = 3;
      c.kinds = std::vector<int>({kStrong, kDominant, kWeak, kFar});
      const Outcome o = run(c);
      for (int kind : {kStrong, kDominant, kFar}) EXPECT_LE(o.errKind[kind], 1e-12) << describe(c, o);
      // Weak lines (condition numbers up to ~1e4: an error bound would measure the conditioning, not the
      // solver): the solver's acceptance criterion max |T x - d| <= 1e-10 max |d| bounds the backward error.
      EXPECT_LE(o.res, 1e-10) << describe(c, o);
      // Every far line must fall back (its first block pivot is zero); the dominant ones never.
      EXPECT_GE(o.fallbacks, o.far) << describe(c, o);
      EXPECT_LE(o.fallbacks, o.far + o.weak) << describe(c, o);
      EXPECT_GT(o.fallbacks, 0) << describe(c, o);
    }
}

TEST(SubstructuredBlockLines, ExactFallbackForEveryLine) {
  // tolerance 0: every line goes through the gathered band LU (folded order when periodic).
  for (int variant = 0; variant < 3; ++variant)
    for (bool periodic : {false, true}) {
      Config c;
      c.bs = variant == 0 ? 4 : variant == 1 ? 5 : 1;
      c.nrhs = variant == 2 ? 5 : 1;
      c.scalar = variant == 2;
      c.periodic = periodic, c.withNext = true, c.nlines = 300, c.base = 3, c.tolerance = 0.0;
      c.kinds = std::vector<int>({kStrong, kDominant, kWeak, kFar});
      const Outcome o = run(c);
      for (int kind : {kStrong, kDominant, kFar}) EXPECT_LE(o.errKind[kind], 1e-12) << describe(c, o);
      EXPECT_LE(o.res, 1e-14) << describe(c, o) << ": band LU with partial pivoting is backward stable";
      EXPECT_EQ(o.fallbacks, c.nlines) << describe(c, o);
    }
}

TEST(SubstructuredBlockLines, SingleLine) {
  for (int kind : {kDominant, kFar})
    for (bool periodic : {false, true}) {
      Config c;
      c.bs = 5, c.periodic = periodic, c.withNext = true, c.nlines = 1, c.base = 3,
      c.kinds = std::vector<int>({kind});
      const Outcome o = run(c);
      EXPECT_LE(o.err, 1e-12) << describe(c, o) << ", kind " << kind;
      EXPECT_EQ(o.fallbacks, kind == kFar ? 1 : 0) << describe(c, o) << ", kind " << kind;
    }
}

TEST(SubstructuredBlockLines, BandAndWoodburyReducedSolve) {
  for (int variant = 0; variant < 3; ++variant)
    for (bool periodic : {false, true}) {
      Config c;
      c.bs = variant == 0 ? 3 : variant == 1 ? 5 : 1;
      c.nrhs = variant == 2 ? 4 : 1;
      c.scalar = variant == 2;
      c.periodic = periodic, c.withNext = true, c.nlines = 9, c.denseMax = 0;
      c.kinds = std::vector<int>({kStrong, kDominant, kFar});
      const Outcome o = run(c);
      EXPECT_LE(o.err, 1e-12) << describe(c, o);
      EXPECT_EQ(o.fallbacks, o.far) << describe(c, o);
    }
}

namespace {
// nlines open lines of n rows of bs x bs blocks (this rank's rows): diagonal blocks holding their largest
// entries off the diagonal (row exchanges in most pivot steps, differing from lane to lane); line far's first
// diagonal block is zero (far >= nlines: none).
struct LaneLines {
  std::vector<double> A, B, C, d;
};
LaneLines laneLines(int bs, int n, int nlines, int far, std::mt19937_64& gen) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const int bb = bs * bs;
  LaneLines L{
      std::vector<double>((size_t)nlines * n * bb), {}, {}, std::vector<double>((size_t)nlines * n * bs)};
  L.B = L.A, L.C = L.A;
  for (int l = 0; l < nlines; ++l)
    for (int i = 0; i < n; ++i) {
      const size_t row = ((size_t)l * n + i) * bb;
      const int shift = 1 + (int)((l + i) % (bs - 1)); // column of row a holding its large entry: a + shift
      for (int a = 0; a < bs; ++a)
        for (int b = 0; b < bs; ++b) {
          L.A[row + a * bs + b] = 0.3 * U(gen), L.C[row + a * bs + b] = 0.3 * U(gen);
          L.B[row + a * bs + b] =
              (b == (a + shift) % bs ? 4.0 : 0.5) * U(gen) + (b == (a + shift) % bs ? 4.0 : 0.0);
        }
      if (l == far && i == 0)
        for (int e = 0; e < bb; ++e) L.B[row + e] = 0.0;
    }
  for (double& v : L.d) v = U(gen);
  return L;
}

// Solves the lines together (*all) and one by one (*one); asserts each line's solution bitwise the same.
void expectLanesBitwiseAlone(int bs, int n, int nlines, const LaneLines& L,
                             suite::linalg::SubstructuredBlockLines* all,
                             suite::linalg::SubstructuredBlockLines* one) {
  const int bb = bs * bs;
  std::vector<double> x_all(L.d.size()), x_one(L.d.size());
  all->solve(PETSC_COMM_WORLD, bs, nlines, n, L.A.data(), L.B.data(), L.C.data(), L.d.data(), false, 0, n,
             x_all.data());
  for (int l = 0; l < nlines; ++l) {
    const size_t r = (size_t)l * n * bb, v = (size_t)l * n * bs;
    one->solve(PETSC_COMM_WORLD, bs, 1, n, L.A.data() + r, L.B.data() + r, L.C.data() + r, L.d.data() + v,
               false, 0, n, x_one.data() + v);
  }
  for (size_t k = 0; k < L.d.size(); ++k)
    ASSERT_EQ(x_all[k], x_one[k]) << "bs " << bs << ", line " << k / ((size_t)n * bs) << ", entry " << k;
}
} // namespace

// Open lines are solved four at a time, one per SIMD lane (block_thomas_lanes.hpp): on one rank the whole line,
// on several the second pass of each rank's rows with the neighbour values moved to the right-hand side. Each
// line's solution must be bitwise the one it gets solved alone. One batch holds a line whose first diagonal
// block on every rank is zero (the lanes give up, the four lines go one by one, that one to the fallback).
TEST(SubstructuredBlockLines, FourLinesAtOnceAreBitwiseEachLineAlone) {
  int rank = 0, P = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  std::mt19937_64 gen(7 + rank); // this rank's rows of the lines
  for (int bs = 3; bs <= 5; ++bs) {
    const int n = 7, nlines = 9, far = 5;
    suite::linalg::SubstructuredBlockLines all, one;
    expectLanesBitwiseAlone(bs, n, nlines, laneLines(bs, n, nlines, far, gen), &all, &one);
    EXPECT_EQ(all.stats().fallbacks, 1) << "bs " << bs << ": the line with a zero diagonal block";
    // Lines 0-3 went four at a time (on one rank the sweep; on several pass 1 and pass 2), lines 4-7 did not
    // (line 5's pivot), line 8 is alone; solved alone, no line went four at a time.
    EXPECT_EQ(all.stats().lane_batches, P == 1 ? 1 : 2) << "bs " << bs;
    EXPECT_EQ(one.stats().lane_batches, 0) << "bs " << bs;
  }
}

// On one rank two or three lines (a 1D line's two systems) go through the four lanes too, the spare lanes
// repeating the first line: still bitwise each line alone, and one lane batch. On several ranks (the passes
// take full batches only) they go one by one.
TEST(SubstructuredBlockLines, TwoOrThreeLinesShareTheFourLanes) {
  int rank = 0, P = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  std::mt19937_64 gen(11 + rank);
  for (int bs = 3; bs <= 5; ++bs)
    for (int nlines : {2, 3, 6}) { // 6: a full batch, then two lines
      const int n = 9;
      suite::linalg::SubstructuredBlockLines all, one;
      expectLanesBitwiseAlone(bs, n, nlines, laneLines(bs, n, nlines, nlines, gen), &all, &one);
      EXPECT_EQ(all.stats().lane_batches, P == 1 ? (nlines + 3) / 4 : 2 * (nlines / 4))
          << "bs " << bs << ", " << nlines << " lines";
    }
}

TEST(SubstructuredBlockLines, RejectsBadArguments) {
  int P = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  std::vector<double> v(1000, 1.0), x(1000);
  suite::linalg::SubstructuredBlockLines s;
  EXPECT_THROW(
      s.solve(PETSC_COMM_WORLD, 6, 1, 4, v.data(), v.data(), v.data(), v.data(), false, 0, 4, x.data()),
      std::invalid_argument);
  EXPECT_THROW(
      s.solve(PETSC_COMM_WORLD, 3, 1, 1, v.data(), v.data(), v.data(), v.data(), false, 0, 1, x.data()),
      std::invalid_argument);
  EXPECT_THROW(s.solveScalar(PETSC_COMM_WORLD, 1, 4, v.data(), 0, v.data(), false, 0, 4, x.data()),
               std::invalid_argument);
  if (rank == P - 1) { // no next row on the last rank of an open line
    EXPECT_THROW(
        s.solve(PETSC_COMM_WORLD, 2, 1, 4, v.data(), v.data(), v.data(), v.data(), false, 0, 5, x.data()),
        std::invalid_argument);
  }
  EXPECT_EQ(s.stats().solves, 0);
}

} // namespace
