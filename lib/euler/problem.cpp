// Problem registry and shared option checks of the 1D Euler app (see problem.hpp).
#include "euler/problem.hpp"

#include <cmath>

namespace suite::euler {

namespace {
struct Entry {
  const char* name;
  PetscErrorCode (*create)(MPI_Comm, const std::string&, Problem*);
};
const Entry kProblems[] = {
    {"riemann", createRiemannProblem},
    {"sod", createRiemannProblem},
    {"lax", createRiemannProblem},
    {"toro123", createRiemannProblem},
    {"modified_sod", createRiemannProblem},
    {"shu_osher", createShockEntropyProblem},
    {"titarev_toro", createShockEntropyProblem},
    {"blast", createBlastProblem},
    {"density_wave", createAdvectionProblem},
    {"pulse", createAdvectionProblem},
};
} // namespace

const char* bcName(Bc bc) {
  switch (bc) {
  case Bc::Periodic:
    return "periodic";
  case Bc::Outflow:
    return "outflow";
  case Bc::Reflecting:
    return "reflecting";
  case Bc::Inflow:
    return "inflow";
  }
  return "?";
}

bool parseBc(const std::string& name, Bc* bc) {
  for (Bc b : {Bc::Periodic, Bc::Outflow, Bc::Reflecting, Bc::Inflow})
    if (name == bcName(b)) {
      *bc = b;
      return true;
    }
  return false;
}

std::string problemNames() {
  std::string out;
  for (const auto& e : kProblems) out += (out.empty() ? "" : ", ") + std::string(e.name);
  return out;
}

PetscErrorCode createProblem(MPI_Comm comm, const std::string& name, Problem* problem) {
  PetscFunctionBeginUser;
  for (const auto& e : kProblems)
    if (name == e.name) {
      problem->name = name;
      PetscCall(e.create(comm, name, problem));
      PetscFunctionReturn(0);
    }
  SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown problem '%s' (option -problem); known problems: %s",
          name.c_str(), problemNames().c_str());
}

PetscErrorCode checkGamma(MPI_Comm comm, double gamma) {
  PetscFunctionBeginUser;
  PetscCheck(gamma > 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -gamma %g: the ratio of specific heats must be > 1", gamma);
  PetscFunctionReturn(0);
}

PetscErrorCode checkState(MPI_Comm comm, const Prim& w, const char* rho_option, const char* p_option) {
  PetscFunctionBeginUser;
  PetscCheck(w.rho > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial density %g (option %s): density must be > 0", w.rho, rho_option);
  PetscCheck(w.p > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial pressure %g (option %s): pressure must be > 0", w.p, p_option);
  PetscCheck(std::isfinite(w.u), comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid initial velocity %g", w.u);
  PetscFunctionReturn(0);
}

} // namespace suite::euler
