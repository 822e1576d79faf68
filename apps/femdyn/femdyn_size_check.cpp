// femdyn's sizes, checked before the allocations they drive (core/resource_checks.hpp): the integer options
// within PetscInt; the mesh's nodes, DOFs, elements and stiffness nonzeros within PetscInt; and the memory
// estimate against the node's limit, twice: before the mesh and model (from -beam_cells and -order, or from a
// mesh file's counts) and, once the ordering's symbolic metrics are known, before the factorisation.
// Measured (Release, -solver cholmod, peak RSS): P1 beam 8000x2x2 (72k nodes) 545 MB, P2 2000x2x2 (100k nodes)
// 1.22 GB, 40x8x8 P1 (3.3k nodes, nnz(L) 2.3M) 96 MB; 200 snapshots of 54k DOFs add 100 MB. The model below
// (50 MB + 7 kB (P1) or 8.5 kB (P2) per node + 16 bytes per factor entry + the history) is above each.
#include "core/resource_checks.hpp"
#include "femdyn_run.hpp"

#include <cstdio>
#include <string>

namespace femdyn_app {

namespace {
constexpr double kBase = 5e7; // libraries, PETSc, buffers

// Mesh, model and matrices per node (replicated on every rank except the distributed matrix of -solver petsc).
double bytesPerNode(int order, bool distributed, int nranks) {
  const double matrices = order == 2 ? 7500.0 : 6000.0;
  return 1000.0 + (distributed ? matrices / nranks : matrices);
}

// Stored factor entries of the chosen solver from the ordering's metrics (-solver petsc: its PC, not known).
double factorEntries(const std::string& solver, const suite::fem::OrderingMetrics& m, double n) {
  if (solver == "banded") return n * (double)(m.bandwidth + 1);
  if (solver == "skyline") return (double)m.profile + n;
  if (solver == "cholmod") return (double)m.nnz_L;
  return 0.0;
}
} // namespace

// The integer options (PETSc wraps values beyond PetscInt silently).
PetscErrorCode FemdynRun::checkIntegerOptions() const {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  PetscCall(suite::checkIntListOptionRange(comm, "-beam_cells", 1));
  for (const char* name : {"-order", "-steps", "-load_steps", "-snapshot_every", "-newton_max_it",
                           "-max_halvings", "-lagged_refresh_iterations", "-newton_max_corrections"})
    PetscCall(suite::checkIntOptionRange(comm, name, 0));
  PetscFunctionReturn(0);
}

// A mesh of `nodes` nodes and `elems` elements of order opt_.order (`what`: the options that set it).
PetscErrorCode FemdynRun::checkModelSizes(double nodes, double elems, const char* what) const {
  MPI_Comm comm = ctx_.comm();
  const int order = (int)opt_.order;
  const double stiffness_nnz = 9.0 * nodes * (order == 2 ? 27.0 : 15.0); // both triangles, incl. diagonal
  const double snapshots =
      opt_.is_static ? 1.0 : 2.0 + (opt_.snapshot_every > 0 ? opt_.steps / opt_.snapshot_every : 0);
  const double history = (opt_.is_static ? 0.0 : opt_.steps * sizeof(StepRecord) * 1.5) +
                         snapshots * 3.0 * nodes * sizeof(double) * 1.2;
  const bool distributed = opt_.solver == "petsc" && ctx_.size() > 1;
  PetscFunctionBeginUser;
  PetscCall(suite::checkIndexCount(comm, nodes, "mesh nodes", what));
  PetscCall(suite::checkIndexCount(comm, 3.0 * nodes, "DOFs (3 per node)", what));
  PetscCall(suite::checkIndexCount(comm, elems * (order == 2 ? 10 : 4), "element node indices", what));
  PetscCall(suite::checkIndexCount(comm, stiffness_nnz, "stiffness matrix nonzeros (estimate)", what));
  std::string memory_what = what;
  if (!opt_.is_static)
    memory_what += " -steps " + std::to_string((long long)opt_.steps) + " -snapshot_every " +
                   std::to_string((long long)opt_.snapshot_every);
  PetscCall(suite::checkMemoryEstimate(
      comm, kBase + nodes * bytesPerNode(order, distributed, ctx_.size()) + history, memory_what.c_str()));
  PetscFunctionReturn(0);
}

// The structured beam's counts from -beam_cells and -order, before the mesh is built.
PetscErrorCode FemdynRun::checkBeamSizes() const {
  const auto& c = opt_.beam.cells;
  const double k = opt_.order == 2 ? 2.0 : 1.0;
  const double nodes = (k * c[0] + 1) * (k * c[1] + 1) * (k * c[2] + 1);
  const double elems = 6.0 * c[0] * c[1] * c[2];
  char what[160];
  std::snprintf(what, sizeof what, "-beam_cells %d,%d,%d -order %d", c[0], c[1], c[2], (int)opt_.order);
  PetscFunctionBeginUser;
  PetscCall(checkModelSizes(nodes, elems, what));
  PetscFunctionReturn(0);
}

// The factorisation's storage, from the ordering's symbolic metrics (before the solver's analysis).
PetscErrorCode FemdynRun::checkFactorSizes() const {
  const double n = model_.numFree();
  const double entries = factorEntries(opt_.solver, res_.metrics, n);
  const double nodes = mesh_.numNodes();
  const bool distributed = opt_.solver == "petsc" && ctx_.size() > 1;
  char what[200];
  std::snprintf(what, sizeof what, "The factor of -solver %s with -ordering %s (%.3g entries) on the %s mesh",
                opt_.solver.c_str(), opt_.ordering.c_str(), entries,
                opt_.mesh == "beam" ? "-beam_cells" : "-mesh_file");
  PetscFunctionBeginUser;
  PetscCall(suite::checkMemoryEstimate(
      ctx_.comm(), kBase + nodes * bytesPerNode((int)opt_.order, distributed, ctx_.size()) + 16.0 * entries,
      what));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
