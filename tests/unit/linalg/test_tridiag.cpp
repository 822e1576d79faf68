// Tridiagonal solvers: Thomas, cyclic Sherman-Morrison, verified block Thomas with banded-LU fallback,
// against a dense Eigen solve; non-diagonally-dominant (CRWENO-type) rows must not break the solve.
#include "linalg/tridiag.hpp"
#include "linalg/tridiag_distributed.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

using namespace suite::linalg;

namespace {
Eigen::MatrixXd dense(int nb, int bs, const std::vector<double>& A, const std::vector<double>& B,
                      const std::vector<double>& C, bool periodic) {
  const int n = nb * bs;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < nb; ++i) {
    const int im = i > 0 ? i - 1 : (periodic ? nb - 1 : -1), ip = i < nb - 1 ? i + 1 : (periodic ? 0 : -1);
    for (int p = 0; p < bs; ++p)
      for (int q = 0; q < bs; ++q) {
        M(i * bs + p, i * bs + q) += B[i * bs * bs + p * bs + q];
        if (im >= 0) M(i * bs + p, im * bs + q) += A[i * bs * bs + p * bs + q];
        if (ip >= 0) M(i * bs + p, ip * bs + q) += C[i * bs * bs + p * bs + q];
      }
  }
  return M;
}

void randomSystem(int nb, int bs, double diag, unsigned seed, std::vector<double>* A, std::vector<double>* B,
                  std::vector<double>* C, std::vector<double>* d) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  A->resize(nb * bs * bs);
  B->resize(nb * bs * bs);
  C->resize(nb * bs * bs);
  d->resize(nb * bs);
  for (auto& x : *A) x = u(gen);
  for (auto& x : *C) x = u(gen);
  for (int i = 0; i < nb * bs * bs; ++i) (*B)[i] = u(gen) + ((i % (bs * bs)) % (bs + 1) == 0 ? diag : 0.0);
  for (auto& x : *d) x = u(gen);
}
} // namespace

TEST(Tridiag, ThomasMatchesDense) {
  const int n = 50;
  std::vector<double> A, B, C, d;
  randomSystem(n, 1, 4.0, 1, &A, &B, &C, &d);
  Eigen::VectorXd ref = dense(n, 1, A, B, C, false).lu().solve(Eigen::Map<Eigen::VectorXd>(d.data(), n));
  ASSERT_TRUE(thomas(n, A.data(), B.data(), C.data(), d.data()));
  for (int i = 0; i < n; ++i) EXPECT_NEAR(d[i], ref(i), 1e-12);
}

TEST(Tridiag, CyclicThomasMatchesDense) {
  const int n = 37;
  std::vector<double> A, B, C, d;
  randomSystem(n, 1, 4.0, 2, &A, &B, &C, &d);
  Eigen::VectorXd ref = dense(n, 1, A, B, C, true).lu().solve(Eigen::Map<Eigen::VectorXd>(d.data(), n));
  ASSERT_TRUE(cyclicThomas(n, A.data(), B.data(), C.data(), d.data()));
  for (int i = 0; i < n; ++i) EXPECT_NEAR(d[i], ref(i), 1e-12);
}

TEST(Tridiag, BlockSolverNonDominantAndPeriodic) {
  for (bool periodic : {false, true})
    for (int bs : {1, 3})
      for (double diag : {4.0, 0.0}) { // diag 0: far from diagonally dominant
        const int nb = 40;
        std::vector<double> A, B, C, d;
        randomSystem(nb, bs, diag, 7 + bs, &A, &B, &C, &d);
        Eigen::MatrixXd M = dense(nb, bs, A, B, C, periodic);
        Eigen::VectorXd ref = M.fullPivLu().solve(Eigen::Map<Eigen::VectorXd>(d.data(), nb * bs));
        BlockTridiagSolver s;
        s.solve(nb, bs, A.data(), B.data(), C.data(), d.data(), periodic);
        const double scale = ref.cwiseAbs().maxCoeff();
        for (int i = 0; i < nb * bs; ++i)
          EXPECT_NEAR(d[i], ref(i), 1e-9 * scale) << "bs " << bs << " diag " << diag;
      }
}

TEST(Tridiag, CrwenoRowWithOmega1AboveHalfForcesPivoting) {
  // Rows that are not diagonally dominant (b < a + c, as CRWENO5 rows with omega_1 > 1/2) whose leading 2x2
  // minor is singular: block Thomas hits a zero pivot at row 1, the banded LU with partial pivoting must
  // still solve the (nonsingular) system.
  const int n = 6;
  std::vector<double> A = {0, 1. / 3, 0.3, 0.3, 0.3, 0.3}, B = {1. / 3, 1. / 3, 0.6, 0.6, 0.6, 0.6},
                      C = {1. / 3, 1. / 3, 0.1, 0.1, 0.1, 0}, d = {1, 2, 3, 4, 5, 6};
  Eigen::MatrixXd M = dense(n, 1, A, B, C, false);
  ASSERT_GT(std::abs(M.determinant()), 1e-6);
  Eigen::VectorXd ref = M.lu().solve(Eigen::Map<Eigen::VectorXd>(d.data(), n));
  BlockTridiagSolver s;
  s.solve(n, 1, A.data(), B.data(), C.data(), d.data(), false);
  EXPECT_EQ(s.stats().lu_fallbacks, 1);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(d[i], ref(i), 1e-12);
}

TEST(Tridiag, DistributedScalarOnOneRankEqualsSerial) {
  const int n = 30;
  std::vector<double> A, B, C, d;
  randomSystem(n, 1, 4.0, 3, &A, &B, &C, &d);
  std::vector<double> abc(3 * n);
  for (int i = 0; i < n; ++i) abc[3 * i] = A[i], abc[3 * i + 1] = B[i], abc[3 * i + 2] = C[i];
  std::vector<double> x(n + 1), ref = d;
  ASSERT_TRUE(cyclicThomas(n, A.data(), B.data(), C.data(), ref.data()));
  DistributedTridiag dt;
  dt.solveScalar(MPI_COMM_SELF, n, abc.data(), 1, d.data(), true, 0, n + 1, x.data());
  for (int i = 0; i <= n; ++i) EXPECT_NEAR(x[i], ref[i % n], 1e-13);
}
