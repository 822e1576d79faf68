// lcpbench's dealer: rank 0 deals chunks of problem indices, workers solve them (see lcpbench_dealer.hpp).
#include "lcpbench_dealer.hpp"
#include "lcpbench_util.hpp"

#include "core/log.hpp"
#include "core/progress.hpp"

#include <algorithm>
#include <stdexcept>

namespace lcpbench_app {

namespace {

constexpr int kTagRequest = 4101, kTagWork = 4102;

// Rank 0: deals, solves between requests, streams the results into the Store.
class Dealer {
public:
  Dealer(const suite::RunContext& ctx, const Batch& b, const DealPlan& plan, const ResumePoint& rp,
         Store* store, double t_start)
      : ctx_(ctx), b_(b), plan_(plan), done_(rp.done), ndone0_(rp.ndone), store_(store), t_start_(t_start),
        rec_len_(b.recordLength()), rec_(rec_len_), active_(ctx.size() - 1), ndone_(rp.ndone) {
    skipDone();
  }
  PetscErrorCode run();
  long long ndone() const { return ndone_; }
  int stopped() const { return stopped_; }

private:
  bool dealing() const { return !stopped_ && next_ < b_.count; }
  void skipDone() {
    while (next_ < b_.count && done_[next_]) ++next_;
  }
  void checkStop() {
    if (suite::g_stop_signal && !stopped_) stopped_ = 1;
    if (plan_.max_walltime > 0 && ctx_.wallSeconds() >= plan_.max_walltime && !stopped_) stopped_ = 2;
  }
  PetscErrorCode flushNow();
  PetscErrorCode add(const double* r);
  PetscErrorCode serve(bool block);
  PetscErrorCode answer(const MPI_Status& st);
  PetscErrorCode solveNext();

  const suite::RunContext& ctx_;
  const Batch& b_;
  const DealPlan plan_;
  const std::vector<unsigned char>& done_;
  const long long ndone0_;
  Store* store_;
  const double t_start_;
  const int rec_len_;
  std::vector<double> rec_, msg_;
  std::string err_;
  long long next_ = 0;
  int active_; // workers not yet told that the dealing is over
  double last_flush_ = MPI_Wtime();
  long long ndone_;
  int stopped_ = 0;
};

PetscErrorCode Dealer::flushNow() {
  PetscFunctionBeginUser;
  const std::string ferr = rank0Try(0, [&] { store_->flush(MPI_Wtime() - t_start_); });
  // Rank 0 alone: in a multi-rank run an error on PETSC_COMM_SELF aborts the job with this message.
  PetscCheck(ferr.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: writing results failed: %s",
             ferr.c_str());
  last_flush_ = MPI_Wtime();
  PetscFunctionReturn(0);
}

PetscErrorCode Dealer::add(const double* r) {
  PetscFunctionBeginUser;
  store_->add(r);
  ++ndone_;
  if (store_->buffered() >= plan_.flush_every || MPI_Wtime() - last_flush_ >= plan_.flush_seconds)
    PetscCall(flushNow());
  PetscFunctionReturn(0);
}

// Answers the requests waiting (block: exactly one, waiting for it).
PetscErrorCode Dealer::serve(bool block) {
  PetscFunctionBeginUser;
  while (true) {
    int flag = 0;
    MPI_Status st;
    if (block) {
      PetscCallMPI(MPI_Probe(MPI_ANY_SOURCE, kTagRequest, ctx_.comm(), &st));
      flag = 1;
    } else {
      PetscCallMPI(MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, ctx_.comm(), &flag, &st));
    }
    if (!flag) break;
    PetscCall(answer(st));
    if (block) break;
  }
  PetscFunctionReturn(0);
}

// One request: [stop flag, records of the previous chunk]; the answer is the next chunk [k0, k1), empty when
// the dealing is over.
PetscErrorCode Dealer::answer(const MPI_Status& st) {
  MPI_Comm comm = ctx_.comm();
  int len = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Get_count(&st, MPI_DOUBLE, &len));
  msg_.resize(std::max(len, 1));
  PetscCallMPI(MPI_Recv(msg_.data(), len, MPI_DOUBLE, st.MPI_SOURCE, kTagRequest, comm, MPI_STATUS_IGNORE));
  if (len > 0 && msg_[0] != 0.0 && !stopped_) stopped_ = 1; // the worker saw a stop signal
  for (int off = 1; off + rec_len_ <= len; off += rec_len_) PetscCall(add(msg_.data() + off));
  checkStop();
  long long work[2] = {next_, next_};
  if (!stopped_) {
    while (work[1] < b_.count && work[1] - work[0] < plan_.chunk && !done_[work[1]]) ++work[1];
    next_ = work[1];
    skipDone();
  }
  if (work[0] == work[1]) --active_;
  PetscCallMPI(MPI_Send(work, 2, MPI_LONG_LONG, st.MPI_SOURCE, kTagWork, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode Dealer::solveNext() {
  PetscFunctionBeginUser;
  const long long k = next_++;
  skipDone();
  solveOne(b_, k, rec_.data(), &err_);
  PetscCall(add(rec_.data()));
  PetscFunctionReturn(0);
}

PetscErrorCode Dealer::run() {
  PetscFunctionBeginUser;
  const long long todo = b_.count - ndone0_;
  suite::Progress progress(PETSC_COMM_SELF, ctx_.quiet(), ctx_.progressInterval(), 0.0);
  long long reported = -1;
  while (dealing() || active_ > 0) {
    if (ctx_.size() > 1) PetscCall(serve(false));
    checkStop();
    if (dealing())
      PetscCall(solveNext());
    else if (active_ > 0)
      PetscCall(serve(true));
    if (ndone_ != reported) PetscCall(progress.updateCount(ndone_ - ndone0_, todo, "problems"));
    reported = ndone_;
  }
  PetscCall(flushNow());
  PetscFunctionReturn(0);
}

// Ranks > 0: request, solve the chunk, send its records with the next request, until an empty chunk.
PetscErrorCode work(MPI_Comm comm, const Batch& b) {
  const int rec_len = b.recordLength();
  std::vector<double> out(1, 0.0); // [stop flag, records of the previous chunk]
  std::string err;
  PetscFunctionBeginUser;
  while (true) {
    out[0] = suite::g_stop_signal ? 1.0 : 0.0;
    PetscCallMPI(MPI_Send(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, 0, kTagRequest, comm));
    long long chunk[2];
    PetscCallMPI(MPI_Recv(chunk, 2, MPI_LONG_LONG, 0, kTagWork, comm, MPI_STATUS_IGNORE));
    if (chunk[0] >= chunk[1]) break;
    out.assign(1 + static_cast<size_t>(chunk[1] - chunk[0]) * rec_len, 0.0);
    for (long long k = chunk[0]; k < chunk[1]; ++k)
      solveOne(b, k, out.data() + 1 + (k - chunk[0]) * rec_len, &err);
  }
  PetscFunctionReturn(0);
}

} // namespace

DealPlan dealPlan(const Options& o, long long count, int nranks) {
  DealPlan p;
  p.chunk = o.chunk > 0 ? o.chunk : std::max<long long>(1, std::min<long long>(64, count / (8LL * nranks)));
  p.flush_every = o.flush_every;
  p.flush_seconds = o.flush_seconds;
  p.max_walltime = o.max_walltime;
  return p;
}

PetscErrorCode dealProblems(const suite::RunContext& ctx, const Batch& b, const DealPlan& plan,
                            const ResumePoint& rp, Store* store, DealOutcome* out) {
  PetscFunctionBeginUser;
  const double t_start = MPI_Wtime();
  long long counts[2] = {rp.ndone, 0}; // ndone, stopped
  if (ctx.rank() == 0) {
    Dealer dealer(ctx, b, plan, rp, store, t_start);
    PetscCall(dealer.run());
    counts[0] = dealer.ndone();
    counts[1] = dealer.stopped();
  } else {
    PetscCall(work(ctx.comm(), b));
  }
  out->wall = MPI_Wtime() - t_start;
  PetscCallMPI(MPI_Bcast(counts, 2, MPI_LONG_LONG, 0, ctx.comm()));
  out->ndone = counts[0];
  out->stopped = static_cast<int>(counts[1]);
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
