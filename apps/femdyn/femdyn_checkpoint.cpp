// femdyn checkpoint/restart: the time-integration state u, v, a (free DOFs) at the end of a step,
// the time and step in the header, and the history of the run so far (per-step records, snapshots, probe
// histories), so that a restarted run continues bitwise identically and writes the same output as an
// uninterrupted one. The FEM state is replicated on all ranks: rank 0 writes the arrays, rank 0 reads them and
// broadcasts. The scheme tag holds every option that changes the dynamics (integrator, material, loads, mass,
// damping): restarting with other physics is refused with a clear message. The time loop chooses the path,
// logs the checkpoint and the restart, and prunes old files.
#include "femdyn_dynamics.hpp"

#include "io/h5_input.hpp"

#include <cstdio>

namespace femdyn_app {

namespace {
using ull = unsigned long long;
constexpr ull kHistoryColumns = std::size(kStepReals) + std::size(kStepCounts);

// The run's history as row-major tables, and the tangent predictor's dt.
struct Tables {
  std::vector<double> history, snapshots, probe_sync, probe_haptic, dt_tangent;
};

// One dataset /fields/<name> of a checkpoint: a table (rows of cols values) or a vector of len values. It is
// there when its owner's data is not empty (no owner: always); a table of another shape is `malformed`.
struct Dataset {
  const char* name;
  ull cols, len;
  std::vector<double>* data;
  const std::vector<double>* owner = nullptr;
  const char* malformed = nullptr;
  bool present = false;
};

std::vector<Dataset> datasets(suite::fem::NewmarkState* s, Tables* t, ull n, ull ndof) {
  const char* probe = "malformed probe history";
  return {
      {"u", 0, n, &s->u},
      {"v", 0, n, &s->v},
      {"a", 0, n, &s->a},
      {"history", kHistoryColumns, 0, &t->history, nullptr,
       "missing or malformed /fields/history (not a femdyn checkpoint?)"},
      {"snapshots", ndof + 1, 0, &t->snapshots, &t->snapshots, "/fields/snapshots does not match this mesh"},
      {"u_tangent", 0, n, &s->u_tangent, &s->u_tangent}, // the tangent predictor's last factorisation
      {"dt_tangent", 0, 1, &t->dt_tangent, &s->u_tangent},
      {"probe_sync", 4, 0, &t->probe_sync, &t->probe_sync, probe},
      {"probe_haptic", 2, 0, &t->probe_haptic, &t->probe_sync, probe}};
}

// Rank 0 writes/reads the data; the others take part with empty blocks.
std::vector<suite::CheckpointField> fields(const std::vector<Dataset>& list, bool root) {
  std::vector<suite::CheckpointField> f;
  for (const Dataset& d : list) {
    if (!d.present) continue;
    suite::Dims dims{d.cols ? d.data->size() / d.cols : d.data->size()};
    if (d.cols) dims.push_back(d.cols);
    suite::Dims count = dims;
    count[0] = root ? dims[0] : 0;
    f.push_back({d.name, dims, suite::Dims(dims.size(), 0), count, d.data->data()});
  }
  return f;
}

// Equal-length columns to a row-major table and back.
std::vector<double> toRows(std::initializer_list<const std::vector<double>*> cols) {
  const size_t w = cols.size(), n = (*cols.begin())->size();
  std::vector<double> t(n * w);
  size_t j = 0;
  for (const auto* c : cols) {
    for (size_t i = 0; i < n; ++i) t[i * w + j] = (*c)[i];
    ++j;
  }
  return t;
}

void fromRows(const std::vector<double>& t, std::initializer_list<std::vector<double>*> cols) {
  const size_t w = cols.size(), n = t.size() / w;
  size_t j = 0;
  for (auto* c : cols) {
    c->resize(n);
    for (size_t i = 0; i < n; ++i) (*c)[i] = t[i * w + j];
    ++j;
  }
}

// Step records, snapshots (time, then the full displacement) and probe histories as tables.
Tables tablesOf(const Results& res) {
  Tables t;
  for (const StepRecord& r : res.steps) {
    for (const auto& c : kStepReals) t.history.push_back(r.*c.field);
    for (const auto& c : kStepCounts) t.history.push_back(1.0 * (r.*c.field));
  }
  for (const auto& [time, u] : res.snapshots) {
    t.snapshots.push_back(time);
    t.snapshots.insert(t.snapshots.end(), u.begin(), u.end());
  }
  const suite::fem::HapticProbeRecord& pr = res.probe;
  t.probe_sync = toRows({&pr.sync_time, &pr.force_full, &pr.force_predicted, &pr.compliance_yy});
  t.probe_haptic = toRows({&pr.haptic_time, &pr.haptic_force});
  return t;
}

// Back into the run's history (every rank, after the broadcast).
void restoreHistory(const Tables& t, ull ndof, Results* res) {
  suite::fem::HapticProbeRecord& pr = res->probe;
  fromRows(t.probe_sync, {&pr.sync_time, &pr.force_full, &pr.force_predicted, &pr.compliance_yy});
  fromRows(t.probe_haptic, {&pr.haptic_time, &pr.haptic_force});
  pr.ticks = (long long)pr.haptic_time.size();
  res->steps.assign(t.history.size() / kHistoryColumns, StepRecord{});
  const double* c = t.history.data();
  for (StepRecord& r : res->steps) {
    for (const auto& col : kStepReals) r.*col.field = *c++;
    for (const auto& col : kStepCounts) r.*col.field = (int)*c++;
  }
  res->snapshots.clear();
  for (auto it = t.snapshots.begin(); it != t.snapshots.end(); it += ndof + 1)
    res->snapshots.push_back({*it, std::vector<double>(it + 1, it + ndof + 1)});
}

// Which datasets the checkpoint holds and their sizes (the tables grow with the step), the tables checked
// against this run (the vectors by readCheckpoint); the data zeroed to be read into.
PetscErrorCode sizeFromFile(MPI_Comm comm, const std::string& path, std::vector<Dataset>* list) {
  suite::H5Input in;
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  for (Dataset& d : *list) {
    const std::string obj = std::string("/fields/") + d.name;
    bool has = false;
    suite::Dims dims;
    PetscCall(in.hasObject(obj, &has));
    if (has && d.cols) PetscCall(in.datasetDims(obj, &dims));
    d.present = has || !d.owner || (d.owner != d.data && !d.owner->empty());
    PetscCheck(!d.present || !d.cols || (dims.size() == 2 && dims[1] == d.cols && (d.owner || dims[0] >= 1)),
               comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: %s", path.c_str(), d.malformed);
    d.data->assign(!d.present ? 0 : d.cols ? dims[0] * d.cols : d.len, 0.0);
  }
  PetscCall(in.close());
  PetscFunctionReturn(0);
}

PetscErrorCode checkRestart(MPI_Comm comm, const std::string& path, const suite::CheckpointHeader& found,
                            const Options& opt, ull records) {
  PetscFunctionBeginUser;
  PetscCheck(found.dt == opt.dt, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: written with -dt %.17g, this run has -dt %.17g", path.c_str(), found.dt, opt.dt);
  PetscCheck(found.step <= opt.steps, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: checkpoint is at step %lld, beyond -steps %d", path.c_str(), found.step,
             (int)opt.steps);
  PetscCheck((long long)records == found.step + 1, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: history has %llu records for step %lld", path.c_str(), records, found.step);
  PetscFunctionReturn(0);
}
} // namespace

suite::CheckpointHeader FemdynDynamics::checkpointHeader() const {
  const Options& o = run_.opt_;
  const auto& nm = o.newmark;
  char scheme[1024];
  std::snprintf(
      scheme, sizeof scheme,
      "%s rho_inf=%.17g beta=%.17g gamma=%.17g newton_max_it=%d jacobian=%s material=%s E=%.17g "
      "nu=%.17g density=%.17g mass=%s rayleigh=%.17g,%.17g tip_load=%.17g gravity=%.17g,%.17g,%.17g",
      o.time_scheme.c_str(), o.rho_inf, nm.beta, nm.gamma, nm.newton_max_it, o.jacobian.c_str(),
      o.material.c_str(), o.young, o.poisson, o.density, o.mass.c_str(), nm.rayleigh_mass,
      nm.rayleigh_stiffness, o.tip_load, o.gravity[0], o.gravity[1], o.gravity[2]);
  // The Newton predictor changes the iterates (not the tolerance): tagged only when not the default, so that
  // checkpoints written before the option existed still load.
  std::string tag = scheme;
  if (o.predictor != "constant") tag += " predictor=" + o.predictor;
  char lagged[128] = "";
  if (o.jacobian == "lagged")
    std::snprintf(lagged, sizeof lagged, " refresh=%.17g,%d", nm.refresh_contraction, nm.refresh_iterations);
  tag += lagged;
  if (nm.max_corrections > 0) tag += " max_corrections=" + std::to_string(nm.max_corrections);
  suite::CheckpointHeader h;
  h.app = "femdyn";
  h.scheme = tag;
  h.grid = {run_.mesh_.numNodes(), run_.mesh_.numElems(), run_.mesh_.order(), run_.model_.numFree()};
  return h;
}

PetscErrorCode FemdynDynamics::saveState(const std::string& path, PetscInt step, double) {
  PetscFunctionBeginUser;
  suite::CheckpointHeader h = checkpointHeader();
  h.step = step, h.time = s_.t, h.dt = run_.opt_.dt;
  Tables t = tablesOf(run_.res_);
  t.dt_tangent = {s_.dt_tangent};
  auto list = datasets(&s_, &t, s_.u.size(), (ull)run_.model_.numDofs());
  for (Dataset& d : list) d.present = !d.owner || !d.owner->empty();
  PetscCall(suite::writeCheckpoint(run_.ctx_.comm(), path, h, fields(list, run_.ctx_.rank() == 0)));
  PetscFunctionReturn(0);
}

// Header first (app, scheme, grid: a clear message for another mesh or other physics), then the datasets'
// sizes, the data (rank 0, broadcast), the history; then the tangent the interrupted run held is refactorised
// (with the probe at its position of the last step).
PetscErrorCode FemdynDynamics::loadState(const std::string& path, PetscInt* step, double* t) {
  MPI_Comm comm = run_.ctx_.comm();
  const ull ndof = (ull)run_.model_.numDofs();
  suite::CheckpointHeader found;
  Tables tab;
  PetscFunctionBeginUser;
  PetscCall(suite::readCheckpoint(comm, path, checkpointHeader(), &found, {}));
  auto list = datasets(&s_, &tab, (ull)run_.model_.numFree(), ndof);
  PetscCall(sizeFromFile(comm, path, &list));
  PetscCall(
      suite::readCheckpoint(comm, path, checkpointHeader(), &found, fields(list, run_.ctx_.rank() == 0)));
  for (const Dataset& d : list)
    if (!d.data->empty()) PetscCallMPI(MPI_Bcast(d.data->data(), (int)d.data->size(), MPI_DOUBLE, 0, comm));
  s_.dt_tangent = tab.dt_tangent.empty() ? 0.0 : tab.dt_tangent[0];
  PetscCall(checkRestart(comm, path, found, run_.opt_, tab.history.size() / kHistoryColumns));
  s_.t = found.time;
  restoreHistory(tab, ndof, &run_.res_);
  *step = (PetscInt)found.step;
  *t = s_.t;
  if (probe_) probe_->placeAt(s_.t);
  PetscCall(nm_.restoreTangent(s_));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
