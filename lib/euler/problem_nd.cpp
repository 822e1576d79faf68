// Problem registry and shared checks of the 2D/3D Euler app (see problem_nd.hpp). Genuinely multi-dimensional
// problems come from the family factories (problem_nd_*.cpp); every 1D problem name of problem.hpp runs as a
// planar problem along -axis (problem_nd_planar.cpp).
#include "euler/problem_nd.hpp"

#include <cmath>
#include <sstream>

namespace suite::euler {

namespace {
struct EntryND {
  const char* name;
  PetscErrorCode (*create)(MPI_Comm, const std::string&, int, int, ProblemND*);
};
const EntryND kProblemsND[] = {
    {"isentropic_vortex", createVortexProblemND},
    {"riemann2d", createRiemann2dProblemND},
    {"lax_liu_4", createRiemann2dProblemND},
    {"lax_liu_6", createRiemann2dProblemND},
    {"liska_wendroff_3", createRiemann2dProblemND},
    {"double_mach", createDoubleMachProblemND},
    {"rayleigh_taylor", createRayleighTaylorProblemND},
    {"explosion", createExplosionProblemND},
    {"sedov", createExplosionProblemND},
    {"taylor_green", createTaylorGreenProblemND},
};

bool isPlanarName(const std::string& name) {
  std::stringstream ss(problemNames());
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(' ');
    if (b != std::string::npos && item.substr(b) == name) return true;
  }
  return false;
}
} // namespace

std::string problemNamesND() {
  std::string out;
  for (const auto& e : kProblemsND) out += (out.empty() ? "" : ", ") + std::string(e.name);
  return out + "; planar (1D problems along -axis): " + problemNames();
}

PetscErrorCode createProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                               ProblemND* problem) {
  PetscFunctionBeginUser;
  PetscCheck(dim == 2 || dim == 3, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -dim %d: must be 2 or 3", dim);
  *problem = ProblemND{};
  problem->name = name;
  problem->dim = dim;
  for (const auto& e : kProblemsND)
    if (name == e.name) {
      PetscCall(e.create(comm, name, dim, axis, problem));
      PetscFunctionReturn(0);
    }
  if (isPlanarName(name)) {
    PetscCall(createPlanarProblemND(comm, name, dim, axis, problem));
    PetscFunctionReturn(0);
  }
  SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown problem '%s' (option -problem); known problems: %s",
          name.c_str(), problemNamesND().c_str());
}

PetscErrorCode checkStateN(MPI_Comm comm, const PrimN& w, const char* rho_option, const char* p_option) {
  PetscFunctionBeginUser;
  PetscCheck(w.rho > 0.0 && std::isfinite(w.rho), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial density %g (option %s): density must be > 0", w.rho, rho_option);
  PetscCheck(w.p > 0.0 && std::isfinite(w.p), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial pressure %g (option %s): pressure must be > 0", w.p, p_option);
  for (int d = 0; d < 3; ++d)
    PetscCheck(std::isfinite(w.u[d]), comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid initial velocity %g", w.u[d]);
  PetscFunctionReturn(0);
}

void extrudeAlongZ(int dim, ProblemND* pr) {
  pr->lo[2] = 0.0;
  pr->hi[2] = 1.0;
  pr->bc[2][0] = pr->bc[2][1] = BcN::Periodic;
  pr->default_n[2] = dim == 3 ? 6 : 1;
}

} // namespace suite::euler
