// Dynamic dealing of independent tasks over ranks, results gathered to every rank (see task_dealer.hpp).
// Protocol: task r starts on rank r (no message); a worker posts its request for the next task before it
// solves the current one, so that the answer arrives while it computes; rank 0 answers the requests waiting
// after each task it solves, with the next task in order or -1 (no more), and each worker stops at its -1.
#include "core/task_dealer.hpp"

#include <algorithm>

namespace suite {

namespace {

constexpr int kTagRequest = 4301, kTagTask = 4302;

// Rank 0: solves task 0, then between its own tasks answers the waiting requests.
class Dealer {
public:
  Dealer(MPI_Comm comm, int size, int ntasks)
      : comm_(comm), ntasks_(ntasks), next_(std::min(size, ntasks)), active_(size - 1) {}
  PetscErrorCode run(const TaskSolve& solve, std::vector<int>* mine,
                     std::vector<std::vector<double>>* results) {
    int own = ntasks_ > 0 ? 0 : -1;
    PetscFunctionBeginUser;
    while (true) {
      if (own >= 0) (*results)[own] = solve(own), mine->push_back(own);
      PetscCall(serve(false));
      if (next_ < ntasks_) {
        own = next_++;
        continue;
      }
      own = -1;
      if (active_ == 0) break;
      PetscCall(serve(true));
    }
    PetscFunctionReturn(0);
  }

private:
  // Answers the requests waiting (block: at least one, waiting for it).
  PetscErrorCode serve(bool block) {
    int flag = 1;
    MPI_Status st;
    PetscFunctionBeginUser;
    while (active_ > 0) {
      if (block)
        PetscCallMPI(MPI_Probe(MPI_ANY_SOURCE, kTagRequest, comm_, &st));
      else
        PetscCallMPI(MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, comm_, &flag, &st));
      if (!flag) break;
      block = false;
      PetscCallMPI(MPI_Recv(nullptr, 0, MPI_INT, st.MPI_SOURCE, kTagRequest, comm_, MPI_STATUS_IGNORE));
      const int task = next_ < ntasks_ ? next_++ : -1;
      active_ -= task < 0;
      PetscCallMPI(MPI_Send(&task, 1, MPI_INT, st.MPI_SOURCE, kTagTask, comm_));
    }
    PetscFunctionReturn(0);
  }
  MPI_Comm comm_;
  int ntasks_, next_, active_;
};

// Ranks > 0: task `rank` first, each next one requested before the current one is solved.
PetscErrorCode work(MPI_Comm comm, int rank, int ntasks, const TaskSolve& solve, std::vector<int>* mine,
                    std::vector<std::vector<double>>* results) {
  int cur = rank < ntasks ? rank : -1, next = -1;
  PetscFunctionBeginUser;
  while (true) {
    MPI_Request req[2];
    PetscCallMPI(MPI_Isend(nullptr, 0, MPI_INT, 0, kTagRequest, comm, &req[0]));
    PetscCallMPI(MPI_Irecv(&next, 1, MPI_INT, 0, kTagTask, comm, &req[1]));
    if (cur >= 0) (*results)[cur] = solve(cur), mine->push_back(cur);
    PetscCallMPI(MPI_Waitall(2, req, MPI_STATUSES_IGNORE));
    if (next < 0) break;
    cur = next;
  }
  PetscFunctionReturn(0);
}

// Every rank's results to every rank, each stored at its task index: messages [task, length, data...].
PetscErrorCode gather(MPI_Comm comm, int size, const std::vector<int>& mine,
                      std::vector<std::vector<double>>* results) {
  std::vector<double> send;
  for (int k : mine) {
    send.push_back(k), send.push_back((double)(*results)[k].size());
    send.insert(send.end(), (*results)[k].begin(), (*results)[k].end());
  }
  std::vector<int> counts(size), displs(size, 0);
  const int n = (int)send.size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all((size_t)displs[size - 1] + counts[size - 1]);
  PetscCallMPI(
      MPI_Allgatherv(send.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  for (size_t off = 0; off < all.size();) {
    const int k = (int)all[off];
    const size_t len = (size_t)all[off + 1];
    (*results)[k].assign(all.begin() + off + 2, all.begin() + off + 2 + len);
    off += 2 + len;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode dealTasks(MPI_Comm comm, int ntasks, const TaskSolve& solve,
                         std::vector<std::vector<double>>* results) {
  int size = 1, rank = 0;
  std::vector<int> mine;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  results->assign(ntasks, {});
  if (size == 1) {
    for (int k = 0; k < ntasks; ++k) (*results)[k] = solve(k);
    PetscFunctionReturn(0);
  }
  if (rank == 0)
    PetscCall(Dealer(comm, size, ntasks).run(solve, &mine, results));
  else
    PetscCall(work(comm, rank, ntasks, solve, &mine, results));
  PetscCall(gather(comm, size, mine, results));
  PetscFunctionReturn(0);
}

} // namespace suite
