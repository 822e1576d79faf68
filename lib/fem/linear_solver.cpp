// Linear solver registry: a new solver is one file plus one line in kSolvers (name, factory, one-line help).
#include "fem/linear_solver.hpp"

namespace suite::fem {
namespace {
struct Entry {
  const char* name;
  std::unique_ptr<LinearSolver> (*make)();
  const char* description;
};
const Entry kSolvers[] = {
    {"skyline", makeSkylineSolver, "envelope (skyline) Cholesky"},
    {"banded", makeBandedSolver,
     "banded Cholesky by blocks of 32 columns cut at the envelope (LAPACK/BLAS kernels)"},
    {"cholmod", makeCholmodSolver, "supernodal Cholesky (CHOLMOD)"},
    {"petsc", makePetscSolver, "distributed MPIAIJ matrix + KSP (-ksp_type, -pc_type)"}};
} // namespace

std::vector<std::string> solverNames() {
  std::vector<std::string> n;
  for (const auto& e : kSolvers) n.emplace_back(e.name);
  return n;
}

std::vector<suite::Choice> solverChoices() {
  return suite::choicesOf(kSolvers);
}

PetscErrorCode createLinearSolver(MPI_Comm comm, const std::string& name,
                                  std::unique_ptr<LinearSolver>* out) {
  PetscFunctionBeginUser;
  PetscCall(suite::checkChoice(comm, "-solver", name, solverChoices()));
  for (const auto& e : kSolvers)
    if (name == e.name) *out = e.make();
  PetscFunctionReturn(0);
}

} // namespace suite::fem
