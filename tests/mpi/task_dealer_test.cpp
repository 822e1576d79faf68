// Tasks dealt over ranks (lib/core/task_dealer): every task is solved exactly once, by any rank, and every rank
// receives every result at its task's index, over several consecutive deals of different sizes (0 tasks, fewer
// tasks than ranks, results of different lengths, tasks of very different cost), which exercises the shared
// counter that is never reset. Checked exactly (the results are functions of the task index). Run at 1 to 3
// ranks.
#include "core/task_dealer.hpp"

#include <petscsys.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace {

// Task k of deal d: k % 4 + 1 values, the first one identifying the deal and the task; odd tasks take longer.
std::vector<double> result(int d, int k) {
  std::vector<double> v(k % 4 + 1, 0.5 * k);
  v[0] = 1000.0 * d + k;
  return v;
}

} // namespace

TEST(TaskDealer, EveryResultOnEveryRankOverConsecutiveDeals) {
  std::unique_ptr<suite::TaskDealer> dealer;
  ASSERT_EQ(suite::TaskDealer::create(PETSC_COMM_WORLD, &dealer), 0);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const int sizes[] = {7, 0, 1, 25, 2, 40};
  for (int d = 0; d < 6; ++d) {
    const int n = sizes[d];
    std::vector<int> solved(n, 0);
    auto solve = [&](int k) {
      ++solved[k];
      if (k % 2) std::this_thread::sleep_for(std::chrono::microseconds(200 * (k % 5)));
      return result(d, k);
    };
    std::vector<std::vector<double>> res;
    ASSERT_EQ(dealer->deal(n, solve, &res), 0);
    ASSERT_EQ((int)res.size(), n);
    for (int k = 0; k < n; ++k) EXPECT_EQ(res[k], result(d, k)) << "deal " << d << " task " << k;
    std::vector<int> total(n, 0);
    MPI_Allreduce(solved.data(), total.data(), n, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
    for (int k = 0; k < n; ++k)
      EXPECT_EQ(total[k], 1) << "deal " << d << " task " << k << " solved " << total[k];
  }
}
