// 'auto' ordering: computes natural (the input order), rcm, amd and metis and keeps the one with the smallest
// predicted nnz(L) from the symbolic factorisation (elimination tree + row subtrees, see sparse.cpp); ties go
// to the earlier candidate, so the input order is kept where no ordering improves on it.
#include "fem/ordering.hpp"

namespace suite::fem {

OrderingChoice chooseOrdering(const Graph& g) {
  const std::pair<const char*, OrderingFn> candidates[] = {
      {"natural", orderNatural}, {"rcm", orderReverseCuthillMcKee}, {"amd", orderAmd}, {"metis", orderMetis}};
  OrderingChoice best;
  long long best_nnz = -1;
  for (const auto& [name, fn] : candidates) {
    auto p = fn(g);
    long long nnz = 0;
    for (long long c : choleskyColumnCounts(g, p)) nnz += c;
    if (best_nnz < 0 || nnz < best_nnz) best_nnz = nnz, best.perm.swap(p), best.name = name;
  }
  return best;
}

std::vector<int> orderAuto(const Graph& g) {
  return chooseOrdering(g).perm;
}

} // namespace suite::fem
