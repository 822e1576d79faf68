// lcpbench results-file summary pass (see lcpbench_store.hpp).
#include "lcpbench_store.hpp"

#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>

namespace lcpbench_app {

using suite::lcp::Status;

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

// The results file of rank 0 (OUT.partial while the batch runs). All methods throw std::runtime_error.
SolverSummary summarise(suite::H5AppendFile& f, const std::string& solver, long long count) {
  const std::string g = "/results/" + solver + "/";
  const unsigned long long C = static_cast<unsigned long long>(count);
  std::map<double, long long> its, pivs, pvns;
  SolverSummary S;
  std::vector<int> st, nn;
  std::vector<long long> it, pv;
  std::vector<double> t, cpu;
  for (unsigned long long a = 0; a < C; a += kBlock) {
    const unsigned long long m = std::min(kBlock, C - a);
    st.resize(m), nn.resize(m), it.resize(m), pv.resize(m), t.resize(m), cpu.resize(m);
    f.read(g + "status", a, st.data(), m);
    f.read("/problems/n", a, nn.data(), m);
    f.read(g + "iterations", a, it.data(), m);
    f.read(g + "pivots", a, pv.data(), m);
    f.read(g + "time", a, t.data(), m);
    f.read(g + "cpu_time", a, cpu.data(), m);
    for (unsigned long long i = 0; i < m; ++i) {
      S.tsum += t[i];
      S.csum += cpu[i];
      if (st[i] == 0) {
        ++its[static_cast<double>(it[i])];
        ++pivs[static_cast<double>(pv[i])];
        ++pvns[static_cast<double>(pv[i]) / std::max(1, nn[i])];
      } else {
        S.failed += 1;
        if (st[i] == static_cast<int>(Status::InvalidInput)) {
          ++S.invalid;
        } else {
          ++S.unsolved;
          if (S.first_unsolved < 0) {
            S.first_unsolved = static_cast<long long>(a + i);
            S.first_status = st[i];
          }
        }
      }
    }
  }
  S.med_it = median(its);
  S.med_piv = median(pivs);
  S.med_pvn = median(pvns);
  // histograms of the solved problems: iterations (integer bins, at most ~100) and pivots in units of n
  // (0.1 n bins)
  const double itmax = its.empty() ? 0.0 : its.rbegin()->first;
  const long long iw = std::max(1LL, static_cast<long long>(std::ceil((itmax + 1) / 100.0)));
  const long long nib = static_cast<long long>(itmax) / iw + 1;
  std::vector<long long> ih(nib, 0);
  std::vector<double> ie(nib + 1);
  for (long long i = 0; i <= nib; ++i) ie[i] = static_cast<double>(i * iw);
  for (const auto& kv : its) ih[static_cast<long long>(kv.first) / iw] += kv.second;
  const double pmax = pvns.empty() ? 0.0 : pvns.rbegin()->first;
  const long long npb = static_cast<long long>(std::floor(pmax / 0.1)) + 1;
  std::vector<long long> ph(npb, 0);
  std::vector<double> pe(npb + 1);
  for (long long i = 0; i <= npb; ++i) pe[i] = 0.1 * i;
  for (const auto& kv : pvns)
    ph[std::min(npb - 1, static_cast<long long>(std::floor(kv.first / 0.1)))] += kv.second;
  const std::string h = g + "histogram";
  f.remove(h); // a completion killed half-way left some
  f.createFixed<long long>(h + "/iterations_counts", nib, 0);
  f.writeAt(h + "/iterations_counts", 0, ih.data(), nib);
  f.createFixed<double>(h + "/iterations_edges", nib + 1, 0.0);
  f.writeAt(h + "/iterations_edges", 0, ie.data(), nib + 1);
  f.createFixed<long long>(h + "/pivots_per_n_counts", npb, 0);
  f.writeAt(h + "/pivots_per_n_counts", 0, ph.data(), npb);
  f.createFixed<double>(h + "/pivots_per_n_edges", npb + 1, 0.0);
  f.writeAt(h + "/pivots_per_n_edges", 0, pe.data(), npb + 1);
  const std::string gg = "/results/" + solver;
  f.setAttribute(gg, "failures", static_cast<long long>(S.failed));
  f.setAttribute(gg, "median_iterations", S.med_it);
  f.setAttribute(gg, "median_pivots", S.med_piv);
  f.setAttribute(gg, "median_pivots_per_n", S.med_pvn);
  f.setAttribute(gg, "total_time", S.tsum);
  f.setAttribute(gg, "problems_per_second_per_core", S.tsum > 0 ? count / S.tsum : 0.0);
  f.setAttribute(gg, "total_cpu_time", S.csum);
  f.setAttribute(gg, "problems_per_cpu_second", S.csum > 0 ? count / S.csum : 0.0);
  return S;
}

} // namespace lcpbench_app
