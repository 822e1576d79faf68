// Dynamic load balancing of independent tasks over the ranks of a communicator, with every result gathered to
// every rank. The tasks are taken in their order (callers put the largest first: the longest-processing-time
// rule, Graham, SIAM J. Appl. Math. 17 (1969) 416-429) by self-scheduling on a shared counter: each rank,
// when free, takes the next task index with an atomic MPI_Fetch_and_op on a counter in a window of rank 0
// (passive target, MPI-3), so no rank waits for a dealer that is busy with a task of its own (guided
// self-scheduling without chunks: Polychronopoulos & Kuck, IEEE Trans. Comput. 36 (1987) 1425-1439). Then every
// rank receives every result (MPI_Allgatherv) and stores it at its task's index, so the results do not depend
// on which rank solved which task, nor on the number of ranks, provided solve(k) depends only on k.
// lcpbench's dealer (apps/lcpbench/lcpbench_dealer.cpp) deals from rank 0 between its own problems, which suits
// its chunks of many problems and its streaming of results to a file; for the contact islands of one step
// (tens of tasks of very different cost) a rank waiting for rank 0 to finish an island idled most of the step.
//
// The counter is never reset: each deal() takes exactly ntasks + size values (every rank's last fetch is
// past the end), and the gather that ends a deal() orders it before the next one, so every rank knows where
// the next deal() starts.
#pragma once

#include <petscsys.h>

#include <functional>
#include <memory>
#include <vector>

namespace suite {

using TaskSolve = std::function<std::vector<double>(int task)>;

class TaskDealer {
public:
  // Collective on comm (duplicated for the dealer's messages and window).
  static PetscErrorCode create(MPI_Comm comm, std::unique_ptr<TaskDealer>* out);
  ~TaskDealer();
  TaskDealer(const TaskDealer&) = delete;
  TaskDealer& operator=(const TaskDealer&) = delete;
  // Collective: results->at(k) = solve(k) for k in [0, ntasks), on every rank (ntasks the same on all).
  PetscErrorCode deal(int ntasks, const TaskSolve& solve, std::vector<std::vector<double>>* results);

private:
  TaskDealer() = default;
  PetscErrorCode take(long long* k);
  PetscErrorCode gather(const std::vector<int>& mine, std::vector<std::vector<double>>* results);
  MPI_Comm comm_ = MPI_COMM_NULL;
  MPI_Win win_ = MPI_WIN_NULL;
  int size_ = 1, rank_ = 0;
  long long base_ = 0; // the counter's value when the next deal() starts
};

} // namespace suite
