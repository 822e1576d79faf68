// Ordering registry: a new ordering is one file plus one line in kOrderings (name, function, the one-line help
// that -help prints under -ordering).
#include "fem/ordering.hpp"

#include "core/clocks.hpp"

#include <algorithm>

#include <numeric>

namespace suite::fem {

std::vector<int> orderNatural(const Graph& g) {
  std::vector<int> p(g.n);
  std::iota(p.begin(), p.end(), 0);
  return p;
}

namespace {
struct Entry {
  const char* name;
  OrderingFn fn;
  const char* description;
};
const Entry kOrderings[] = {
    {"natural", orderNatural, "the given node order (no permutation)"},
    {"cm", orderCuthillMcKee, "Cuthill-McKee exactly as SPARSEPAK's GENRCM before its reversal"},
    {"rcm", orderReverseCuthillMcKee,
     "reverse Cuthill-McKee exactly as SPARSEPAK's GENRCM (George & Liu 1981): bandwidth/profile reducing"},
    {"amd", orderAmd, "approximate minimum degree (SuiteSparse AMD): fill reducing"},
    {"metis", orderMetis, "nested dissection (METIS_NodeND): fill reducing"},
    {"auto", orderAuto,
     "the one of natural, rcm, amd and metis with the smallest symbolic nnz(L) (the output names it)"},
};
} // namespace

std::vector<std::string> orderingNames() {
  std::vector<std::string> n;
  for (const auto& e : kOrderings) n.emplace_back(e.name);
  return n;
}

std::vector<suite::Choice> orderingChoices() {
  return suite::choicesOf(kOrderings);
}

PetscErrorCode findOrdering(MPI_Comm comm, const std::string& name, OrderingFn* fn) {
  PetscFunctionBeginUser;
  PetscCall(suite::checkChoice(comm, "-ordering", name, orderingChoices()));
  for (const auto& e : kOrderings)
    if (name == e.name) *fn = e.fn;
  PetscFunctionReturn(0);
}

OrderingChoice runOrdering(const std::string& name, const Graph& g) {
  if (name == "auto") return chooseOrdering(g);
  for (const auto& e : kOrderings)
    if (name == e.name) return {name, e.fn(g)};
  return {name, {}}; // not reached: findOrdering checked the name
}

double timeOrdering(OrderingFn fn, const Graph& g, int repeat, std::vector<int>* perm) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = threadCpuSeconds();
    *perm = fn(g);
    best = std::min(best, threadCpuSeconds() - t0);
  }
  return best;
}

} // namespace suite::fem
