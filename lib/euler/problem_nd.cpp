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
  const char* description; // one line for -help
};
const EntryND kProblemsND[] = {
    {"isentropic_vortex", createVortexProblemND,
     "Isentropic vortex advected by a uniform flow, periodic, exact"},
    {"riemann2d", createRiemann2dProblemND, "Four-quadrant 2D Riemann problem with any states (-rho_ne ...)"},
    {"lax_liu_4", createRiemann2dProblemND, "Lax-Liu configuration 4: four shocks"},
    {"lax_liu_6", createRiemann2dProblemND, "Lax-Liu configuration 6: four slip lines"},
    {"liska_wendroff_3", createRiemann2dProblemND, "Liska-Wendroff configuration 3: four shocks"},
    {"double_mach", createDoubleMachProblemND, "Woodward-Colella double Mach reflection of a Mach 10 shock"},
    {"rayleigh_taylor", createRayleighTaylorProblemND, "Rayleigh-Taylor instability under gravity"},
    {"explosion", createExplosionProblemND, "Toro's cylindrical (2D) / spherical (3D) explosion"},
    {"sedov", createExplosionProblemND, "Sedov point explosion in a cold uniform gas"},
    {"jet", createJetProblemND, "Zhang-Shu Mach 2000 astrophysical jet, inflow on part of the left face"},
    {"taylor_green", createTaylorGreenProblemND, "Inviscid Taylor-Green vortex at Mach 0.1 (3D only)"},
    {"forward_step", createObstacleProblemND, "Woodward-Colella Mach 3 wind tunnel with a step (2D, solid)"},
    {"shock_cylinder", createObstacleProblemND, "Mach 2.8 shock over a cylinder (2D, solid)"},
    {"shock_sphere", createObstacleProblemND, "Mach 2.8 shock over a sphere (3D, solid)"},
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

std::vector<ProblemDoc> problemDocsND() {
  std::vector<ProblemDoc> docs;
  for (const auto& e : kProblemsND) docs.push_back({e.name, e.description});
  return docs;
}

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

bool isUserProblem(const std::string& name) {
  return name == "formula" || name == "file";
}

std::vector<ProblemDoc> userProblemDocs() {
  return {
      {"formula", "Your initial state as formulas of x, y, z (-ic_rho -ic_u -ic_v -ic_w -ic_p -ic_param)"},
      {"file", "Your initial state from an HDF5 file on the run's grid (-initial_state FILE.h5)"}};
}

PetscErrorCode createUserProblem(MPI_Comm comm, const std::string& name, int dim, ProblemND* pr) {
  PetscFunctionBeginUser;
  *pr = ProblemND{};
  pr->name = name;
  pr->dim = dim;
  pr->user_defined = true;
  pr->t_final = NAN;
  for (int d = 0; d < 3; ++d) {
    pr->default_n[d] = d < dim ? 0 : 1;
    pr->bc[d][0] = pr->bc[d][1] = d < dim ? BcN::Outflow : BcN::Periodic;
  }
  if (name == "formula")
    PetscCall(createFormulaProblem(comm, dim, pr));
  else
    PetscCall(createFileProblem(comm, dim, pr));
  PetscFunctionReturn(0);
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

std::string faceLabel(const ProblemND& pr, int dir, int side) {
  if (!pr.bc_label[dir][side].empty()) return pr.bc_label[dir][side];
  switch (pr.bc[dir][side]) {
  case BcN::Periodic:
    return "periodic";
  case BcN::Outflow:
    return "outflow";
  case BcN::Reflecting:
    return "wall";
  case BcN::Custom:
    return "custom";
  }
  return "?";
}

void extrudeAlongZ(int dim, ProblemND* pr) {
  pr->lo[2] = 0.0;
  pr->hi[2] = 1.0;
  pr->bc[2][0] = pr->bc[2][1] = BcN::Periodic;
  pr->default_n[2] = dim == 3 ? 6 : 1;
}

} // namespace suite::euler
