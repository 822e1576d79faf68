// Substructured parallel tridiagonal line solves against a dense LU of the global systems: non-periodic and
// periodic lines, rows that are not diagonally dominant, uneven and one-row blocks; run at 1 to 6 ranks
// (6 ranks exercise the banded + Woodbury reduced solve, fewer the dense one).
#include "linalg/substructured_lines.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

struct Lines {
  int nglobal;
  std::vector<int> offset;    // first global row of each rank
  Eigen::MatrixXd a, b, c, d; // (nlines x nglobal)
};

// Every rank builds the same global lines (same seed) and takes its rows; rank r has 1 + (r * 3) % 5 rows.
Lines makeLines(int P, int nlines, unsigned seed, double max_off_sum) {
  Lines L;
  L.offset.assign(P + 1, 0);
  for (int r = 0; r < P; ++r) L.offset[r + 1] = L.offset[r] + 1 + (r * 3) % 5;
  L.nglobal = L.offset[P];
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  L.a.resize(nlines, L.nglobal), L.b = L.c = L.d = L.a;
  for (int l = 0; l < nlines; ++l)
    for (int i = 0; i < L.nglobal; ++i) {
      const double t = U(gen);
      L.a(l, i) = max_off_sum * (0.2 + 0.6 * t); // e.g. CRWENO rows: omega_1 up to 0.7 > 1/2
      L.c(l, i) = max_off_sum * 0.8 * (1.0 - t) * U(gen);
      L.b(l, i) = 1.0;
      L.d(l, i) = 2.0 * U(gen) - 1.0;
    }
  return L;
}

Eigen::VectorXd denseSolve(const Lines& L, int l, bool periodic) {
  const int n = L.nglobal;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    T(i, i) += L.b(l, i);
    if (i > 0)
      T(i, i - 1) += L.a(l, i);
    else if (periodic)
      T(i, n - 1) += L.a(l, i);
    if (i < n - 1)
      T(i, i + 1) += L.c(l, i);
    else if (periodic)
      T(i, 0) += L.c(l, i);
  }
  return T.partialPivLu().solve(L.d.row(l).transpose());
}

void check(bool periodic, double max_off_sum) {
  int P, rank;
  MPI_Comm_size(PETSC_COMM_WORLD, &P);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const int nlines = 7;
  Lines L = makeLines(P, nlines, 42u + periodic, max_off_sum);
  const int first = L.offset[rank], m = L.offset[rank + 1] - first;
  std::vector<double> a, b, c, d;
  for (int l = 0; l < nlines; ++l)
    for (int i = first; i < first + m; ++i) {
      a.push_back(L.a(l, i)), b.push_back(L.b(l, i)), c.push_back(L.c(l, i)), d.push_back(L.d(l, i));
    }
  suite::linalg::SubstructuredLines solver;
  ASSERT_EQ(solver.solve(PETSC_COMM_WORLD, nlines, m, a.data(), b.data(), c.data(), d.data(), periodic), 0);
  double worst = 0.0;
  for (int l = 0; l < nlines; ++l) {
    Eigen::VectorXd x = denseSolve(L, l, periodic);
    for (int i = 0; i < m; ++i)
      worst = std::max(worst, std::abs(d[(size_t)l * m + i] - x(first + i)) / x.cwiseAbs().maxCoeff());
  }
  double all = 0.0;
  MPI_Allreduce(&worst, &all, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  EXPECT_LE(all, 1e-12) << "P = " << P << (periodic ? " periodic" : "");
}

TEST(SubstructuredLines, DiagonallyDominantLines) {
  check(false, 0.9);
}
TEST(SubstructuredLines, DiagonallyDominantPeriodicLines) {
  check(true, 0.9);
}
TEST(SubstructuredLines, RowsNotDiagonallyDominant) {
  check(false, 1.5);
}
TEST(SubstructuredLines, PeriodicRowsNotDiagonallyDominant) {
  check(true, 1.5);
}

} // namespace
