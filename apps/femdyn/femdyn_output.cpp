// femdyn output: provenance and run attributes, the mesh (corner nodes of the tets for XDMF), ordering
// metrics, the static result or the per-step timings and energies, the haptic probe's histories, snapshots
// with an XDMF tetrahedral series, the final displacement.
#include "femdyn_run.hpp"

#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <cstdio>

namespace femdyn_app {

namespace {
using ull = unsigned long long;

template <class T> std::vector<T> column(const std::vector<StepRecord>& steps, T StepRecord::*f) {
  std::vector<T> c(steps.size());
  for (size_t i = 0; i < steps.size(); ++i) c[i] = steps[i].*f;
  return c;
}
} // namespace

PetscErrorCode FemdynRun::writeRunAttributes(suite::H5Output& out) const {
  PetscFunctionBeginUser;
  PetscCall(out.writeAttribute("/", "mode", opt_.is_static ? "static" : "dynamic"));
  PetscCall(out.writeAttribute("/", "material", material_->name()));
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
  PetscCall(out.writeAttribute("/ordering", "bandwidth", m.bandwidth));
  PetscCall(out.writeAttribute("/ordering", "profile", m.profile));
  PetscCall(out.writeAttribute("/ordering", "profile_definition",
                               "sum_i (i - f_i), f_i = first nonzero column of row i of the permuted lower "
                               "triangle (diagonal excluded)"));
  PetscCall(out.writeAttribute("/ordering", "nnz_L", m.nnz_L));
  PetscCall(out.writeAttribute("/ordering", "factor_flops", m.flops));
  PetscCall(out.writeAttribute("/ordering", "envelope_flops", m.envelope_flops));
  PetscCall(out.writeAttribute("/ordering", "time", res_.ordering_time));
  PetscCall(out.writeAttribute("/ordering", "solver_nnz_L", res_.factor.nnz_L));
  PetscFunctionReturn(0);
}

// Mesh: coordinates and the corner nodes of every tet (XDMF Tetrahedron); the final displacement.
PetscErrorCode FemdynRun::writeMesh(suite::H5Output& out) const {
  const long long nn = mesh_.numNodes(), ne = mesh_.numElems();
  PetscFunctionBeginUser;
  std::vector<double> xyz(3 * nn);
  for (long long v = 0; v < nn; ++v)
    for (int i = 0; i < 3; ++i) xyz[3 * v + i] = mesh_.nodes[v][i];
  std::vector<int> tets(4 * ne);
  for (long long e = 0; e < ne; ++e)
    for (int a = 0; a < 4; ++a) tets[4 * e + a] = mesh_.elem(e)[a];
  PetscCall(out.writeReplicated("/mesh/coordinates", xyz.data(), {(ull)nn, 3}, "m"));
  PetscCall(out.writeReplicated("/mesh/tets", tets.data(), {(ull)ne, 4}, ""));
  PetscCall(out.writeReplicated("/final/u", res_.u_full.data(), {(ull)nn, 3}, "m"));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeStatic(suite::H5Output& out) const {
  PetscFunctionBeginUser;
  PetscCall(out.writeAttribute("/", "tip_deflection", res_.tip_deflection));
  PetscCall(out.writeAttribute("/", "tip_ux", res_.tip_ux));
  PetscCall(out.writeAttribute("/", "load_steps", (long long)res_.stat.load_steps));
  PetscCall(out.writeAttribute("/", "newton_iterations", (long long)res_.stat.newton_iterations));
  PetscCall(out.writeAttribute("/", "residual", res_.stat.residual));
  PetscCall(out.writeAttribute("/", "strain_energy", res_.stat.energy));
  PetscFunctionReturn(0);
}

// Per-step records (step 0 first) as /steps columns, and the run's rates.
PetscErrorCode FemdynRun::writeSteps(suite::H5Output& out) const {
  const size_t n = res_.steps.size();
  const struct {
    const char* name;
    double StepRecord::*f;
    const char* units;
  } cols[] = {{"time", &StepRecord::time, "s"},
              {"assemble", &StepRecord::assemble, "s"},
              {"factor", &StepRecord::factor, "s"},
              {"solve", &StepRecord::solve, "s"},
              {"wall", &StepRecord::total, "s"},
              {"cpu", &StepRecord::cpu, "s"},
              {"kinetic_energy", &StepRecord::kinetic, "J"},
              {"strain_energy", &StepRecord::strain, "J"},
              {"external_work", &StepRecord::external, "J"},
              {"tip_deflection", &StepRecord::tip_uy, "m"}};
  PetscFunctionBeginUser;
  for (const auto& c : cols) {
    const auto v = column(res_.steps, c.f);
    PetscCall(out.writeReplicated(std::string("/steps/") + c.name, v.data(), {(ull)n}, c.units));
  }
  for (const auto& [name, f] : {std::make_pair("newton_iterations", &StepRecord::newton),
                                std::make_pair("rejected", &StepRecord::rejected),
                                std::make_pair("converged", &StepRecord::converged)}) {
    const auto v = column(res_.steps, f);
    PetscCall(out.writeReplicated(std::string("/steps/") + name, v.data(), {(ull)n}, ""));
  }
  double wall = 0, cpu = 0;
  for (size_t i = 1; i < n; ++i) wall += res_.steps[i].total, cpu += res_.steps[i].cpu;
  PetscCall(out.writeAttribute("/", "steps", (long long)(n - 1)));
  PetscCall(out.writeAttribute("/", "dt", opt_.dt));
  PetscCall(out.writeAttribute("/", "rate_hz", cpu > 0 ? (n - 1) / cpu : 0.0)); // steps per CPU second
  PetscCall(out.writeAttribute("/", "rate_hz_wall", wall > 0 ? (n - 1) / wall : 0.0));
  PetscCall(out.writeAttribute("/", "tip_deflection", res_.steps.back().tip_uy));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeProbe(suite::H5Output& out) const {
  const auto& pr = res_.probe;
  const ull ns = pr.sync_time.size(), nh = pr.haptic_time.size();
  PetscFunctionBeginUser;
  PetscCall(out.createGroup("/probe"));
  PetscCall(out.writeAttribute("/probe", "node", (long long)pr.node));
  PetscCall(out.writeAttribute("/probe", "stiffness", opt_.probe_stiffness));
  PetscCall(out.writeAttribute("/probe", "haptic_rate", opt_.haptic_rate));
  PetscCall(out.writeAttribute("/probe", "haptic_ticks", pr.ticks));
  PetscCall(out.writeAttribute("/probe", "haptic_tick_cpu_seconds", pr.tick_seconds));
  PetscCall(out.writeAttribute("/probe", "compliance_cpu_seconds", pr.compliance_seconds));
  PetscCall(out.writeReplicated("/probe/sync_time", pr.sync_time.data(), {ns}, "s"));
  PetscCall(out.writeReplicated("/probe/force_full", pr.force_full.data(), {ns}, "N"));
  // force_predicted[i]: the local model's force at sync_time[i+1], made at sync_time[i].
  PetscCall(out.writeReplicated("/probe/force_predicted", pr.force_predicted.data(), {ns}, "N"));
  PetscCall(out.writeReplicated("/probe/compliance_yy", pr.compliance_yy.data(), {ns}, "m/N"));
  PetscCall(out.writeReplicated("/probe/haptic_time", pr.haptic_time.data(), {nh}, "s"));
  PetscCall(out.writeReplicated("/probe/haptic_force", pr.haptic_force.data(), {nh}, "N"));
  PetscFunctionReturn(0);
}

// Snapshots /snapshots/NNNNNN/u and the steps of the XDMF series over them (or over /final/u alone).
PetscErrorCode FemdynRun::writeSnapshots(suite::H5Output& out,
                                         std::vector<suite::XdmfTetStep>* xsteps) const {
  const ull nn = (ull)mesh_.numNodes();
  PetscFunctionBeginUser;
  for (size_t k = 0; k < res_.snapshots.size(); ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "/snapshots/%06zu/u", k);
    PetscCall(out.writeReplicated(name, res_.snapshots[k].second.data(), {nn, 3}, "m"));
    xsteps->push_back({res_.snapshots[k].first, {{"displacement", name, 3}}});
  }
  if (xsteps->empty())
    xsteps->push_back({res_.steps.empty() ? 0.0 : res_.steps.back().time, {{"displacement", "/final/u", 3}}});
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeOutput() const {
  suite::H5Output out;
  PetscFunctionBeginUser;
  PetscCall(out.open(ctx_.comm(), opt_.output));
  PetscCall(out.writeProvenance(ctx_));
  PetscCall(writeRunAttributes(out));
  PetscCall(writeOrdering(out));
  PetscCall(writeMesh(out));
  if (opt_.is_static)
    PetscCall(writeStatic(out));
  else if (!res_.steps.empty())
    PetscCall(writeSteps(out));
  if (!res_.probe.sync_time.empty()) PetscCall(writeProbe(out));
  std::vector<suite::XdmfTetStep> xsteps;
  PetscCall(writeSnapshots(out, &xsteps));
  PetscCall(out.commit(&ctx_));
  suite::XdmfTetMesh xm{"/mesh/coordinates", "/mesh/tets", (ull)mesh_.numNodes(), (ull)mesh_.numElems()};
  PetscCall(suite::writeXdmfTetSeries(ctx_.comm(), opt_.output + ".xmf", opt_.output, xm, xsteps));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
