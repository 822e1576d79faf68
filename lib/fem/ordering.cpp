// Ordering registry: a new ordering is one file plus one line in kOrderings.
#include "fem/ordering.hpp"

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
};
const Entry kOrderings[] = {
    {"natural", orderNatural}, {"cm", orderCuthillMcKee}, {"rcm", orderReverseCuthillMcKee},
    {"amd", orderAmd},         {"metis", orderMetis},     {"auto", orderAuto},
};
} // namespace

std::vector<std::string> orderingNames() {
  std::vector<std::string> n;
  for (const auto& e : kOrderings) n.emplace_back(e.name);
  return n;
}

PetscErrorCode findOrdering(MPI_Comm comm, const std::string& name, OrderingFn* fn) {
  PetscFunctionBeginUser;
  for (const auto& e : kOrderings)
    if (name == e.name) {
      *fn = e.fn;
      PetscFunctionReturn(0);
    }
  SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown -ordering %s (valid: natural|cm|rcm|amd|metis|auto)",
          name.c_str());
}

} // namespace suite::fem
