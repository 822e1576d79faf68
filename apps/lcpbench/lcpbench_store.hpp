// lcpbench's streamed results file (the Store: OUT.partial with preallocated per-problem datasets, done
// flags, resume, completion into OUT) and the per-solver summary pass over it; the protocol is described at
// the top of lcpbench_run.cpp.
#pragma once

#include "io/h5_append.hpp"
#include "lcp/problem.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <unistd.h>
#include <vector>

namespace lcpbench_app {

using suite::lcp::kInf;

constexpr int kFields = 6; // status, iterations, pivots, time, residual, cpu_time
inline const char* const kFieldNames[kFields] = {"status", "iterations", "pivots",
                                                 "time",   "residual",   "cpu_time"};
constexpr unsigned long long kBlock = 65536;  // problems per block of the final statistics pass
constexpr unsigned long long kMaxRuns = 4096; // runs (start + resumes) whose wall time is recorded

// What the Store needs to know of a batch.
struct BatchShape {
  long long count = 0;
  std::vector<std::string> solver_names;
};

class Store {
public:
  Store(const BatchShape& b, std::vector<std::pair<std::string, std::string>> header, int rec_len)
      : b_(b), header_(std::move(header)), rec_len_(rec_len) {}

  // Opens a matching OUT.partial (resume) or creates a new one. done gets the done flags.
  void start(const std::string& partial, bool resume, std::vector<unsigned char>* done, long long* ndone,
             std::string* note) {
    const unsigned long long C = static_cast<unsigned long long>(b_.count);
    done->assign(C, 0);
    *ndone = 0;
    note->clear();
    if (resume && access(partial.c_str(), F_OK) == 0) {
      const std::string hint = "; rerun with the same options to resume it, or pass -resume 0 to discard it";
      if (!suite::H5AppendFile::isHdf5(partial))
        throw std::runtime_error(
            partial + " exists but is not an HDF5 file (not an interrupted lcpbench batch?)" + hint);
      f_.open(partial, false); // read-only until the header matches: a refused resume leaves the file as is
      for (const auto& kv : header_) {
        std::string have;
        if (!f_.getAttribute("/batch", kv.first, &have))
          throw std::runtime_error(partial + " lacks the batch header attribute /batch/" + kv.first +
                                   " (not an lcpbench batch?)" + hint);
        if (have != kv.second)
          throw std::runtime_error(partial + " holds an interrupted batch with other parameters (" +
                                   kv.first + ": '" + have + "' there, '" + kv.second + "' now)" + hint);
      }
      if (f_.size("/batch/done") != C)
        throw std::runtime_error(partial + ": /batch/done has the wrong size" + hint);
      f_.open(partial, true);
      for (unsigned long long a = 0; a < C; a += kBlock) {
        const unsigned long long m = std::min(kBlock, C - a);
        f_.read("/batch/done", a, done->data() + a, m);
      }
      // the run number: one more than the largest run recorded among the done problems
      int last = -1;
      std::vector<int> runs;
      for (unsigned long long a = 0; a < C; a += kBlock) {
        const unsigned long long m = std::min(kBlock, C - a);
        runs.resize(m);
        f_.read("/batch/run", a, runs.data(), m);
        for (unsigned long long i = 0; i < m; ++i)
          if ((*done)[a + i]) {
            ++*ndone;
            last = std::max(last, runs[i]);
          }
      }
      run_ = last + 1;
      *note = "resuming " + partial + ": " + std::to_string(*ndone) + " of " + std::to_string(C) +
              " problems done in " + std::to_string(run_) + " earlier run(s)";
    } else {
      // Built under another name and renamed once complete on disk: a kill during the creation (metadata
      // being written) never leaves a half-made OUT.partial.
      const std::string init = partial + ".init";
      f_.create(init);
      for (const auto& kv : header_) f_.setAttribute("/batch", kv.first, kv.second);
      f_.createFixed<unsigned char>("/batch/done", C, 0);
      f_.createFixed<int>("/batch/run", C, -1);
      f_.createFixed<double>("/batch/run_wall_time", kMaxRuns, 0.0, "s");
      f_.createFixed<int>("/problems/n", C, 0);
      for (const auto& s : b_.solver_names) {
        const std::string g = "/results/" + s + "/";
        f_.createFixed<int>(g + "status", C, -1);
        f_.createFixed<long long>(g + "iterations", C, 0);
        f_.createFixed<long long>(g + "pivots", C, 0);
        f_.createFixed<double>(g + "time", C, 0.0, "s");
        f_.createFixed<double>(g + "residual", C, kInf);
        f_.createFixed<double>(g + "cpu_time", C, 0.0, "s");
      }
      run_ = 0;
      f_.flush();
      if (std::rename(init.c_str(), partial.c_str()) != 0)
        throw std::runtime_error("cannot rename " + init + " to " + partial);
    }
    f_.flush(); // from here on only raw data is written in place (no metadata changes) until completion
  }

  // Buffers one record (k, n, solver fields).
  void add(const double* rec) {
    buf_.insert(buf_.end(), rec, rec + rec_len_);
    ++nbuf_;
  }
  long long buffered() const { return nbuf_; }

  // Writes the buffered records, flushes, then sets their done flags and flushes again.
  void flush(double run_wall) {
    if (nbuf_ > 0) {
      std::vector<long long> order(nbuf_);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](long long a, long long c) { return key(a) < key(c); });
      std::vector<unsigned long long> idx(nbuf_);
      for (long long i = 0; i < nbuf_; ++i) idx[i] = static_cast<unsigned long long>(key(order[i]));
      f_.select(idx);
      std::vector<int> iv(nbuf_);
      std::vector<long long> lv(nbuf_);
      std::vector<double> dv(nbuf_);
      auto col = [&](int c) {
        return [this, c, &order](long long i) { return buf_[order[i] * rec_len_ + c]; };
      };
      auto fillInt = [&](int c) {
        auto g = col(c);
        for (long long i = 0; i < nbuf_; ++i) iv[i] = static_cast<int>(g(i));
      };
      fillInt(1);
      f_.writeSelected("/problems/n", iv.data());
      std::fill(iv.begin(), iv.end(), run_);
      f_.writeSelected("/batch/run", iv.data());
      for (size_t s = 0; s < b_.solver_names.size(); ++s) {
        const std::string g = "/results/" + b_.solver_names[s] + "/";
        const int base = 2 + static_cast<int>(s) * kFields;
        fillInt(base + 0);
        f_.writeSelected(g + "status", iv.data());
        for (int c : {1, 2}) {
          auto get = col(base + c);
          for (long long i = 0; i < nbuf_; ++i) lv[i] = static_cast<long long>(get(i));
          f_.writeSelected(g + kFieldNames[c], lv.data());
        }
        for (int c : {3, 4, 5}) {
          auto get = col(base + c);
          for (long long i = 0; i < nbuf_; ++i) dv[i] = get(i);
          f_.writeSelected(g + kFieldNames[c], dv.data());
        }
      }
      f_.flush(); // the data is in the file before the flags that vouch for it
      const std::vector<unsigned char> ones(nbuf_, 1);
      f_.writeSelected("/batch/done", ones.data());
    }
    if (run_ < static_cast<int>(kMaxRuns)) f_.writeAt("/batch/run_wall_time", run_, &run_wall, 1);
    f_.flush();
    buf_.clear();
    nbuf_ = 0;
  }

  suite::H5AppendFile& file() { return f_; }
  int run() const { return run_; }
  // Wall seconds of every run and problems solved by each run (read back at completion).
  void runTotals(std::vector<double>* walls, std::vector<double>* solved) {
    const unsigned long long C = static_cast<unsigned long long>(b_.count);
    const size_t nr = static_cast<size_t>(run_) + 1;
    walls->assign(nr, 0.0);
    solved->assign(nr, 0.0);
    f_.read("/batch/run_wall_time", 0, walls->data(), std::min<unsigned long long>(nr, kMaxRuns));
    std::vector<int> runs;
    for (unsigned long long a = 0; a < C; a += kBlock) {
      const unsigned long long m = std::min(kBlock, C - a);
      runs.resize(m);
      f_.read("/batch/run", a, runs.data(), m);
      for (int r : runs)
        if (r >= 0 && static_cast<size_t>(r) < nr) (*solved)[r] += 1;
    }
  }

private:
  long long key(long long i) const { return static_cast<long long>(buf_[i * rec_len_]); }
  BatchShape b_;
  std::vector<std::pair<std::string, std::string>> header_;
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
