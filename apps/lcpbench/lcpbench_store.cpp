// lcpbench's results file (see lcpbench.hpp): the Store's layout and streamed writes (data first, then the done
// flags that vouch for it; protocol in main.cpp), and the per-solver summary pass over it at completion.
#include "lcpbench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>

namespace lcpbench_app {

using suite::lcp::Status;

void Store::create(const std::string& partial) {
  const unsigned long long C = static_cast<unsigned long long>(b_.count);
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

template <class T>
void Store::writeColumn(const std::vector<long long>& order, int c, const std::string& path) {
  std::vector<T> v(nbuf_);
  for (long long i = 0; i < nbuf_; ++i) v[i] = static_cast<T>(buf_[order[i] * rec_len_ + c]);
  f_.writeSelected(path, v.data());
}

// The buffered records in index order, then their done flags.
void Store::writeBuffered() {
  std::vector<long long> order(nbuf_);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](long long a, long long c) { return key(a) < key(c); });
  std::vector<unsigned long long> idx(nbuf_);
  for (long long i = 0; i < nbuf_; ++i) idx[i] = static_cast<unsigned long long>(key(order[i]));
  f_.select(idx);
  writeColumn<int>(order, 1, "/problems/n");
  const std::vector<int> run(nbuf_, run_);
  f_.writeSelected("/batch/run", run.data());
  for (size_t s = 0; s < b_.solver_names.size(); ++s) {
    const std::string g = "/results/" + b_.solver_names[s] + "/";
    const int base = 2 + static_cast<int>(s) * kFields;
    writeColumn<int>(order, base + 0, g + kFieldNames[0]);
    for (int c : {1, 2}) writeColumn<long long>(order, base + c, g + kFieldNames[c]);
    for (int c : {3, 4, 5}) writeColumn<double>(order, base + c, g + kFieldNames[c]);
  }
  f_.flush(); // the data is in the file before the flags that vouch for it
  const std::vector<unsigned char> ones(nbuf_, 1);
  f_.writeSelected("/batch/done", ones.data());
}

void Store::flush(double run_wall) {
  if (nbuf_ > 0) writeBuffered();
  if (run_ < static_cast<int>(kMaxRuns)) f_.writeAt("/batch/run_wall_time", run_, &run_wall, 1);
  f_.flush();
  buf_.clear();
  nbuf_ = 0;
}

void Store::runTotals(std::vector<double>* walls, std::vector<double>* solved) {
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

namespace {

// Median of a multiset given as value -> multiplicity.
double median(const std::map<double, long long>& m) {
  long long total = 0;
  for (const auto& kv : m) total += kv.second;
  if (total == 0) return std::nan("");
  auto nth = [&](long long i) {
    for (const auto& kv : m) {
      if (i < kv.second) return kv.first;
      i -= kv.second;
    }
    return m.rbegin()->first;
  };
  return total % 2 ? nth(total / 2) : 0.5 * (nth(total / 2 - 1) + nth(total / 2));
}

// Multisets of the solved problems' iterations, pivots and pivots per n.
struct Tallies {
  std::map<double, long long> its, pivs, pvns;
};

// One block of problems [a, a + m) into S and T.
void tallyBlock(suite::H5AppendFile& f, const std::string& g, unsigned long long a, unsigned long long m,
                SolverSummary* S, Tallies* T) {
  std::vector<int> st(m), nn(m);
  std::vector<long long> it(m), pv(m);
  std::vector<double> t(m), cpu(m);
  f.read(g + "status", a, st.data(), m);
  f.read("/problems/n", a, nn.data(), m);
  f.read(g + "iterations", a, it.data(), m);
  f.read(g + "pivots", a, pv.data(), m);
  f.read(g + "time", a, t.data(), m);
  f.read(g + "cpu_time", a, cpu.data(), m);
  for (unsigned long long i = 0; i < m; ++i) {
    S->tsum += t[i];
    S->csum += cpu[i];
    if (st[i] == 0) {
      ++T->its[static_cast<double>(it[i])];
      ++T->pivs[static_cast<double>(pv[i])];
      ++T->pvns[static_cast<double>(pv[i]) / std::max(1, nn[i])];
      continue;
    }
    S->failed += 1;
    if (st[i] == static_cast<int>(Status::InvalidInput)) {
      ++S->invalid;
      continue;
    }
    ++S->unsolved;
    if (S->first_unsolved < 0) {
      S->first_unsolved = static_cast<long long>(a + i);
      S->first_status = st[i];
    }
  }
}

template <class T>
void writeDataset(suite::H5AppendFile& f, const std::string& path, const std::vector<T>& v) {
  f.createFixed<T>(path, v.size(), T(0));
  f.writeAt(path, 0, v.data(), v.size());
}

// Histograms of the solved problems: iterations (integer bins, at most ~100) and pivots in units of n
// (0.1 n bins), written to <g>histogram/.
void writeHistograms(suite::H5AppendFile& f, const std::string& g, const Tallies& T) {
  const double itmax = T.its.empty() ? 0.0 : T.its.rbegin()->first;
  const long long iw = std::max(1LL, static_cast<long long>(std::ceil((itmax + 1) / 100.0)));
  const long long nib = static_cast<long long>(itmax) / iw + 1;
  std::vector<long long> ih(nib, 0);
  std::vector<double> ie(nib + 1);
  for (long long i = 0; i <= nib; ++i) ie[i] = static_cast<double>(i * iw);
  for (const auto& kv : T.its) ih[static_cast<long long>(kv.first) / iw] += kv.second;
  const double pmax = T.pvns.empty() ? 0.0 : T.pvns.rbegin()->first;
  const long long npb = static_cast<long long>(std::floor(pmax / 0.1)) + 1;
  std::vector<long long> ph(npb, 0);
  std::vector<double> pe(npb + 1);
  for (long long i = 0; i <= npb; ++i) pe[i] = 0.1 * i;
  for (const auto& kv : T.pvns)
    ph[std::min(npb - 1, static_cast<long long>(std::floor(kv.first / 0.1)))] += kv.second;
  const std::string h = g + "histogram";
  f.remove(h); // a completion killed half-way left some
  writeDataset(f, h + "/iterations_counts", ih);
  writeDataset(f, h + "/iterations_edges", ie);
  writeDataset(f, h + "/pivots_per_n_counts", ph);
  writeDataset(f, h + "/pivots_per_n_edges", pe);
}

void writeSummaryAttributes(suite::H5AppendFile& f, const std::string& gg, const SolverSummary& S,
                            long long count) {
  f.setAttribute(gg, "failures", static_cast<long long>(S.failed));
  f.setAttribute(gg, "median_iterations", S.med_it);
  f.setAttribute(gg, "median_pivots", S.med_piv);
  f.setAttribute(gg, "median_pivots_per_n", S.med_pvn);
  f.setAttribute(gg, "total_time", S.tsum);
  f.setAttribute(gg, "problems_per_second_per_core", S.rate(count));
  f.setAttribute(gg, "total_cpu_time", S.csum);
  f.setAttribute(gg, "problems_per_cpu_second", S.cpuRate(count));
}

} // namespace

SolverSummary summarise(suite::H5AppendFile& f, const std::string& solver, long long count) {
  const std::string g = "/results/" + solver + "/";
  const unsigned long long C = static_cast<unsigned long long>(count);
  SolverSummary S;
  Tallies T;
  for (unsigned long long a = 0; a < C; a += kBlock) tallyBlock(f, g, a, std::min(kBlock, C - a), &S, &T);
  S.med_it = median(T.its);
  S.med_piv = median(T.pivs);
  S.med_pvn = median(T.pvns);
  writeHistograms(f, g, T);
  writeSummaryAttributes(f, "/results/" + solver, S, count);
  return S;
}

} // namespace lcpbench_app
