// -solver cholmod (lib/fem/solver_cholmod.cpp): the numeric factorisation starts no OpenMP team (the threads of
// /proc/self/task before and after it, once OpenBLAS has started its own pool), and its solution equals the one with CHOLMOD's OpenMP
// loops on (-cholmod_openmp) and the skyline solver's on a StVK effective tangent of a 10^3-cell cube.
#include "fem_test_util.hpp"

#include "fem/linear_solver.hpp"
#include "fem/material.hpp"
#include "fem/ordering.hpp"

#include <gtest/gtest.h>

#include <dirent.h>

#include <cmath>
#include <cstdio>

using namespace suite::fem;

namespace {
int threadsOfProcess() {
  int n = 0;
  if (DIR* d = opendir("/proc/self/task")) {
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.') ++n;
    closedir(d);
  }
  return n;
}

std::vector<double> solveWith(const char* name, bool openmp, const SymCsc& A, const std::vector<int>& perm,
                              const std::vector<double>& b, int* threads_added) {
  std::unique_ptr<LinearSolver> s;
  EXPECT_EQ(createLinearSolver(PETSC_COMM_SELF, name, &s), 0);
  PetscOptionsSetValue(nullptr, "-cholmod_openmp", openmp ? "true" : "false");
  EXPECT_EQ(s->setFromOptions(PETSC_COMM_SELF), 0);
  PetscOptionsClearValue(nullptr, "-cholmod_openmp");
  EXPECT_EQ(s->analyze(PETSC_COMM_SELF, A, perm), 0);
  const int before = threadsOfProcess();
  bool ok = false;
  EXPECT_EQ(s->factor(A, &ok), 0);
  EXPECT_TRUE(ok);
  if (threads_added) *threads_added = threadsOfProcess() - before;
  std::vector<double> x(A.n);
  EXPECT_EQ(s->solve(b.data(), x.data()), 0);
  return x;
}
} // namespace

TEST(FemCholmod, FactorisesOnTheCallingThreadWithTheSameAnswer) {
  const TetMesh mesh = femtest::cube(10);
  Lame lame;
  ASSERT_EQ(lameFromYoung(PETSC_COMM_SELF, 1000, 0.3, &lame), 0);
  auto mat = makeStVenantKirchhoff(lame);
  std::vector<char> fixed(3 * mesh.numNodes(), 0);
  for (int v : nodesOnPlane(mesh, 0, 0.0))
    for (int c = 0; c < 3; ++c) fixed[3 * v + c] = 1;
  ElasticModel model;
  ASSERT_EQ(model.setup(PETSC_COMM_SELF, mesh, *mat, fixed), 0);
  const int n = model.numFree();
  std::vector<double> u(n), f(n), K;
  for (int i = 0; i < n; ++i) u[i] = 1e-2 * std::sin(0.1 * i);
  ASSERT_TRUE(model.internalForce(u.data(), f.data(), &K, nullptr));
  const auto M = model.consistentMass(1.0);
  SymCsc A = model.pattern();
  for (size_t k = 0; k < A.val.size(); ++k) A.val[k] = K[k] + 1e4 * M[k];
  OrderingFn fn;
  ASSERT_EQ(findOrdering(PETSC_COMM_SELF, "metis", &fn), 0);
  const auto perm = expandToDofs(fn(model.nodeGraphOf()), model.eq(), n);
  std::vector<double> b(n);
  for (int i = 0; i < n; ++i) b[i] = std::cos(0.3 * i);
  int added_off = -1, added_on = -1;
  solveWith("cholmod", false, A, perm, b, nullptr); // OpenBLAS starts its own thread pool at its first call
  const auto x_off = solveWith("cholmod", false, A, perm, b, &added_off);
  const auto x_on = solveWith("cholmod", true, A, perm, b, &added_on);
  const auto x_sky = solveWith("skyline", false, A, perm, b, nullptr);
  double xn = 0, d_on = 0, d_sky = 0;
  for (int i = 0; i < n; ++i) {
    xn = std::max(xn, std::abs(x_sky[i]));
    d_on = std::max(d_on, std::abs(x_off[i] - x_on[i]));
    d_sky = std::max(d_sky, std::abs(x_off[i] - x_sky[i]));
  }
  std::printf("%d DOFs: threads started by the factorisation: %d (OpenMP off), %d (on); |x_off - x_on| %.2e, "
              "|x_off - x_skyline| %.2e (|x| %.2e)\n",
              n, added_off, added_on, d_on, d_sky, xn);
  EXPECT_EQ(added_off, 0);      // measured: 0 (with -cholmod_openmp: 3, CHOLMOD's team of 4)
  EXPECT_LT(d_on, 1e-14 * xn);  // measured: 0 (bitwise)
  EXPECT_LT(d_sky, 1e-13 * xn); // measured: 3.6e-15 relative
}
