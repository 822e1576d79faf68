// lcpbench's dealer: dynamic load balancing. Rank 0 deals chunks of not-yet-done problem indices on request
// (MPI point-to-point), solves problems itself between requests and streams every result into the Store;
// workers send the results of a chunk with their next request. A stop ends the dealing (main.cpp).
#include "lcpbench.hpp"

#include "core/progress.hpp"
#include "core/rank0_work.hpp"

#include <algorithm>

namespace lcpbench_app {
namespace {

constexpr int kTagRequest = 4101, kTagWork = 4102;

// Rank 0: deals, solves between requests, streams the results into the Store.
class Dealer {
public:
  Dealer(const suite::RunContext& ctx, const Options& o, const Batch& b, Store* store, RunState* st)
      : ctx_(ctx), o_(o), b_(b), store_(store), st_(st), rec_len_(b.recordLength()), rec_(rec_len_),
        active_(ctx.size() - 1) {
    st->ndone = st->ndone0;
    // -chunk, or automatic (0): up to 64 problems, about 8 requests per rank
    chunk_ =
        o.chunk > 0 ? o.chunk : std::max<long long>(1, std::min<long long>(64, b.count / (8LL * ctx.size())));
    skipDone();
  }
  // Deals every problem not done, or until a stop (st->ndone, st->stopped).
  PetscErrorCode run() {
    suite::Progress progress(PETSC_COMM_SELF, ctx_.quiet(), ctx_.progressInterval(), 0.0);
    long long reported = -1;
    PetscFunctionBeginUser;
    while (dealing() || active_ > 0) {
      if (ctx_.size() > 1) PetscCall(serve(false));
      checkStop();
      if (dealing()) {
        const long long k = next_++;
        skipDone();
        solveOne(b_, k, rec_.data());
        PetscCall(add(rec_.data()));
      } else if (active_ > 0) {
        PetscCall(serve(true));
      }
      if (st_->ndone != reported)
        PetscCall(progress.updateCount(st_->ndone - st_->ndone0, b_.count - st_->ndone0, "problems"));
      reported = st_->ndone;
    }
    PetscCall(flushNow());
    PetscFunctionReturn(0);
  }

private:
  bool dealing() const { return !st_->stopped && next_ < b_.count; }
  void skipDone() {
    while (next_ < b_.count && st_->done[next_]) ++next_;
  }
  void checkStop() {
    if (suite::g_stop_signal && !st_->stopped) st_->stopped = 1;
    if (o_.max_walltime > 0 && ctx_.wallSeconds() >= o_.max_walltime && !st_->stopped) st_->stopped = 2;
  }

  PetscErrorCode flushNow() {
    PetscFunctionBeginUser;
    const std::string err = suite::messageOf([&] { store_->flush(MPI_Wtime() - t_start_); });
    // Rank 0 alone: in a multi-rank run an error on PETSC_COMM_SELF aborts the job with this message.
    PetscCheck(err.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: writing results failed: %s",
               err.c_str());
    last_flush_ = MPI_Wtime();
    PetscFunctionReturn(0);
  }

  PetscErrorCode add(const double* r) {
    PetscFunctionBeginUser;
    store_->add(r);
    ++st_->ndone;
    if (store_->buffered() >= o_.flush_every || MPI_Wtime() - last_flush_ >= o_.flush_seconds)
      PetscCall(flushNow());
    PetscFunctionReturn(0);
  }

  // Answers the requests waiting (block: exactly one, waiting for it).
  PetscErrorCode serve(bool block) {
    MPI_Status st;
    int flag = 1;
    PetscFunctionBeginUser;
    do {
      PetscCallMPI(block ? MPI_Probe(MPI_ANY_SOURCE, kTagRequest, ctx_.comm(), &st)
                         : MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, ctx_.comm(), &flag, &st));
      if (flag) PetscCall(answer(st));
    } while (flag && !block);
    PetscFunctionReturn(0);
  }

  // One request: [stop flag, records of the previous chunk]; answer: the next chunk [k0, k1), empty at the end.
  PetscErrorCode answer(const MPI_Status& st) {
    MPI_Comm comm = ctx_.comm();
    int len = 0;
    PetscFunctionBeginUser;
    PetscCallMPI(MPI_Get_count(&st, MPI_DOUBLE, &len));
    msg_.resize(std::max(len, 1));
    PetscCallMPI(MPI_Recv(msg_.data(), len, MPI_DOUBLE, st.MPI_SOURCE, kTagRequest, comm, MPI_STATUS_IGNORE));
    if (len > 0 && msg_[0] != 0.0 && !st_->stopped) st_->stopped = 1; // the worker saw a stop signal
    for (int off = 1; off + rec_len_ <= len; off += rec_len_) PetscCall(add(msg_.data() + off));
    checkStop();
    long long work[2] = {next_, next_};
    if (!st_->stopped) {
      while (work[1] < b_.count && work[1] - work[0] < chunk_ && !st_->done[work[1]]) ++work[1];
      next_ = work[1];
      skipDone();
    }
    if (work[0] == work[1]) --active_;
    PetscCallMPI(MPI_Send(work, 2, MPI_LONG_LONG, st.MPI_SOURCE, kTagWork, comm));
    PetscFunctionReturn(0);
  }

  const suite::RunContext& ctx_;
  const Options& o_;
  const Batch& b_;
  Store* store_;
  RunState* st_;
  const double t_start_ = MPI_Wtime();
  const int rec_len_;
  std::vector<double> rec_, msg_;
  long long chunk_, next_ = 0;
  int active_; // workers not yet told that the dealing is over
  double last_flush_ = MPI_Wtime();
};

// Ranks > 0: request, solve the chunk, send its records with the next request, until an empty chunk.
PetscErrorCode work(MPI_Comm comm, const Batch& b) {
  const int rec_len = b.recordLength();
  std::vector<double> out(1, 0.0); // [stop flag, records of the previous chunk]
  PetscFunctionBeginUser;
  while (true) {
    out[0] = suite::g_stop_signal ? 1.0 : 0.0;
    PetscCallMPI(MPI_Send(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, 0, kTagRequest, comm));
    long long chunk[2];
    PetscCallMPI(MPI_Recv(chunk, 2, MPI_LONG_LONG, 0, kTagWork, comm, MPI_STATUS_IGNORE));
    if (chunk[0] >= chunk[1]) break;
    out.assign(1 + static_cast<size_t>(chunk[1] - chunk[0]) * rec_len, 0.0);
    for (long long k = chunk[0]; k < chunk[1]; ++k) solveOne(b, k, out.data() + 1 + (k - chunk[0]) * rec_len);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode dealProblems(const suite::RunContext& ctx, const Options& o, const Batch& b, Store* store,
                            RunState* st) {
  PetscFunctionBeginUser;
  // Every rank warms every solver up before any timed solve (problems are dealt to any rank).
  const double t_warm = MPI_Wtime();
  if (st->ndone0 < b.count) st->warmup_solves = warmUp(b);
  st->warmup_wall = MPI_Wtime() - t_warm;
  const double t_start = MPI_Wtime();
  if (ctx.rank() == 0)
    PetscCall(Dealer(ctx, o, b, store, st).run());
  else
    PetscCall(work(ctx.comm(), b));
  st->wall = MPI_Wtime() - t_start;
  long long counts[2] = {st->ndone, st->stopped}; // rank 0's
  PetscCallMPI(MPI_Bcast(counts, 2, MPI_LONG_LONG, 0, ctx.comm()));
  st->ndone = counts[0];
  st->stopped = static_cast<int>(counts[1]);
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
