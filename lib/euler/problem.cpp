// Problem registry and shared option checks of the 1D Euler app (see problem.hpp).
#include "euler/problem.hpp"

#include <cmath>

namespace suite::euler {

namespace {
struct Entry {
  const char* name;
  PetscErrorCode (*create)(MPI_Comm, const std::string&, Problem*);
  const char* description; // one line for -help
};
const Entry kProblems[] = {
    {"riemann", createRiemannProblem, "Riemann problem with any states (-rho_l -u_l -p_l -rho_r ...), exact"},
    {"sod", createRiemannProblem, "Sod shock tube (1978), exact solution"},
    {"lax", createRiemannProblem, "Lax shock tube (1954), exact solution"},
    {"toro123", createRiemannProblem, "Toro's 123 problem: two strong rarefactions, near vacuum, exact"},
    {"modified_sod", createRiemannProblem, "Toro's modified Sod (sonic rarefaction, x0 = 0.3), exact"},
    {"shu_osher", createShockEntropyProblem, "Shu-Osher Mach 3 shock into a density sine wave (no exact)"},
    {"titarev_toro", createShockEntropyProblem, "Titarev-Toro shock into a high-frequency sine (no exact)"},
    {"blast", createBlastProblem, "Woodward-Colella interacting blast waves, reflecting walls (no exact)"},
    {"density_wave", createAdvectionProblem, "Advected density sine wave, periodic: accuracy test, exact"},
    {"pulse", createAdvectionProblem, "Rectangular density pulse at Mach 2.5, 2000 fixed steps, exact"},
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

std::vector<ProblemDoc> problemDocs() {
  std::vector<ProblemDoc> docs;
  for (const auto& e : kProblems) docs.push_back({e.name, e.description});
  return docs;
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
