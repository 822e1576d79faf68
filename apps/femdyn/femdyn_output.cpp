// femdyn output: provenance and run attributes, the mesh (corner nodes of the tets for XDMF), ordering
// metrics, the static result or the per-step timings and energies, the haptic probe's histories, snapshots
// with an XDMF tetrahedral series, the final displacement.
#include "core/log_stages.hpp"
#include "femdyn_run.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <cstdio>

namespace femdyn_app {

namespace {
using ull = unsigned long long;

// The column f of the step records as /steps/<name>.
template <class T>
PetscErrorCode writeColumn(suite::H5Output& out, const std::vector<StepRecord>& steps,
                           const StepColumn<T>& c) {
  std::vector<T> v(steps.size());
  PetscFunctionBeginUser;
  for (size_t i = 0; i < steps.size(); ++i) v[i] = steps[i].*c.field;
  PetscCall(out.writeReplicated(std::string("/steps/") + c.name, v.data(), {(ull)v.size()}, c.units));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode FemdynRun::writeRunAttributes(suite::H5Output& out) const {
  PetscFunctionBeginUser;
  PetscCall(out.writeAttribute("/", "status", res_.status));
  PetscCall(out.writeAttribute("/", "mode", opt_.is_static ? "static" : "dynamic"));
  PetscCall(out.writeAttribute("/", "material", opt_.materialAuto() ? "auto" : material_->name()));
  PetscCall(out.writeAttribute("/", "ordering", opt_.ordering));
  PetscCall(out.writeAttribute("/", "solver", solver_->name()));
  PetscCall(out.writeAttribute("/", "element_order", (long long)mesh_.order()));
  PetscCall(out.writeAttribute("/", "nodes", (long long)mesh_.numNodes()));
  PetscCall(out.writeAttribute("/", "elements", (long long)mesh_.numElems()));
  PetscCall(out.writeAttribute("/", "dofs", (long long)model_.numFree()));
  PetscCall(out.writeAttribute("/", "young", opt_.young));
  PetscCall(out.writeAttribute("/", "poisson", opt_.poisson));
  PetscCall(out.writeAttribute("/", "tip_load", opt_.tip_load));
  PetscCall(out.writeAttribute("/", "setup_seconds", res_.setup_time));
  PetscCall(out.writeAttribute("/", "solve_seconds", res_.loop_time));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeOrdering(suite::H5Output& out) const {
  const auto& m = res_.metrics;
  PetscFunctionBeginUser;
  PetscCall(out.createGroup("/ordering"));
  PetscCall(out.writeAttribute("/ordering", "name", opt_.ordering));
  PetscCall(out.writeAttribute("/ordering", "taken", res_.ordering_taken)); // auto: the one it chose
  PetscCall(out.writeAttribute("/ordering", "bandwidth", m.bandwidth));
  PetscCall(out.writeAttribute("/ordering", "profile", m.profile));
  PetscCall(out.writeAttribute("/ordering", "profile_definition", suite::fem::kProfileDefinition));
  PetscCall(out.writeAttribute("/ordering", "nnz_L", m.nnz_L));
  PetscCall(out.writeAttribute("/ordering", "factor_flops", m.flops));
  PetscCall(out.writeAttribute("/ordering", "envelope_flops", m.envelope_flops));
  PetscCall(out.writeAttribute("/ordering", "time", res_.ordering_time));
  PetscCall(out.writeAttribute("/ordering", "solver_nnz_L", res_.factor.nnz_L));
  PetscFunctionReturn(0);
}

// Mesh: coordinates and the corner nodes of every tet (XDMF Tetrahedron); the final displacement.
PetscErrorCode FemdynRun::writeMesh(suite::H5Output& out) const {
  const ull nn = (ull)mesh_.numNodes(), ne = (ull)mesh_.numElems();
  PetscFunctionBeginUser;
  PetscCall(
      out.writeReplicated("/mesh/coordinates", suite::fem::flatCoordinates(mesh_).data(), {nn, 3}, "m"));
  PetscCall(out.writeReplicated("/mesh/tets", suite::fem::cornerNodes(mesh_).data(), {ne, 4}, ""));
  PetscCall(out.writeReplicated("/final/u", res_.u_full.data(), {nn, 3}, "m"));
  PetscFunctionReturn(0);
}

// Per-step records (step 0 first) as /steps columns, and the run's rates.
PetscErrorCode FemdynRun::writeSteps(suite::H5Output& out) const {
  const size_t n = res_.steps.size();
  PetscFunctionBeginUser;
  for (const auto& c : kStepReals) PetscCall(writeColumn(out, res_.steps, c));
  for (const auto& c : kStepCounts) PetscCall(writeColumn(out, res_.steps, c));
  double wall = 0, cpu = 0;
  for (size_t i = 1; i < n; ++i) wall += res_.steps[i].total, cpu += res_.steps[i].cpu;
  PetscCall(out.writeAttribute("/", "steps", (long long)(n - 1)));
  PetscCall(out.writeAttribute("/", "dt", opt_.dt));
  PetscCall(out.writeAttribute("/", "rate_hz", cpu > 0 ? (n - 1) / cpu : 0.0)); // steps per CPU second
  PetscCall(out.writeAttribute("/", "rate_hz_wall", wall > 0 ? (n - 1) / wall : 0.0));
  PetscCall(out.writeAttribute("/", "tip_deflection", res_.steps.back().tip_uy));
  PetscFunctionReturn(0);
}

// force_predicted[i]: the local model's force at sync_time[i+1], made at sync_time[i].
PetscErrorCode FemdynRun::writeProbe(suite::H5Output& out) const {
  const auto& pr = res_.probe;
  const struct {
    const char* name;
    const std::vector<double>& v;
    const char* units;
  } series[] = {{"sync_time", pr.sync_time, "s"},
                {"force_full", pr.force_full, "N"},
                {"force_predicted", pr.force_predicted, "N"},
                {"compliance_yy", pr.compliance_yy, "m/N"},
                {"haptic_time", pr.haptic_time, "s"},
                {"haptic_force", pr.haptic_force, "N"}};
  PetscFunctionBeginUser;
  PetscCall(out.createGroup("/probe"));
  PetscCall(out.writeAttribute("/probe", "node", (long long)pr.node));
  PetscCall(out.writeAttribute("/probe", "stiffness", opt_.probe_set.stiffness));
  PetscCall(out.writeAttribute("/probe", "haptic_rate", opt_.probe_set.haptic_rate));
  PetscCall(out.writeAttribute("/probe", "haptic_ticks", pr.ticks));
  PetscCall(out.writeAttribute("/probe", "haptic_tick_cpu_seconds", pr.tick_seconds));
  PetscCall(out.writeAttribute("/probe", "compliance_cpu_seconds", pr.compliance_seconds));
  for (const auto& s : series)
    PetscCall(out.writeReplicated(std::string("/probe/") + s.name, s.v.data(), {(ull)s.v.size()}, s.units));
  PetscFunctionReturn(0);
}

// Snapshots /snapshots/NNNNNN/u and the steps of the XDMF series over them (or over /final/u alone).
PetscErrorCode FemdynRun::writeSnapshots(suite::H5Output& out,
                                         std::vector<suite::XdmfTetStep>* xsteps) const {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < res_.snapshots.size(); ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "/snapshots/%06zu/u", k);
    PetscCall(out.writeReplicated(name, res_.snapshots[k].second.data(), {(ull)mesh_.numNodes(), 3}, "m"));
    xsteps->push_back({res_.snapshots[k].first, {{"displacement", name, 3}}});
  }
  if (xsteps->empty())
    xsteps->push_back({res_.steps.empty() ? 0.0 : res_.steps.back().time, {{"displacement", "/final/u", 3}}});
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeOutput() const {
  suite::LogStages stages;
  suite::H5Output out;
  std::vector<suite::XdmfTetStep> xsteps;
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(0); // no -output: nothing written
  PetscCall(suite::LogStages::get(&stages));
  suite::StageScope stage(stages.output);
  PetscCall(out.open(ctx_.comm(), opt_.output));
  PetscCall(out.writeProvenance(ctx_));
  PetscCall(writeRunAttributes(out));
  PetscCall(writeOrdering(out));
  PetscCall(writeMesh(out));
  if (opt_.is_static) { // the static result
    PetscCall(out.writeAttribute("/", "tip_deflection", res_.tip_deflection));
    PetscCall(out.writeAttribute("/", "tip_ux", res_.tip_ux));
    PetscCall(out.writeAttribute("/", "load_steps", (long long)res_.stat.load_steps));
    PetscCall(out.writeAttribute("/", "newton_iterations", (long long)res_.stat.newton_iterations));
    PetscCall(out.writeAttribute("/", "residual", res_.stat.residual));
    PetscCall(out.writeAttribute("/", "strain_energy", res_.stat.energy));
  } else if (!res_.steps.empty()) {
    PetscCall(writeSteps(out));
  }
  if (!res_.probe.sync_time.empty()) PetscCall(writeProbe(out));
  if (!res_.law.empty()) PetscCall(writeMaterialAuto(out));
  if (!res_.adapt_dt.empty()) PetscCall(writeTimeAdapt(out));
  PetscCall(writeSnapshots(out, &xsteps));
  PetscCall(out.commit(&ctx_));
  suite::XdmfTetMesh xm{"/mesh/coordinates", "/mesh/tets", (ull)mesh_.numNodes(), (ull)mesh_.numElems()};
  PetscCall(suite::writeXdmfTetSeries(ctx_.comm(), suite::xdmfPathFor(opt_.output),
                                      suite::fileNameOf(opt_.output), xm, xsteps));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
