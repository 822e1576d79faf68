// Sparse symmetric positive definite direct solvers with a fixed pattern: analyze(pattern, ordering) once per
// mesh, factor(values) per Newton step, solve(b). Registry by name: skyline (own envelope Cholesky), banded
// (LAPACK), cholmod, petsc (distributed).
#pragma once

#include "core/named_choice.hpp"
#include "fem/sparse.hpp"

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

namespace suite::fem {

struct FactorStats {
  long long nnz_L = 0; // stored factor entries (skyline: envelope + diagonal)
  double flops = 0;    // of one numeric factorisation (estimate)
};

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  virtual const char* name() const = 0;
  // Reads the solver's own options (petsc: KSPSetFromOptions); called while the app reads its options.
  virtual PetscErrorCode setFromOptions(MPI_Comm) { return 0; }
  // The mesh node graph and eq[3*node + c] (free DOF index or -1), for solvers that partition by node (petsc).
  virtual void setNodeGraph(const Graph&, const std::vector<int>&) {}
  // A: upper-triangle pattern (values ignored); perm[new] = old. Called once per pattern.
  virtual PetscErrorCode analyze(MPI_Comm comm, const SymCsc& A, const std::vector<int>& perm) = 0;
  // Numeric factorisation of A (same pattern as analyze). *ok = false if A is not positive definite.
  virtual PetscErrorCode factor(const SymCsc& A, bool* ok) = 0;
  // x = A^{-1} b (x may alias b).
  virtual PetscErrorCode solve(const double* b, double* x) = 0;
  virtual FactorStats stats() const = 0;
  // Distributed assembly (petsc at several ranks): the values given to factor() are this rank's partial sums
  // (its elements only); the solver adds them up. nodePartition()[node] = owning rank (after analyze).
  virtual bool distributedAssembly() const { return false; }
  virtual const std::vector<int>& nodePartition() const {
    static const std::vector<int> none;
    return none;
  }
  // One line for the log (default: the name).
  virtual std::string describe() const { return name(); }
};

std::unique_ptr<LinearSolver> makeSkylineSolver();
std::unique_ptr<LinearSolver> makeCholmodSolver();
std::unique_ptr<LinearSolver> makeBandedSolver(); // LAPACK dpbtrf on the band of the ordering
std::unique_ptr<LinearSolver> makePetscSolver();  // MPIAIJ on a METIS node partition, KSP (MUMPS or CG+GAMG)
std::vector<std::string> solverNames();
std::vector<suite::Choice> solverChoices(); // with each solver's one-line help (-help lists them)
PetscErrorCode createLinearSolver(MPI_Comm comm, const std::string& name, std::unique_ptr<LinearSolver>* out);

} // namespace suite::fem
