// Problem registry of the 1D Euler app: each problem family (one file each) reads its physical parameters
// from the PETSc options database and returns its standard domain, end time, boundary conditions, initial
// state and, where known, the exact solution. Invalid parameters (gamma <= 1, rho <= 0 or p <= 0 in an
// initial state) are reported collectively, naming the option.
#pragma once

#include "euler/gas.hpp"

#include <petscsys.h>

#include <functional>
#include <string>
#include <vector>

namespace suite::euler {

enum class Bc { Periodic, Outflow, Reflecting, Inflow };
const char* bcName(Bc bc);
// nullptr-safe parse of "periodic", "outflow", "reflecting", "inflow"; false when unknown.
bool parseBc(const std::string& name, Bc* bc);

struct Problem {
  std::string name;
  double gamma = 1.4, xmin = 0.0, xmax = 1.0, t_final = 0.2;
  Bc bc_left = Bc::Outflow, bc_right = Bc::Outflow;
  Prim inflow_left{1.0, 0.0, 1.0}, inflow_right{1.0, 0.0, 1.0}; // used by Bc::Inflow
  PetscInt default_nx = 200;
  PetscInt default_max_steps = -1; // > 0: problem defined by a step count (pulse: 2000)
  double default_dt = 0.0;         // > 0: fixed time step by default (pulse)
  PetscInt default_spacetime_every = 0;
  std::function<Prim(double x)> initial;
  std::function<Prim(double x, double t)> exact; // empty when no exact solution is known
};

// Reads the options of problem `name` (collective) into *problem. Unknown name: error listing the known ones.
PetscErrorCode createProblem(MPI_Comm comm, const std::string& name, Problem* problem);
std::string problemNames();
// Name and one-line description of every registered problem, in registry order (for -help).
struct ProblemDoc {
  const char* name;
  const char* description;
};
std::vector<ProblemDoc> problemDocs();

// Family factories (one file each), used by the registry in problem.cpp.
PetscErrorCode createRiemannProblem(MPI_Comm comm, const std::string& name, Problem* problem);
PetscErrorCode createShockEntropyProblem(MPI_Comm comm, const std::string& name, Problem* problem);
PetscErrorCode createBlastProblem(MPI_Comm comm, const std::string& name, Problem* problem);
PetscErrorCode createAdvectionProblem(MPI_Comm comm, const std::string& name, Problem* problem);

// Shared checks: gamma > 1 (option -gamma) and a physical state (options named by prefix, e.g. "_l").
PetscErrorCode checkGamma(MPI_Comm comm, double gamma);
PetscErrorCode checkState(MPI_Comm comm, const Prim& w, const char* rho_option, const char* p_option);

} // namespace suite::euler
