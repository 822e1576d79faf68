// Approximate minimum degree ordering through SuiteSparse AMD (Amestoy, Davis & Duff, SIAM J. Matrix Anal.
// Appl. 17 (1996) 886-905 and ACM TOMS 30 (2004) 381-388), default control parameters.
#include "fem/ordering.hpp"

#include <amd.h>

namespace suite::fem {

std::vector<int> orderAmd(const Graph& g) {
  if (g.n == 0) return {};
  std::vector<int> p(g.n);
  double control[AMD_CONTROL], info[AMD_INFO];
  amd_defaults(control);
  const int st = amd_order(g.n, g.xadj.data(), g.adj.data(), p.data(), control, info);
  if (st != AMD_OK && st != AMD_OK_BUT_JUMBLED) return orderNatural(g);
  return p;
}

} // namespace suite::fem
