// femdyn checkpoint/restart (issue #8): the time-integration state u, v, a (free DOFs) at the end of a step,
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
constexpr int kHistoryColumns = 13;

// The tables of a checkpoint beyond u, v, a: their buffers (rows x columns, row-major) and sizes.
struct Tables {
  ull nrec = 0, nsnap = 0, nps = 0, nph = 0, ndof = 0;
  bool has_tangent = false;
  std::vector<double> hist, snaps, psync, phap;
  double dt_tangent = 0;
};

void packRecord(const StepRecord& r, double* c) {
  const double v[kHistoryColumns] = {r.time,         r.assemble,       r.factor,         r.solve,    r.total,
                                     r.cpu,          r.kinetic,        r.strain,         r.external, r.tip_uy,
                                     1.0 * r.newton, 1.0 * r.rejected, 1.0 * r.converged};
  std::copy(v, v + kHistoryColumns, c);
}

StepRecord unpackRecord(const double* c) {
  StepRecord r{};
  r.time = c[0], r.assemble = c[1], r.factor = c[2], r.solve = c[3], r.total = c[4], r.cpu = c[5];
  r.kinetic = c[6], r.strain = c[7], r.external = c[8], r.tip_uy = c[9];
  r.newton = (int)c[10], r.rejected = (int)c[11], r.converged = (int)c[12];
  return r;
}

// Step history, snapshots (time, then the full displacement) and probe tables into t.
void packTables(const Results& res, Tables* t) {
  t->nrec = res.steps.size(), t->nsnap = res.snapshots.size();
  t->hist.resize(t->nrec * kHistoryColumns), t->snaps.resize(t->nsnap * (t->ndof + 1));
  for (ull i = 0; i < t->nrec; ++i) packRecord(res.steps[i], t->hist.data() + i * kHistoryColumns);
  for (ull i = 0; i < t->nsnap; ++i) {
    t->snaps[i * (t->ndof + 1)] = res.snapshots[i].first;
    std::copy(res.snapshots[i].second.begin(), res.snapshots[i].second.end(),
              t->snaps.begin() + i * (t->ndof + 1) + 1);
  }
  const suite::fem::HapticProbeRecord& pr = res.probe;
  t->nps = pr.sync_time.size(), t->nph = pr.haptic_time.size();
  t->psync.resize(4 * t->nps), t->phap.resize(2 * t->nph);
  for (ull i = 0; i < t->nps; ++i)
    t->psync[4 * i] = pr.sync_time[i], t->psync[4 * i + 1] = pr.force_full[i],
                 t->psync[4 * i + 2] = pr.force_predicted[i], t->psync[4 * i + 3] = pr.compliance_yy[i];
  for (ull i = 0; i < t->nph; ++i)
    t->phap[2 * i] = pr.haptic_time[i], t->phap[2 * i + 1] = pr.haptic_force[i];
}

// Back into the run's history (every rank, after the broadcast).
void unpackTables(const Tables& t, Results* res) {
  suite::fem::HapticProbeRecord& pr = res->probe;
  pr.sync_time.clear(), pr.force_full.clear(), pr.force_predicted.clear(), pr.compliance_yy.clear();
  pr.haptic_time.clear(), pr.haptic_force.clear();
  for (ull i = 0; i < t.nps; ++i) {
    pr.sync_time.push_back(t.psync[4 * i]), pr.force_full.push_back(t.psync[4 * i + 1]);
    pr.force_predicted.push_back(t.psync[4 * i + 2]), pr.compliance_yy.push_back(t.psync[4 * i + 3]);
  }
  for (ull i = 0; i < t.nph; ++i)
    pr.haptic_time.push_back(t.phap[2 * i]), pr.haptic_force.push_back(t.phap[2 * i + 1]);
  pr.ticks = (long long)t.nph;
  res->steps.clear();
  for (ull i = 0; i < t.nrec; ++i) res->steps.push_back(unpackRecord(t.hist.data() + i * kHistoryColumns));
  res->snapshots.clear();
  const ull w = t.ndof + 1;
  for (ull i = 0; i < t.nsnap; ++i)
    res->snapshots.push_back(
        {t.snaps[i * w], std::vector<double>(t.snaps.begin() + i * w + 1, t.snaps.begin() + (i + 1) * w)});
}

// The checkpoint's fields: u, v, a, the tables and (tangent predictor) the last factorisation's point and dt.
// Rank 0 writes/reads the data; the others take part with empty blocks.
std::vector<suite::CheckpointField> bindFields(suite::fem::NewmarkState* s, Tables* t, bool root) {
  const ull n = s->u.size(), nc = kHistoryColumns, w = t->ndof + 1;
  std::vector<suite::CheckpointField> f;
  for (const auto& [name, vec] :
       {std::make_pair("u", &s->u), std::make_pair("v", &s->v), std::make_pair("a", &s->a)})
    f.push_back({name, {n}, {0}, {root ? n : 0}, vec->data()});
  f.push_back({"history", {t->nrec, nc}, {0, 0}, {root ? t->nrec : 0, nc}, t->hist.data()});
  if (t->nsnap > 0)
    f.push_back({"snapshots", {t->nsnap, w}, {0, 0}, {root ? t->nsnap : 0, w}, t->snaps.data()});
  if (t->has_tangent) {
    f.push_back({"u_tangent", {n}, {0}, {root ? n : 0}, s->u_tangent.data()});
    f.push_back({"dt_tangent", {1}, {0}, {root ? 1ull : 0ull}, &t->dt_tangent});
  }
  if (t->nps > 0) {
    f.push_back({"probe_sync", {t->nps, 4}, {0, 0}, {root ? t->nps : 0, 4}, t->psync.data()});
    f.push_back({"probe_haptic", {t->nph, 2}, {0, 0}, {root ? t->nph : 0, 2}, t->phap.data()});
  }
  return f;
}

// The table sizes of a checkpoint (they grow with the step), checked against this mesh.
PetscErrorCode readTableSizes(MPI_Comm comm, const std::string& path, Tables* t) {
  suite::Dims hdims, sdims, psdims, phdims;
  bool has_hist = false, has_snap = false, has_probe = false;
  suite::H5Input in;
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(in.hasObject("/fields/history", &has_hist));
  if (has_hist) PetscCall(in.datasetDims("/fields/history", &hdims));
  PetscCall(in.hasObject("/fields/snapshots", &has_snap));
  if (has_snap) PetscCall(in.datasetDims("/fields/snapshots", &sdims));
  PetscCall(in.hasObject("/fields/u_tangent", &t->has_tangent));
  PetscCall(in.hasObject("/fields/probe_sync", &has_probe));
  if (has_probe) {
    PetscCall(in.datasetDims("/fields/probe_sync", &psdims));
    PetscCall(in.datasetDims("/fields/probe_haptic", &phdims));
  }
  PetscCall(in.close());
  PetscCheck(has_hist && hdims.size() == 2 && hdims[0] >= 1 && hdims[1] == kHistoryColumns, comm,
             PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: missing or malformed /fields/history (not a femdyn checkpoint?)", path.c_str());
  PetscCheck(!has_snap || (sdims.size() == 2 && sdims[1] == t->ndof + 1), comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: /fields/snapshots does not match this mesh", path.c_str());
  PetscCheck(!has_probe || (psdims.size() == 2 && psdims[1] == 4 && phdims.size() == 2 && phdims[1] == 2),
             comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: malformed probe history", path.c_str());
  t->nrec = hdims[0], t->nsnap = has_snap ? sdims[0] : 0;
  t->nps = has_probe ? psdims[0] : 0, t->nph = has_probe ? phdims[0] : 0;
  t->hist.resize(t->nrec * kHistoryColumns), t->snaps.resize(t->nsnap * (t->ndof + 1));
  t->psync.resize(4 * t->nps), t->phap.resize(2 * t->nph);
  PetscFunctionReturn(0);
}

// Rank 0 read the state and the tables: every rank gets them.
PetscErrorCode broadcast(MPI_Comm comm, suite::fem::NewmarkState* s, Tables* t) {
  const int n = (int)s->u.size();
  PetscFunctionBeginUser;
  if (t->nps > 0) PetscCallMPI(MPI_Bcast(t->psync.data(), (int)t->psync.size(), MPI_DOUBLE, 0, comm));
  if (t->nph > 0) PetscCallMPI(MPI_Bcast(t->phap.data(), (int)t->phap.size(), MPI_DOUBLE, 0, comm));
  for (auto* vec : {&s->u, &s->v, &s->a}) PetscCallMPI(MPI_Bcast(vec->data(), n, MPI_DOUBLE, 0, comm));
  if (t->has_tangent) {
    PetscCallMPI(MPI_Bcast(s->u_tangent.data(), n, MPI_DOUBLE, 0, comm));
    PetscCallMPI(MPI_Bcast(&t->dt_tangent, 1, MPI_DOUBLE, 0, comm));
  }
  PetscCallMPI(MPI_Bcast(t->hist.data(), (int)t->hist.size(), MPI_DOUBLE, 0, comm));
  if (t->nsnap > 0) PetscCallMPI(MPI_Bcast(t->snaps.data(), (int)t->snaps.size(), MPI_DOUBLE, 0, comm));
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
  suite::CheckpointHeader h;
  h.app = "femdyn";
  h.scheme = tag;
  h.grid = {run_.mesh_.numNodes(), run_.mesh_.numElems(), run_.mesh_.order(), run_.model_.numFree()};
  return h;
}

PetscErrorCode FemdynDynamics::saveState(const std::string& path, PetscInt step, double) {
  PetscFunctionBeginUser;
  suite::CheckpointHeader h = checkpointHeader();
  h.step = step;
  h.time = s_.t;
  h.dt = run_.opt_.dt;
  Tables t;
  t.ndof = (ull)run_.model_.numDofs();
  packTables(run_.res_, &t);
  // Tangent predictor: where the last factorisation was made (and its dt), refactorised on restart.
  t.has_tangent = !s_.u_tangent.empty();
  t.dt_tangent = s_.dt_tangent;
  const auto f = bindFields(&s_, &t, run_.ctx_.rank() == 0);
  PetscCall(suite::writeCheckpoint(run_.ctx_.comm(), path, h, f));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynDynamics::checkRestart(const std::string& path, const suite::CheckpointHeader& found,
                                            ull records) const {
  MPI_Comm comm = run_.ctx_.comm();
  PetscFunctionBeginUser;
  PetscCheck(found.dt == run_.opt_.dt, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: written with -dt %.17g, this run has -dt %.17g", path.c_str(), found.dt,
             run_.opt_.dt);
  PetscCheck(found.step <= run_.opt_.steps, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: checkpoint is at step %lld, beyond -steps %d", path.c_str(), found.step,
             (int)run_.opt_.steps);
  PetscCheck((long long)records == found.step + 1, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: history has %llu records for step %lld", path.c_str(), records, found.step);
  PetscFunctionReturn(0);
}

// Header first (app, scheme, grid: a clear message for another mesh or other physics), then the table sizes,
// the data (rank 0, broadcast), the history; then the tangent the interrupted run held is refactorised (with
// the probe at its position of the last step).
PetscErrorCode FemdynDynamics::loadState(const std::string& path, PetscInt* step, double* t) {
  MPI_Comm comm = run_.ctx_.comm();
  suite::CheckpointHeader found;
  Tables tab;
  PetscFunctionBeginUser;
  PetscCall(suite::readCheckpoint(comm, path, checkpointHeader(), &found, {}));
  tab.ndof = (ull)run_.model_.numDofs();
  PetscCall(readTableSizes(comm, path, &tab));
  const ull n = (ull)run_.model_.numFree();
  s_.u.assign(n, 0.0), s_.v.assign(n, 0.0), s_.a.assign(n, 0.0);
  if (tab.has_tangent)
    s_.u_tangent.assign(n, 0.0);
  else
    s_.u_tangent.clear();
  PetscCall(suite::readCheckpoint(comm, path, checkpointHeader(), &found,
                                  bindFields(&s_, &tab, run_.ctx_.rank() == 0)));
  PetscCall(broadcast(comm, &s_, &tab));
  s_.dt_tangent = tab.dt_tangent;
  PetscCall(checkRestart(path, found, tab.nrec));
  s_.t = found.time;
  unpackTables(tab, &run_.res_);
  *step = (PetscInt)found.step;
  *t = s_.t;
  if (probe_) probe_->placeAt(s_.t);
  PetscCall(nm_.restoreTangent(s_));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
