// lcpbench's results file (see lcpbench.hpp): the Store's layout and streamed writes (data first, then the done
// flags that vouch for it; protocol in main.cpp), and the per-solver summary pass over it at completion.
#include "lcpbench.hpp"

#include "core/comma_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>

namespace lcpbench_app {

using suite::lcp::Status;

void Store::create(const std::string& partial) {
  const unsigned long long C = static_cast<unsigned long long>(count);
  const std::string init = partial + ".init";
  file.create(init);
  for (const auto& kv : header) file.setAttribute("/batch", kv.first, kv.second);
  file.createFixed<unsigned char>("/batch/done", C, 0);
  file.createFixed<int>("/batch/run", C, -1);
  file.createFixed<double>("/batch/run_wall_time", kMaxRuns, 0.0, "s");
  file.createFixed<int>("/problems/n", C, 0);
  for (const auto& s : b_.solver_names) {
    const std::string g = "/results/" + s + "/";
    file.createFixed<int>(g + "status", C, -1);
    file.createFixed<long long>(g + "iterations", C, 0);
    file.createFixed<long long>(g + "pivots", C, 0);
    file.createFixed<double>(g + "time", C, 0.0, "s");
    file.createFixed<double>(g + "residual", C, kInf);
    file.createFixed<double>(g + "cpu_time", C, 0.0, "s");
    if (b_.z_len > 0) { // problem k's z at [k z_len, k z_len + n_k)
      file.createFixed<double>(g + "z", C * static_cast<unsigned long long>(b_.z_len), std::nan(""));
      file.setAttribute(g + "z", "row_length", static_cast<long long>(b_.z_len));
    }
  }
  if (b_.auto_index >= 0) createAuto();
  run = 0;
  file.flush();
  if (std::rename(init.c_str(), partial.c_str()) != 0)
    throw std::runtime_error("cannot rename " + init + " to " + partial);
}

// The portfolio's per-problem choices (lcpbench.hpp, kAutoFields) and the name lists their indices refer to.
void Store::createAuto() {
  const unsigned long long C = static_cast<unsigned long long>(count);
  const std::string g = "/results/auto/";
  file.createFixed<int>(g + "class", C, -1);
  file.createFixed<int>(g + "solver", C, -1);
  file.createFixed<int>(g + "tried_count", C, 0);
  for (int j = 0; j < suite::lcp::kAutoMaxTried; ++j)
    file.createFixed<int>(g + "tried_" + std::to_string(j), C, -1);
  file.setAttribute("/results/auto", "class_names", suite::joinCommaList(suite::lcp::problemClassNames()));
  file.setAttribute("/results/auto", "solver_names", suite::joinCommaList(suite::lcp::solverNames()));
  file.setAttribute("/results/auto", "portfolio", b_.portfolio.source);
}

void Store::writeAuto(const std::vector<long long>& order) {
  const std::string g = "/results/auto/";
  const int base = b_.autoBase();
  writeColumn<int>(order, base + 0, g + "class");
  writeColumn<int>(order, base + 1, g + "solver");
  writeColumn<int>(order, base + 2, g + "tried_count");
  for (int j = 0; j < suite::lcp::kAutoMaxTried; ++j)
    writeColumn<int>(order, base + 3 + j, g + "tried_" + std::to_string(j));
}

template <class T>
void Store::writeColumn(const std::vector<long long>& order, int c, const std::string& path) {
  std::vector<T> v(order.size());
  for (size_t i = 0; i < order.size(); ++i) v[i] = static_cast<T>(buf_[order[i] * rec_len_ + c]);
  file.writeSelected(path, v.data());
}

// -save_solutions: each solver's z of the buffered records (order: by problem index) into its row of z.
void Store::writeSolutions(const std::vector<long long>& order) {
  const unsigned long long L = static_cast<unsigned long long>(b_.z_len);
  std::vector<unsigned long long> idx;
  idx.reserve(order.size() * L);
  for (long long i : order)
    for (unsigned long long j = 0; j < L; ++j) idx.push_back(static_cast<unsigned long long>(key(i)) * L + j);
  file.select(idx);
  std::vector<double> v(idx.size());
  for (size_t s = 0; s < b_.solver_names.size(); ++s) {
    const size_t base = static_cast<size_t>(b_.zBase()) + s * L;
    for (size_t i = 0; i < order.size(); ++i)
      std::copy_n(buf_.begin() + order[i] * rec_len_ + base, L, v.begin() + i * L);
    file.writeSelected("/results/" + b_.solver_names[s] + "/z", v.data());
  }
}

// The buffered records in index order (their solutions first), then their done flags.
void Store::writeBuffered() {
  std::vector<long long> order(buffered());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](long long a, long long c) { return key(a) < key(c); });
  if (b_.z_len > 0) writeSolutions(order);
  std::vector<unsigned long long> idx;
  for (long long i : order) idx.push_back(static_cast<unsigned long long>(key(i)));
  file.select(idx);
  writeColumn<int>(order, 1, "/problems/n");
  file.writeSelected("/batch/run", std::vector<int>(order.size(), run).data());
  for (size_t s = 0; s < b_.solver_names.size(); ++s) {
    const std::string g = "/results/" + b_.solver_names[s] + "/";
    const int base = 2 + static_cast<int>(s) * kFields;
    writeColumn<int>(order, base + 0, g + kFieldNames[0]);
    for (int c : {1, 2}) writeColumn<long long>(order, base + c, g + kFieldNames[c]);
    for (int c : {3, 4, 5}) writeColumn<double>(order, base + c, g + kFieldNames[c]);
  }
  if (b_.auto_index >= 0) writeAuto(order);
  file.flush(); // the data is in the file before the flags that vouch for it
  file.writeSelected("/batch/done", std::vector<unsigned char>(order.size(), 1).data());
}

void Store::flush(double run_wall) {
  if (!buf_.empty()) writeBuffered();
  if (run < static_cast<int>(kMaxRuns)) file.writeAt("/batch/run_wall_time", run, &run_wall, 1);
  file.flush();
  buf_.clear();
}

void Store::runTotals(std::vector<double>* walls, std::vector<double>* solved) {
  const size_t nr = static_cast<size_t>(run) + 1;
  walls->assign(nr, 0.0);
  solved->assign(nr, 0.0);
  file.read("/batch/run_wall_time", 0, walls->data(), std::min<unsigned long long>(nr, kMaxRuns));
  forBlocks<int>(file, "/batch/run", count, [&](unsigned long long, const std::vector<int>& runs) {
    for (int r : runs)
      if (r >= 0 && static_cast<size_t>(r) < nr) (*solved)[r] += 1;
  });
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

// A histogram of m: nb bins of width w from 0 (the last one takes larger values), <path>_counts and _edges.
void writeHistogram(suite::H5AppendFile& f, const std::string& path, const std::map<double, long long>& m,
                    double w, long long nb) {
  std::vector<long long> counts(nb, 0);
  std::vector<double> edges(nb + 1);
  for (long long i = 0; i <= nb; ++i) edges[i] = w * i;
  for (const auto& kv : m)
    counts[std::min(nb - 1, static_cast<long long>(std::floor(kv.first / w)))] += kv.second;
  f.createFixed<long long>(path + "_counts", nb, 0);
  f.writeAt(path + "_counts", 0, counts.data(), nb);
  f.createFixed<double>(path + "_edges", nb + 1, 0.0);
  f.writeAt(path + "_edges", 0, edges.data(), nb + 1);
}

// Histograms of the solved problems, written to <g>histogram/: iterations (integer bins, at most ~100) and
// pivots in units of n (0.1 n bins).
void writeHistograms(suite::H5AppendFile& f, const std::string& g, const Tallies& T) {
  const double itmax = T.its.empty() ? 0.0 : T.its.rbegin()->first;
  const long long iw = std::max(1LL, static_cast<long long>(std::ceil((itmax + 1) / 100.0)));
  const double pmax = T.pvns.empty() ? 0.0 : T.pvns.rbegin()->first;
  f.remove(g + "histogram"); // a completion killed half-way left some
  writeHistogram(f, g + "histogram/iterations", T.its, static_cast<double>(iw),
                 static_cast<long long>(itmax) / iw + 1);
  writeHistogram(f, g + "histogram/pivots_per_n", T.pvns, 0.1,
                 static_cast<long long>(std::floor(pmax / 0.1)) + 1);
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
  const std::string gg = "/results/" + solver;
  f.setAttribute(gg, "failures", static_cast<long long>(S.failed));
  f.setAttribute(gg, "median_iterations", S.med_it);
  f.setAttribute(gg, "median_pivots", S.med_piv);
  f.setAttribute(gg, "median_pivots_per_n", S.med_pvn);
  f.setAttribute(gg, "total_time", S.tsum);
  f.setAttribute(gg, "problems_per_second_per_core", S.rate(count));
  f.setAttribute(gg, "total_cpu_time", S.csum);
  f.setAttribute(gg, "problems_per_cpu_second", S.cpuRate(count));
  return S;
}

std::string summariseAuto(suite::H5AppendFile& f, long long count) {
  const auto& names = suite::lcp::solverNames();
  std::vector<long long> chosen(names.size() + 1, 0); // last: none
  long long fallbacks = 0;
  forBlocks<int>(f, "/results/auto/solver", static_cast<unsigned long long>(count),
                 [&](unsigned long long, const std::vector<int>& v) {
                   for (int s : v) ++chosen[s >= 0 && s < (int)names.size() ? s : names.size()];
                 });
  forBlocks<int>(f, "/results/auto/tried_count", static_cast<unsigned long long>(count),
                 [&](unsigned long long, const std::vector<int>& v) {
                   for (int t : v) fallbacks += t > 1;
                 });
  std::string line = "auto (" + std::to_string(fallbacks) + " problem(s) needed more than one solver):";
  std::vector<double> counts;
  for (size_t s = 0; s <= names.size(); ++s) {
    counts.push_back(static_cast<double>(chosen[s]));
    if (chosen[s]) line += " " + (s < names.size() ? names[s] : "none") + " " + std::to_string(chosen[s]);
  }
  f.setAttribute("/results/auto", "chosen_counts", counts); // per registry solver, then "none"
  f.setAttribute("/results/auto", "fallbacks", fallbacks);
  return line;
}

} // namespace lcpbench_app
