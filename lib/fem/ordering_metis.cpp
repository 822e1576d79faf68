// Nested dissection ordering through METIS_NodeND (Karypis & Kumar, SIAM J. Sci. Comput. 20 (1998) 359-392),
// default options; perm[new] = old as METIS defines perm.
#include "fem/ordering.hpp"

#include <metis.h>

namespace suite::fem {

std::vector<int> orderMetis(const Graph& g) {
  if (g.n == 0) return {};
  if (g.adj.empty()) return orderNatural(g);
  idx_t n = g.n;
  std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end()), adj(g.adj.begin(), g.adj.end()), perm(g.n),
      iperm(g.n);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (METIS_NodeND(&n, xadj.data(), adj.data(), nullptr, options, perm.data(), iperm.data()) != METIS_OK)
    return orderNatural(g);
  return std::vector<int>(perm.begin(), perm.end());
}

} // namespace suite::fem
