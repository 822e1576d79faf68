// Problem registry of the 2D/3D Euler app (-dim 2|3): each problem family (one file each, problem_nd_*.cpp)
// reads its parameters from the PETSc options database and returns its domain, end time, boundary conditions
// per face, initial state, optional exact solution and gravity. 1D problems (problem.hpp) run along any axis
// of a 2D/3D grid with -axis x|y|z (planar: the other directions are periodic on [0, 1]). Invalid parameters
// are reported collectively, naming the option.
#pragma once

#include "euler/problem.hpp"

#include <petscsys.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace suite::euler {

struct InitialStateFile; // initial_state_file.hpp

// Primitive state in 2D/3D: density, velocity (u, v, w) along (x, y, z), pressure. In 2D w = 0.
struct PrimN {
  double rho, u[3], p;
};

// Face boundary conditions. Custom: ghost cells from ProblemND::ghost (e.g. double Mach's mixed bottom wall
// and moving top boundary).
enum class BcN { Periodic, Outflow, Reflecting, Custom };

struct ProblemND {
  std::string name;
  int dim = 2;
  double gamma = 1.4;
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}; // domain [lo, hi] per direction (x, y, z)
  double t_final = 0.2;
  PetscInt default_n[3] = {64, 64, 64};
  BcN bc[3][2] = {
      {BcN::Periodic, BcN::Periodic}, {BcN::Periodic, BcN::Periodic}, {BcN::Periodic, BcN::Periodic}};
  double gravity[3] = {0, 0, 0};                 // source (0, rho g, rho u.g) when non-zero (rayleigh_taylor)
  std::function<PrimN(const double* x)> initial; // x: cell centre (3 numbers, unused ones 0)
  std::function<PrimN(const double* x, double t)> exact; // empty when no exact solution is known
  // Custom faces: state of the ghost cell centred at x on face (dir, side = 0 low / 1 high) at time t, given the
  // interior cell mirrored across the face (`mirror`) and the interior cell next to the face (`edge`).
  std::function<PrimN(int dir, int side, const double* x, double t, const PrimN& mirror, const PrimN& edge)>
      ghost;
  // Defaults carried over from a planar 1D problem (pulse: 2000 fixed steps of dt = 1.25e-4); -1 / 0: none.
  PetscInt default_max_steps = -1;
  double default_dt = 0.0;
  // A problem of the user's (`formula`, `file`): no end time (t_final NaN) and, for `formula`, no grid size
  // (default_n 0) of its own, so -t_final and -nx ... are required.
  bool user_defined = false;
  // `formula -ic_average`: the initial state is the cell average of conservative(initial) by this many Gauss
  // points per direction (0: point values at the cell centres).
  int initial_quadrature = 0;
  // `file`: the initial state is read from this HDF5 file's group (initial_state_file.hpp); `initial` is empty.
  std::string initial_file, initial_group;
  std::shared_ptr<const InitialStateFile> initial_state; // its datasets, as inspected
  bool fixed_extent[3] = {false, false,
                          false}; // `file`: lo/hi from the file's attributes (options may not differ)
  // Face names as the user gave them (-bc_x_lo wall, symmetry, inflow, ...; bcLabel() when empty), for the output.
  std::string bc_label[3][2];
  // Solid obstacle (solid_body.hpp): cells whose centre has solid(x) > 0 are solid; or, with solid_mask_file, the
  // cells whose mask value in that file is non-zero. Empty and "": no obstacle.
  std::function<double(const double* x)> solid;
  std::string solid_mask_file, solid_mask_group = "/";
  bool hasSolid() const { return static_cast<bool>(solid) || !solid_mask_file.empty(); }
};

// The name of face (dir, side) for output and messages: bc_label when set, else periodic / outflow / wall /
// custom from bc.
std::string faceLabel(const ProblemND& problem, int dir, int side);

// Reads the options of problem `name` (collective) for a `dim`-dimensional grid. `axis` (0, 1, 2) places a 1D
// problem of problem.hpp along that axis; ignored by genuinely multi-dimensional problems. Unknown name: one
// error listing the known ones; a problem that needs another dimension (taylor_green needs 3): clear error.
PetscErrorCode createProblemND(MPI_Comm comm, const std::string& name, int dim, int axis, ProblemND* problem);
std::string problemNamesND();
// The genuinely multi-dimensional problems with their one-line descriptions, in registry order (the planar
// ones are problemDocs() of problem.hpp).
std::vector<ProblemDoc> problemDocsND();

// Family factories (one file each, problem_nd_*.cpp), used by the registry in problem_nd.cpp. Each sets
// everything in ProblemND except name and dim (set by the registry before the call).
PetscErrorCode createVortexProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                     ProblemND* problem);
PetscErrorCode createRiemann2dProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                        ProblemND* problem);
PetscErrorCode createDoubleMachProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                         ProblemND* problem);
PetscErrorCode createRayleighTaylorProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                             ProblemND* problem);
PetscErrorCode createExplosionProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                        ProblemND* problem);
PetscErrorCode createJetProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                  ProblemND* problem);
PetscErrorCode createTaylorGreenProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                          ProblemND* problem);
PetscErrorCode createObstacleProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                       ProblemND* problem);
// Any 1D problem name of problem.hpp placed along `axis`.
// The boundary of a grid face for a 1D boundary condition (Inflow: a Custom face with the 1D inflow state).
BcN gridBc(Bc bc);

PetscErrorCode createPlanarProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                     ProblemND* problem);

// The user's own problems, for -dim 1|2|3: `formula` (problem_formula.cpp: -ic_rho ... as formulas of x, y, z)
// and `file` (problem_file.cpp: -initial_state FILE.h5). They set name and dim themselves.
bool isUserProblem(const std::string& name);
std::vector<ProblemDoc> userProblemDocs();
PetscErrorCode createUserProblem(MPI_Comm comm, const std::string& name, int dim, ProblemND* problem);
PetscErrorCode createFormulaProblem(MPI_Comm comm, int dim, ProblemND* problem);
PetscErrorCode createFileProblem(MPI_Comm comm, int dim, ProblemND* problem);

// Shared check: a physical state rho > 0, p > 0, finite velocity (options named, e.g. "-rho_ne", "-p_ne").
PetscErrorCode checkStateN(MPI_Comm comm, const PrimN& w, const char* rho_option, const char* p_option);
// A 2D problem run with -dim 3 is uniform along z: z in [0, 1], periodic, 6 cells by default (the app's
// minimum, its stencil width). In 2D it sets the unused z direction to one cell on [0, 1].
void extrudeAlongZ(int dim, ProblemND* problem);
// Reflecting-wall ghost: the mirrored interior state with the velocity normal to face `dir` negated.
inline PrimN reflectN(const PrimN& mirror, int dir) {
  PrimN g = mirror;
  g.u[dir] = -g.u[dir];
  return g;
}

} // namespace suite::euler
