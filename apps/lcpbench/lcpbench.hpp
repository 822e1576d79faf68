// What lcpbench's parts share, one .cpp each (options, batch, store, resume, dealer, finalize); main.cpp runs
// them and describes the streaming protocol.
#pragma once

#include "core/run_context.hpp"
#include "io/h5_append.hpp"
#include "lcp/generators.hpp"
#include "lcp/portfolio.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lcpbench_app {

using suite::lcp::kInf;

struct Options {
  // problems
  std::string family = "random_box"; // a generator family of lib/lcp or "file"
  std::vector<std::string> files;    // -file, for family "file"
  std::string fclib_model = "box_friction";
  PetscInt n = 100, count = 500, seed = 1;
  PetscReal cond = 1e4, qrange = 1e2, lower = -1e2, upper = 1e2;
  // solvers
  std::vector<std::string> solvers = {"lemke", "keller",    "cottle_dantzig",  "murty",
                                      "bpp",   "fb_newton", "smoothed_newton", "pgs"};
  PetscInt max_it = 0, block_size = 3;
  PetscReal omega = 1.0, rel_tol = 1e-10;
  PetscBool refine = PETSC_TRUE;
  std::string portfolio; // -portfolio: table of "auto" ("" = built-in)
  // the run
  std::string output;
  PetscInt chunk = 0, flush_every = 4096;
  PetscReal flush_seconds = 30.0, delay = 0.0, max_walltime = 0.0;
  PetscBool strict = PETSC_FALSE, resume = PETSC_TRUE;
  PetscBool save_solutions = PETSC_FALSE; // -save_solutions: every solver's z per problem in the file
  // timing (lcpbench_timing.cpp): 0 = one timed run per (solver, problem)
  PetscReal time_repeat = 0.0;
  PetscInt time_batches = 3;
  PetscInt warmup = 1; // untimed solves of the batch's first problems by every solver, on every rank

  bool fromFiles() const { return family == "file"; }
  bool hasAuto() const { return std::find(solvers.begin(), solvers.end(), "auto") != solvers.end(); }
};

// Collective: reads and validates every option. *help_only: -help was given (nothing to run).
PetscErrorCode readOptions(const suite::RunContext& ctx, Options* o, bool* help_only);
// The reader model of a (validated) -fclib_model name.
suite::lcp::FclibModel fclibModel(const std::string& name);

constexpr int kFields = 6; // per solver and problem: status, iterations, pivots, time, residual, cpu_time
inline const char* const kFieldNames[kFields] = {"status", "iterations", "pivots",
                                                 "time",   "residual",   "cpu_time"};

// Per problem with -solvers auto: class index (problem_class.hpp), index of the succeeding solver (registry
// order, -1: none), number of solvers tried, the tried ones in order (-1 padding).
constexpr int kAutoFields = 3 + suite::lcp::kAutoMaxTried;

// Timing of one (solver, problem), lcpbench_timing.cpp: repeat_time 0 = the one timed run of solve().
struct Timing {
  double repeat_time = 0.0; // seconds of CPU time one batch of repetitions lasts at least
  int batches = 3;          // batches timed; the fastest one's time per run is recorded
};
constexpr long long kMaxRepetitions = 1000000; // runs in one batch at most
// run(timed) solves once (timed: fill Result::time / cpu_time). Returns the first, timed run's result; with
// t.repeat_time > 0 its time / cpu_time are replaced by the time per run of the fastest of t.batches batches
// of R untimed runs, R grown until a batch takes >= t.repeat_time CPU seconds (at most kMaxRepetitions).
suite::lcp::Result timedRun(const std::function<suite::lcp::Result(bool timed)>& run, const Timing& t);
// The next batch size after a batch of reps runs took batch_cpu seconds: reps when the batch reached
// repeat_time (or kMaxRepetitions), else at least twice reps, aiming at 1.2 repeat_time.
long long repetitionsFor(double batch_cpu, long long reps, double repeat_time);

struct Batch {
  std::string family;
  suite::lcp::GeneratorParams gp;
  long long count = 0;
  std::vector<suite::lcp::Problem> file_problems; // family "file": every rank holds them (read up front)
  std::vector<std::string> file_errors;           // "" or the reason a file is invalid
  std::vector<std::unique_ptr<suite::lcp::Solver>> solvers; // nullptr for "auto"
  std::vector<std::string> solver_names;
  suite::lcp::SolverOptions opt;
  suite::lcp::Portfolio portfolio; // the table of "auto"
  int auto_index = -1;             // position of "auto" in solver_names, -1 if absent
  double delay = 0.0;              // testing: seconds of sleep after each problem
  int z_len = 0; // -save_solutions: values of z kept per (solver, problem), the largest n (0: none kept)
  Timing timing; // -time_repeat, -time_batches
  long long warmup = 1; // -warmup: problems solved untimed by every solver before timing

  bool fromFiles() const { return family == "file"; }
  // index, n, kFields per solver, then (with auto) class, succeeding solver, tried count, kAutoMaxTried tried,
  // then (with -save_solutions) z_len values of z per solver (NaN past the problem's n or without a z)
  int recordLength() const { return zBase() + static_cast<int>(solvers.size()) * z_len; }
  int autoBase() const { return 2 + static_cast<int>(solvers.size()) * kFields; }
  int zBase() const { return autoBase() + (auto_index >= 0 ? kAutoFields : 0); }
};

// Collective: the batch; files are read here (a malformed HDF5 file stops the job, others go to file_errors).
PetscErrorCode makeBatch(MPI_Comm comm, const Options& o, Batch* b);
// Problem k solved by every solver: rec = k, n, then kFields values per solver. Depends on k alone.
void solveOne(const Batch& b, long long k, double* rec);
// The untimed warm-up of this rank (lcpbench_batch.cpp): every solver solves the first b.warmup valid problems
// of the batch once, results discarded, before any timed solve. Returns the solves per solver (the same for
// every solver and rank: min(b.warmup, valid problems among the first b.warmup + 1000)).
long long warmUp(const Batch& b);

constexpr unsigned long long kBlock = 65536;  // problems per block of the streamed passes over the file
constexpr unsigned long long kMaxRuns = 4096; // runs (start + resumes) whose wall time is recorded
// The batch header (name, value): /batch attributes that a resumed batch must match exactly.
using BatchHeader = std::vector<std::pair<std::string, std::string>>;

// fn(a, v) for each block v = path[a, a + kBlock) of a 1-D dataset of f with count entries.
template <class T, class F>
void forBlocks(const suite::H5AppendFile& f, const std::string& path, unsigned long long count, F fn) {
  std::vector<T> v;
  for (unsigned long long a = 0; a < count; a += kBlock) {
    v.resize(std::min(kBlock, count - a));
    f.read(path, a, v.data(), v.size());
    fn(a, v);
  }
}

// Rank 0's results file OUT.partial: every per-problem dataset preallocated at its final size, records
// buffered and written in place. All methods throw std::runtime_error.
class Store {
public:
  explicit Store(const Batch& b) : count(b.count), b_(b), rec_len_(b.recordLength()) {}
  // A new OUT.partial (run 0), built under another name and renamed once complete: never half-made.
  void create(const std::string& partial);
  void add(const double* rec) { buf_.insert(buf_.end(), rec, rec + rec_len_); } // buffers one record
  long long buffered() const { return static_cast<long long>(buf_.size()) / rec_len_; }
  // Writes the buffered records, flushes, then sets their done flags and flushes again.
  void flush(double run_wall);
  // Wall seconds of every run and problems solved by each run.
  void runTotals(std::vector<double>* walls, std::vector<double>* solved);

  suite::H5AppendFile file;
  BatchHeader header; // set by startBatchFile
  const long long count;
  int run = 0; // this run's number: 0 for a new OUT.partial, one more per resume

private:
  long long key(long long i) const { return static_cast<long long>(buf_[i * rec_len_]); }
  template <class T> void writeColumn(const std::vector<long long>& order, int c, const std::string& path);
  void writeBuffered();
  void writeSolutions(const std::vector<long long>& order);
  void createAuto();
  void writeAuto(const std::vector<long long>& order);
  const Batch& b_;
  const int rec_len_;
  std::vector<double> buf_;
};

// Statistics of one solver (trivially copyable: broadcast as bytes).
struct SolverSummary {
  double failed = 0, med_it = 0, med_piv = 0, med_pvn = 0, tsum = 0, csum = 0;
  long long invalid = 0, unsolved = 0, first_unsolved = -1;
  int first_status = 0;
  double rate(long long count) const { return tsum > 0 ? count / tsum : 0.0; } // problems per second
  double cpuRate(long long count) const { return csum > 0 ? count / csum : 0.0; }
};
// One streamed pass over /results/<solver>/: histograms and summary attributes written to f.
SolverSummary summarise(suite::H5AppendFile& f, const std::string& solver, long long count);

// One streamed pass over /results/auto: how often each solver succeeded and how many problems needed more
// than one (attributes chosen_counts, fallbacks); returns the summary line.
std::string summariseAuto(suite::H5AppendFile& f, long long count);

// Where the batch stands: startBatchFile sets done and ndone0, dealProblems the rest.
struct RunState {
  std::vector<unsigned char> done; // rank 0: done flags (1 byte per problem)
  long long ndone0 = 0;            // every rank: problems done before this run
  long long ndone = 0;             // every rank: problems done, this run and before
  int stopped = 0;                 // 0: no stop, 1: signal, 2: -max_walltime
  double wall = 0;                 // seconds spent dealing
  long long warmup_solves = 0;     // every rank: untimed warm-up solves per solver in this run (warmUp)
  double warmup_wall = 0;          // rank 0: seconds they took
};
// Collective: rank 0 resumes OUT.partial (under -resume, if it exists) or creates it.
PetscErrorCode startBatchFile(const suite::RunContext& ctx, const Options& o, const Batch& b, Store* store,
                              RunState* st);
// Collective: solves every problem not done, results in store (rank 0).
PetscErrorCode dealProblems(const suite::RunContext& ctx, const Options& o, const Batch& b, Store* store,
                            RunState* st);
// Collective: closes OUT.partial of an interrupted run, or completes OUT, prints the summary, checks the outcome.
PetscErrorCode finishRun(const suite::RunContext& ctx, const Options& o, const Batch& b, const RunState& st,
                         Store* store);

} // namespace lcpbench_app
