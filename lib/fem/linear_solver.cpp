// Linear solver registry: a new solver is one file plus one line in kSolvers.
#include "fem/linear_solver.hpp"

namespace suite::fem {
namespace {
struct Entry {
  const char* name;
  std::unique_ptr<LinearSolver> (*make)();
};
const Entry kSolvers[] = {{"skyline", makeSkylineSolver},
                          {"banded", makeBandedSolver},
                          {"cholmod", makeCholmodSolver},
                          {"petsc", makePetscSolver}};
} // namespace

std::vector<std::string> solverNames() {
  std::vector<std::string> n;
  for (const auto& e : kSolvers) n.emplace_back(e.name);
  return n;
}

PetscErrorCode createLinearSolver(MPI_Comm comm, const std::string& name,
                                  std::unique_ptr<LinearSolver>* out) {
  PetscFunctionBeginUser;
  for (const auto& e : kSolvers)
    if (name == e.name) {
      *out = e.make();
      PetscFunctionReturn(0);
    }
  SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown -solver %s (valid: skyline|banded|cholmod|petsc)",
          name.c_str());
}

} // namespace suite::fem
