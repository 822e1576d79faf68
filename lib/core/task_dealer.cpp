// Self-scheduled tasks over ranks on a shared counter, results gathered to every rank (see task_dealer.hpp).
#include "core/task_dealer.hpp"

namespace suite {

PetscErrorCode TaskDealer::create(MPI_Comm comm, std::unique_ptr<TaskDealer>* out) {
  std::unique_ptr<TaskDealer> d(new TaskDealer());
  long long* counter = nullptr;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_dup(comm, &d->comm_));
  PetscCallMPI(MPI_Comm_size(d->comm_, &d->size_));
  PetscCallMPI(MPI_Comm_rank(d->comm_, &d->rank_));
  const MPI_Aint bytes = d->rank_ == 0 ? (MPI_Aint)sizeof(long long) : 0;
  PetscCallMPI(MPI_Win_allocate(bytes, sizeof(long long), MPI_INFO_NULL, d->comm_, &counter, &d->win_));
  if (d->rank_ == 0) {
    PetscCallMPI(MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, d->win_));
    *counter = 0;
    PetscCallMPI(MPI_Win_unlock(0, d->win_));
  }
  PetscCallMPI(MPI_Barrier(d->comm_)); // the counter is set before anyone takes from it
  *out = std::move(d);
  PetscFunctionReturn(0);
}

TaskDealer::~TaskDealer() {
  if (win_ != MPI_WIN_NULL) MPI_Win_free(&win_);
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

// The next value of the counter (atomically: each value goes to exactly one rank).
PetscErrorCode TaskDealer::take(long long* k) {
  const long long one = 1;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, win_));
  PetscCallMPI(MPI_Fetch_and_op(&one, k, MPI_LONG_LONG, 0, 0, MPI_SUM, win_));
  PetscCallMPI(MPI_Win_unlock(0, win_));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskDealer::deal(int ntasks, const TaskSolve& solve,
                                std::vector<std::vector<double>>* results) {
  std::vector<int> mine;
  PetscFunctionBeginUser;
  results->assign(ntasks, {});
  if (size_ == 1) {
    for (int k = 0; k < ntasks; ++k) (*results)[k] = solve(k);
    PetscFunctionReturn(0);
  }
  while (true) {
    long long k = 0;
    PetscCall(take(&k));
    k -= base_;
    if (k >= ntasks) break;
    (*results)[k] = solve((int)k);
    mine.push_back((int)k);
  }
  base_ += ntasks + size_;
  PetscCall(gather(mine, results));
  PetscFunctionReturn(0);
}

// Every rank's results to every rank, each stored at its task index: messages [task, length, data...].
PetscErrorCode TaskDealer::gather(const std::vector<int>& mine, std::vector<std::vector<double>>* results) {
  std::vector<double> send;
  for (int k : mine) {
    send.push_back(k), send.push_back((double)(*results)[k].size());
    send.insert(send.end(), (*results)[k].begin(), (*results)[k].end());
  }
  std::vector<int> counts(size_), displs(size_, 0);
  const int n = (int)send.size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_));
  for (int r = 1; r < size_; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all((size_t)displs[size_ - 1] + counts[size_ - 1]);
  PetscCallMPI(MPI_Allgatherv(send.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                              MPI_DOUBLE, comm_));
  for (size_t off = 0; off < all.size();) {
    const int k = (int)all[off];
    const size_t len = (size_t)all[off + 1];
    (*results)[k].assign(all.begin() + off + 2, all.begin() + off + 2 + len);
    off += 2 + len;
  }
  PetscFunctionReturn(0);
}

} // namespace suite
