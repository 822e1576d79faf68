// femdyn -backend plex: setup, the static solve or the time steps with checkpoints and stop requests (see
// femdyn_plex.hpp).
#include "femdyn_plex.hpp"

#include "core/clocks.hpp"
#include "core/log.hpp"
#include "fem/material.hpp"
#include "fem/plex_beam.hpp"
#include "fem/plex_mesh_file.hpp"
#include "fem/plex_mesh_h5.hpp"
#include "core/run_summary.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <algorithm>

namespace femdyn_app {

using namespace suite::fem;

namespace {

// Options of the replicated path that -backend plex does not implement (yet): given explicitly, an error.
PetscErrorCode refuseUnsupported(MPI_Comm comm, const Options& o) {
  static const char* names[] = {"-order",
                                "-material_auto_law",
                                "-target_error",
                                "-target_switch_up",
                                "-target_switch_down",
                                "-ordering",
                                "-solver",
                                "-load_steps",
                                "-jacobian",
                                "-newton_predictor",
                                "-lagged_refresh_contraction",
                                "-lagged_refresh_iterations",
                                "-newton_max_corrections",
                                "-mass",
                                "-max_halvings",
                                "-probe",
                                "-probe_point",
                                "-probe_stiffness",
                                "-probe_speed",
                                "-probe_depth",
                                "-haptic_rate",
                                "-dt_adapt",
                                "-dt_min",
                                "-dt_max",
                                "-load_release"};
  PetscFunctionBeginUser;
  for (const char* n : names) {
    PetscBool set = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, n, &set));
    PetscCheck(!set, comm, PETSC_ERR_SUP, "%s is not available with -backend plex (the distributed path)", n);
  }
  PetscCheck(o.mesh == "beam" || o.mesh == "file", comm, PETSC_ERR_SUP,
             "-backend plex: -mesh %s is not available (beam or file)", o.mesh.c_str());
  PetscCheck(o.material != "auto", comm, PETSC_ERR_SUP, "-backend plex has no -material auto (yet)");
  PetscFunctionReturn(0);
}

} // namespace

PlexRun::~PlexRun() {
  DMDestroy(&dm_);
}

PetscErrorCode PlexRun::checkLocalDofs() const {
  Vec l;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &l));
  PetscCall(VecGetLocalSize(l, &n));
  PetscCall(DMRestoreLocalVector(dm_, &l));
  PetscCall(checkRankCapCount(ctx_.comm(), n, o_.plex_rank_cap, "local DOFs", "in its local vector"));
  PetscFunctionReturn(0);
}

// The generated beam or the mesh file, distributed, with the natural node of each local vertex.
PetscErrorCode PlexRun::createMesh(std::vector<PetscInt>* vertex_node, long long* nodes) {
  PetscFunctionBeginUser;
  if (o_.mesh == "beam") {
    const auto& c = o_.beam.cells;
    PetscCall(createPlexBeam(ctx_.comm(), o_.beam, o_.plex_rank_cap, &dm_));
    PetscCall(beamVertexNodes(dm_, o_.beam, vertex_node));
    *nodes = (long long)(c[0] + 1) * (c[1] + 1) * (c[2] + 1);
  } else {
    PlexFileMesh m;
    PetscCall(createPlexFromFile(ctx_.comm(), o_.mesh_file, o_.plex_rank_cap, &m));
    dm_ = m.dm, *nodes = m.nodes;
    vertex_node->swap(m.vertex_node);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::setup() {
  MPI_Comm comm = ctx_.comm();
  Lame lame;
  Vec g;
  PetscFunctionBeginUser;
  const double t0 = suite::wallSeconds();
  PetscCall(refuseUnsupported(comm, o_));
  if (!o_.output.empty()) PetscCall(suite::checkOutputWritable(comm, o_.output, "output"));
  PetscCall(lameFromYoung(comm, o_.young, o_.poisson, &lame));
  std::vector<PetscInt> vertex_node;
  long long nodes = 0;
  PetscCall(createMesh(&vertex_node, &nodes));
  PetscCall(plexSupportsAndLoads(dm_, o_, &groups_));
  PlexElasticParams p;
  p.law = o_.material, p.lame = lame, p.rho = o_.density, p.prescribed = groups_.held;
  p.rayleigh_mass = o_.newmark.rayleigh_mass, p.rayleigh_stiffness = o_.newmark.rayleigh_stiffness;
  std::copy(o_.gravity, o_.gravity + 3, p.gravity);
  const auto& n = o_.newmark;
  PetscCall(nm_.setup(dm_, p, groups_.loads, n.beta, n.gamma, n.newton_rtol, n.newton_atol, n.newton_max_it));
  nm_.setPrescribedRamp(o_.bc_ramp);
  nm_.setGeneralizedAlpha(n.alpha_m, n.alpha_f);
  PetscCheck(
      !(nm_.prescribed().nonzero() && !o_.is_static && (policy_.enabled() || policy_.restartRequested())),
      comm, PETSC_ERR_SUP,
      "-bc_displacement with nonzero values: dynamic runs are not checkpointed (the prescribed DOFs' "
      "velocities and accelerations are not in the checkpoint)");
  PetscCall(ctx_.checkUnusedOptions()); // after SNESSetFromOptions: -snes_*, -ksp_*, -pc_* are used now
  PetscCall(nat_.setup(dm_, nodes, vertex_node));
  PetscCall(plexGlobalSizes(dm_, &nv_, &nc_));
  PetscCall(DMGetGlobalVector(dm_, &g));
  PetscCall(VecGetSize(g, &ndof_));
  PetscCall(DMRestoreGlobalVector(dm_, &g));
  PetscCall(checkLocalDofs());
  if (policy_.restartRequested()) {
    std::string path;
    PetscCall(policy_.restartPath(&path));
    PetscCall(readCheckpoint(path));
  }
  setup_s_ = suite::wallSeconds() - t0;
  PetscCall(suite::logInfo(comm, ctx_.quiet(),
                           "femdyn plex: %s, %lld nodes, %lld P1 tets, %d free DOFs on %d ranks (distributed "
                           "DMPlex), material %s, setup %.3f s",
                           o_.mesh == "beam" ? "generated beam" : o_.mesh_file.c_str(), nv_, nc_, (int)ndof_,
                           ctx_.size(), o_.material.c_str(), setup_s_));
  PetscFunctionReturn(0);
}

// After accepted step `step`: a periodic checkpoint, or on a stop request a final one (when enabled).
PetscErrorCode PlexRun::afterStep(long long step, bool* stop) {
  bool due = false;
  PetscFunctionBeginUser;
  PetscCall(ctx_.stopRequested(stop));
  PetscCall(policy_.due(step, &due));
  if (policy_.enabled() && (due || *stop)) PetscCall(writeCheckpoint(step));
  if (*stop) {
    status_ = ctx_.stopReason() == "max_walltime" ? "stopped by walltime" : "stopped by signal";
    PetscCall(suite::logInfo(ctx_.comm(), false, "femdyn plex: stopped after step %lld (%s)", step,
                             ctx_.stopReason().c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::timeSteps() {
  PetscFunctionBeginUser;
  if (!restarted_) PetscCall(nm_.initialize());
  if (!restarted_ && o_.snapshot_every > 0) PetscCall(snapshot());
  for (long long s = (long long)steps_.size(); s < o_.steps; ++s) {
    const double w0 = suite::wallSeconds(), c0 = suite::processCpuSeconds();
    PlexStepStats st;
    PetscCall(nm_.step(o_.dt, &st));
    double tip, kinetic, strain;
    PetscCall(nm_.groupMean(groups_.tip, 1, -1.0, &tip));
    PetscCall(nm_.energies(&kinetic, &strain));
    steps_.push_back({nm_.time(), tip, suite::wallSeconds() - w0, suite::processCpuSeconds() - c0, kinetic,
                      strain, (long long)st.newton_iterations, (long long)st.linear_iterations});
    if (o_.snapshot_every > 0 && (s + 1) % o_.snapshot_every == 0) PetscCall(snapshot());
    bool stop = false;
    PetscCall(afterStep(s + 1, &stop));
    if (stop) break;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::solve() {
  PetscFunctionBeginUser;
  const double t0 = suite::wallSeconds();
  if (o_.is_static)
    PetscCall(nm_.solveStatic(&stat_));
  else
    PetscCall(timeSteps());
  solve_s_ = suite::wallSeconds() - t0;
  PetscCall(nm_.groupMean(groups_.tip, 1, -1.0, &tip_));
  PetscCall(nm_.groupMean(groups_.tip, 0, 1.0, &tip_ux_));
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                           "femdyn plex: tip_deflection %.10g (mean -u_y on the group tip), tip u_x %.6g, %s "
                           "%.3f s",
                           tip_, tip_ux_, o_.is_static ? "static solve" : "time steps", solve_s_));
  PetscCall(write());
  char what[128];
  PetscCall(PetscSNPrintf(what, sizeof what, "%s in %.3f s (distributed, %d ranks)",
                          o_.is_static ? "static solve" : (std::to_string(steps_.size()) + " steps").c_str(),
                          solve_s_, ctx_.size()));
  PetscCall(suite::logRunSummary(ctx_, status_, what, suite::outputWithSidecar(o_.output)));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::convertMesh() {
  std::vector<PetscInt> vertex_node;
  long long nodes = 0;
  PetscFunctionBeginUser;
  const double t0 = suite::wallSeconds();
  PetscCall(refuseUnsupported(ctx_.comm(), o_));
  PetscCall(suite::checkOutputWritable(ctx_.comm(), o_.mesh_convert, "mesh_convert"));
  PetscCall(createMesh(&vertex_node, &nodes));
  PetscCall(nat_.setupLayout(dm_, nodes, vertex_node));
  PetscCall(plexGlobalSizes(dm_, &nv_, &nc_));
  PetscCall(ctx_.checkUnusedOptions());
  PetscCall(writePlexMeshH5(dm_, nat_, ctx_, o_.mesh_convert));
  char what[256];
  PetscCall(PetscSNPrintf(what, sizeof what, "mesh of %lld nodes and %lld tetrahedra converted in %.3f s",
                          nv_, nc_, suite::wallSeconds() - t0));
  PetscCall(suite::logRunSummary(ctx_, "completed", what, {o_.mesh_convert}));
  PetscFunctionReturn(0);
}

PetscErrorCode runPlexFemdyn(const suite::RunContext& ctx, const Options& opt,
                             suite::CheckpointPolicy& policy) {
  PlexRun run(ctx, opt, policy);
  PetscFunctionBeginUser;
  if (!opt.mesh_convert.empty()) {
    PetscCall(run.convertMesh());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(run.solve());
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
