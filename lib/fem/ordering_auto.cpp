// 'auto' ordering: computes rcm, amd and metis and keeps the one with the smallest predicted nnz(L) from the
// symbolic factorisation (elimination tree + row subtrees, see sparse.cpp); ties go to the earlier candidate.
#include "fem/ordering.hpp"

namespace suite::fem {

std::vector<int> orderAuto(const Graph& g) {
  std::vector<int> best;
  long long best_nnz = -1;
  for (OrderingFn fn : {orderReverseCuthillMcKee, orderAmd, orderMetis}) {
    auto p = fn(g);
    long long nnz = 0;
    for (long long c : choleskyColumnCounts(g, p)) nnz += c;
    if (best_nnz < 0 || nnz < best_nnz) best_nnz = nnz, best.swap(p);
  }
  return best;
}

} // namespace suite::fem
