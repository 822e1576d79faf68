// lcpbench's streamed results file, the Store of rank 0: OUT.partial with every per-problem dataset
// preallocated at its final size, records buffered and written in place (data first, then the done flags
// that vouch for it), the run number and wall time of every run; and the per-solver summary pass over it at
// completion. The protocol is described at the top of lcpbench_run.cpp; resuming is lcpbench_resume.*.
#pragma once

#include "io/h5_append.hpp"
#include "lcp/problem.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lcpbench_app {

using suite::lcp::kInf;

constexpr int kFields = 6; // status, iterations, pivots, time, residual, cpu_time
inline const char* const kFieldNames[kFields] = {"status", "iterations", "pivots",
                                                 "time",   "residual",   "cpu_time"};
constexpr unsigned long long kBlock = 65536;  // problems per block of the streamed passes over the file
constexpr unsigned long long kMaxRuns = 4096; // runs (start + resumes) whose wall time is recorded

// The batch header (name, value): /batch attributes that a resumed batch must match exactly.
using BatchHeader = std::vector<std::pair<std::string, std::string>>;

// What the Store needs to know of a batch.
struct BatchShape {
  long long count = 0;
  std::vector<std::string> solver_names;
};

// All methods throw std::runtime_error (rank 0 only).
class Store {
public:
  Store(const BatchShape& b, BatchHeader header, int rec_len)
      : b_(b), header_(std::move(header)), rec_len_(rec_len) {}

  // A new OUT.partial (run 0), built under another name and renamed once complete on disk: a kill during
  // the creation (metadata being written) never leaves a half-made OUT.partial.
  void create(const std::string& partial);
  // Continues an existing OUT.partial as run number `run` (lcpbench_resume.cpp checked it).
  void resumeAs(int run) { run_ = run; }

  // Buffers one record (k, n, solver fields).
  void add(const double* rec) {
    buf_.insert(buf_.end(), rec, rec + rec_len_);
    ++nbuf_;
  }
  long long buffered() const { return nbuf_; }
  // Writes the buffered records, flushes, then sets their done flags and flushes again.
  void flush(double run_wall);

  suite::H5AppendFile& file() { return f_; }
  const BatchHeader& header() const { return header_; }
  long long count() const { return b_.count; }
  int run() const { return run_; }
  // Wall seconds of every run and problems solved by each run (read back at completion).
  void runTotals(std::vector<double>* walls, std::vector<double>* solved);

private:
  long long key(long long i) const { return static_cast<long long>(buf_[i * rec_len_]); }
  double field(const std::vector<long long>& order, long long i, int c) const {
    return buf_[order[i] * rec_len_ + c];
  }
  template <class T> void writeColumn(const std::vector<long long>& order, int c, const std::string& path);
  void writeBuffered();
  BatchShape b_;
  BatchHeader header_;
  int rec_len_;
  suite::H5AppendFile f_;
  std::vector<double> buf_;
  long long nbuf_ = 0;
  int run_ = 0;
};

// Statistics of one solver, by a streamed pass over the file (rank 0).
struct SolverSummary {
  double failed = 0, med_it = 0, med_piv = 0, med_pvn = 0, tsum = 0, csum = 0;
  long long invalid = 0, unsolved = 0;
  long long first_unsolved = -1;
  int first_status = 0;
};

// Median of a multiset given as value -> multiplicity.
double median(const std::map<double, long long>& m);
// One streamed pass over /results/<solver>/: histograms and summary attributes written to f.
SolverSummary summarise(suite::H5AppendFile& f, const std::string& solver, long long count);

} // namespace lcpbench_app
