// femdyn setup: material, mesh (beam or Gmsh/TetGen file, P2 promotion: fem::makeMesh), the clamped Dirichlet
// plane and the elastic model, the loads (fem/beam_loads.hpp), the fill-reducing ordering and the solver's
// symbolic analysis (with -solver petsc at several ranks: each rank assembles the elements it owns).
#include "core/log.hpp"
#include "core/clocks.hpp"
#include "fem/material.hpp"
#include "fem/mesh.hpp"
#include "femdyn_run.hpp"
#include "io/h5_output.hpp"

namespace femdyn_app {

using namespace suite::fem;

PetscErrorCode FemdynRun::buildMesh() {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  if (opt_.mesh == "beam") PetscCall(checkBeamSizes());
  PetscCall(makeMesh(comm, opt_.mesh, opt_.beam, opt_.mesh_file, (int)opt_.order, &mesh_));
  if (opt_.mesh != "beam") {
    const std::string what = "-mesh_file " + opt_.mesh_file + " -order " + std::to_string((int)opt_.order);
    PetscCall(checkModelSizes(mesh_.numNodes(), mesh_.numElems(), what.c_str()));
  }
  if (opt_.poisson > 0.45 && mesh_.order() == 1)
    PetscCall(suite::logInfo(
        comm, false,
        "femdyn: warning: -poisson %g with P1 tetrahedra: volumetric locking makes the response "
        "far too stiff (use -order 2)",
        opt_.poisson));
  PetscFunctionReturn(0);
}

// All DOFs of the nodes on the -dirichlet plane fixed; the elastic model on the free DOFs.
PetscErrorCode FemdynRun::clampAndSetupModel() {
  MPI_Comm comm = ctx_.comm();
  std::vector<char> fixed;
  PetscFunctionBeginUser;
  PetscCall(clampPlane(comm, "-dirichlet", opt_.dirichlet, mesh_, &fixed));
  int nfixed = 0;
  for (char f : fixed) nfixed += f;
  PetscCheck(
      !opt_.is_static || nfixed > 0, comm, PETSC_ERR_ARG_WRONG,
      "Dirichlet set -dirichlet %s is empty (no mesh node on that plane): the static problem is singular",
      opt_.dirichlet.c_str());
  PetscCall(model_.setup(comm, mesh_, *material_, fixed));
  if (material_nl_) PetscCall(model_nl_.setup(comm, mesh_, *material_nl_, fixed)); // -material auto
  PetscFunctionReturn(0);
}

// Ordering on the node graph, expanded to the free DOFs; metrics on the DOF matrix; the solver's analysis.
PetscErrorCode FemdynRun::orderAndAnalyze() {
  MPI_Comm comm = ctx_.comm();
  OrderingFn order_fn;
  PetscFunctionBeginUser;
  PetscCall(findOrdering(comm, opt_.ordering, &order_fn));
  const double to = suite::threadCpuSeconds();
  OrderingChoice choice = runOrdering(opt_.ordering, model_.nodeGraphOf());
  perm_ = expandToDofs(choice.perm, model_.eq(), model_.numFree());
  res_.ordering_time = suite::threadCpuSeconds() - to;
  res_.ordering_taken = choice.name;
  res_.metrics = computeMetrics(graphOfMatrix(model_.pattern()), perm_);
  PetscCall(checkFactorSizes());
  solver_->setNodeGraph(model_.nodeGraphOf(), model_.eq());
  PetscCall(solver_->analyze(comm, model_.pattern(), perm_));
  if (solver_->distributedAssembly()) { // each rank assembles its elements of the solver's node partition
    model_.ownElementsOfNodes(solver_->nodePartition(), ctx_.rank());
    partial_ = opt_.newmark.partial_sums = true;
  }
  if (solver_nl_) { // -material auto: the nonlinear law's solver, same pattern and ordering
    solver_nl_->setNodeGraph(model_nl_.nodeGraphOf(), model_nl_.eq());
    PetscCall(solver_nl_->analyze(comm, model_nl_.pattern(), perm_));
    if (solver_nl_->distributedAssembly())
      model_nl_.ownElementsOfNodes(solver_nl_->nodePartition(), ctx_.rank());
  }
  if (solver_filter_) { // -dt_adapt: the low-pass filter on the linear pattern (model_'s partition)
    solver_filter_->setNodeGraph(model_.nodeGraphOf(), model_.eq());
    PetscCall(solver_filter_->analyze(comm, model_.pattern(), perm_));
  }
  res_.factor = solver_->stats();
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::setup() {
  MPI_Comm comm = ctx_.comm();
  Lame lame;
  PetscFunctionBeginUser;
  if (!opt_.output.empty()) PetscCall(suite::checkOutputWritable(comm, opt_.output, "output"));
  const double t0 = suite::wallSeconds();
  PetscCall(lameFromYoung(comm, opt_.young, opt_.poisson, &lame));
  PetscCall(createMaterial(comm, opt_.materialAuto() ? "linear" : opt_.material, lame, &material_));
  if (opt_.materialAuto()) PetscCall(createMaterial(comm, opt_.auto_law, lame, &material_nl_));
  PetscCall(buildMesh());
  PetscCall(clampAndSetupModel());
  tip_nodes_ = tipNodes(mesh_); // the loads: total -tip_load along -y on the end face x = max, and gravity
  PetscCall(tipTractionLoad(comm, model_, opt_.tip_load, &f_ext_));
  addGravityLoad(model_, opt_.density, opt_.gravity, &f_ext_);
  PetscCall(orderAndAnalyze());
  res_.setup_time = suite::wallSeconds() - t0;
  const bool chose = res_.ordering_taken != opt_.ordering;
  const std::string taken_note = chose ? " (took " + res_.ordering_taken : "";
  const char* taken_end = chose ? ")" : "";
  PetscCall(suite::logInfo(
      comm, ctx_.quiet(),
      "femdyn: %d nodes, %d P%d tets, %d free DOFs, material %s, ordering %s%s%s (%.3f ms): "
      "bandwidth %lld, profile %lld, nnz(L) %lld, %.3g flops; solver %s",
      mesh_.numNodes(), mesh_.numElems(), mesh_.order(), model_.numFree(),
      opt_.materialAuto() ? ("auto (linear/" + opt_.auto_law + ")").c_str() : material_->name(),
      opt_.ordering.c_str(), taken_note.c_str(), taken_end, 1e3 * res_.ordering_time, res_.metrics.bandwidth,
      res_.metrics.profile, res_.metrics.nnz_L, res_.metrics.flops, solver_->describe().c_str()));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
