// femdyn checkpoint/restart (issue #8): the time-integration state u, v, a (free DOFs) at the end of a step,
// the time and step in the header, and the history of the run so far (per-step records and snapshots), so
// that a restarted run continues bitwise identically and writes the same output as an uninterrupted one.
// The FEM state is replicated on all ranks: rank 0 writes the arrays, rank 0 reads them and broadcasts.
// The scheme tag holds every option that changes the dynamics (integrator, material, loads, mass, damping):
// restarting with other physics is refused with a clear message.
#include "femdyn_run.hpp"

#include "core/log.hpp"
#include "io/h5_input.hpp"

#include <cstdio>

namespace femdyn_app {

namespace {
constexpr int kHistoryColumns = 13;

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
} // namespace

suite::CheckpointHeader FemdynRun::checkpointHeader() const {
  const auto& nm = opt_.newmark;
  char scheme[1024];
  std::snprintf(
      scheme, sizeof scheme,
      "%s rho_inf=%.17g beta=%.17g gamma=%.17g newton_max_it=%d jacobian=%s material=%s E=%.17g "
      "nu=%.17g density=%.17g mass=%s rayleigh=%.17g,%.17g tip_load=%.17g gravity=%.17g,%.17g,%.17g",
      opt_.time_scheme.c_str(), opt_.rho_inf, nm.beta, nm.gamma, nm.newton_max_it, opt_.jacobian.c_str(),
      opt_.material.c_str(), opt_.young, opt_.poisson, opt_.density, opt_.mass.c_str(), nm.rayleigh_mass,
      nm.rayleigh_stiffness, opt_.tip_load, opt_.gravity[0], opt_.gravity[1], opt_.gravity[2]);
  // The Newton predictor changes the iterates (not the tolerance): tagged only when not the default, so that
  // checkpoints written before the option existed still load.
  std::string tag = scheme;
  if (opt_.predictor != "constant") tag += " predictor=" + opt_.predictor;
  suite::CheckpointHeader h;
  h.app = "femdyn";
  h.scheme = tag;
  h.grid = {mesh_.numNodes(), mesh_.numElems(), mesh_.order(), model_.numFree()};
  return h;
}

PetscErrorCode FemdynRun::writeCheckpointAt(const suite::fem::NewmarkState& s, long long step) {
  PetscFunctionBeginUser;
  using ull = unsigned long long;
  const bool root = ctx_.rank() == 0;
  suite::CheckpointHeader h = checkpointHeader();
  h.step = step;
  h.time = s.t;
  h.dt = opt_.dt;
  const ull n = s.u.size(), nrec = res_.steps.size(), nsnap = res_.snapshots.size();
  const ull ndof = (ull)model_.numDofs();
  std::vector<double> hist(nrec * kHistoryColumns), snaps(nsnap * (ndof + 1));
  for (ull i = 0; i < nrec; ++i) packRecord(res_.steps[i], hist.data() + i * kHistoryColumns);
  for (ull i = 0; i < nsnap; ++i) {
    snaps[i * (ndof + 1)] = res_.snapshots[i].first;
    std::copy(res_.snapshots[i].second.begin(), res_.snapshots[i].second.end(),
              snaps.begin() + i * (ndof + 1) + 1);
  }
  std::vector<suite::CheckpointField> f;
  for (const auto& [name, vec] :
       {std::make_pair("u", &s.u), std::make_pair("v", &s.v), std::make_pair("a", &s.a)})
    f.push_back({name, {n}, {0}, {root ? n : 0}, const_cast<double*>(vec->data())});
  f.push_back({"history",
               {nrec, (ull)kHistoryColumns},
               {0, 0},
               {root ? nrec : 0, (ull)kHistoryColumns},
               hist.data()});
  if (nsnap > 0)
    f.push_back({"snapshots", {nsnap, ndof + 1}, {0, 0}, {root ? nsnap : 0, ndof + 1}, snaps.data()});
  // Tangent predictor: where the last factorisation was made (and its dt), refactorised on restart.
  double dt_tangent = s.dt_tangent;
  if (!s.u_tangent.empty()) {
    f.push_back({"u_tangent", {n}, {0}, {root ? n : 0}, const_cast<double*>(s.u_tangent.data())});
    f.push_back({"dt_tangent", {1}, {0}, {root ? 1ull : 0ull}, &dt_tangent});
  }
  // Haptic probe history (sync records and haptic ticks), so that a restarted run's /probe is complete.
  const auto& pr = res_.probe;
  const ull nps = pr.sync_time.size(), nph = pr.haptic_time.size();
  std::vector<double> psync(4 * nps), phap(2 * nph);
  for (ull i = 0; i < nps; ++i)
    psync[4 * i] = pr.sync_time[i], psync[4 * i + 1] = pr.force_full[i],
              psync[4 * i + 2] = pr.force_predicted[i], psync[4 * i + 3] = pr.compliance_yy[i];
  for (ull i = 0; i < nph; ++i) phap[2 * i] = pr.haptic_time[i], phap[2 * i + 1] = pr.haptic_force[i];
  if (nps > 0) {
    f.push_back({"probe_sync", {nps, 4}, {0, 0}, {root ? nps : 0, 4}, psync.data()});
    f.push_back({"probe_haptic", {nph, 2}, {0, 0}, {root ? nph : 0, 2}, phap.data()});
  }
  const std::string path = policy_.pathForStep(step);
  PetscCall(suite::writeCheckpoint(ctx_.comm(), path, h, f));
  PetscCall(policy_.written(step));
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(), "femdyn: checkpoint %s (step %lld, t = %.17g)",
                           path.c_str(), step, s.t));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::readRestart(suite::fem::NewmarkState* s, long long* step) {
  PetscFunctionBeginUser;
  using ull = unsigned long long;
  MPI_Comm comm = ctx_.comm();
  const bool root = ctx_.rank() == 0;
  std::string path;
  PetscCall(policy_.restartPath(&path));
  // Header first (app, scheme, grid: a clear message for another mesh or other physics), then the table
  // sizes (they grow with the step): history rows and snapshot count.
  suite::CheckpointHeader found;
  PetscCall(suite::readCheckpoint(comm, path, checkpointHeader(), &found, {}));
  suite::Dims hdims, sdims;
  bool has_hist = false, has_snap = false, has_probe = false, has_tangent = false;
  suite::Dims psdims, phdims;
  {
    suite::H5Input in;
    PetscCall(in.open(comm, path));
    PetscCall(in.hasObject("/fields/history", &has_hist));
    if (has_hist) PetscCall(in.datasetDims("/fields/history", &hdims));
    PetscCall(in.hasObject("/fields/snapshots", &has_snap));
    if (has_snap) PetscCall(in.datasetDims("/fields/snapshots", &sdims));
    PetscCall(in.hasObject("/fields/u_tangent", &has_tangent));
    PetscCall(in.hasObject("/fields/probe_sync", &has_probe));
    if (has_probe) {
      PetscCall(in.datasetDims("/fields/probe_sync", &psdims));
      PetscCall(in.datasetDims("/fields/probe_haptic", &phdims));
    }
    PetscCall(in.close());
  }
  const ull n = (ull)model_.numFree(), ndof = (ull)model_.numDofs();
  PetscCheck(has_hist && hdims.size() == 2 && hdims[0] >= 1 && hdims[1] == kHistoryColumns, comm,
             PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: missing or malformed /fields/history (not a femdyn checkpoint?)", path.c_str());
  PetscCheck(!has_snap || (sdims.size() == 2 && sdims[1] == ndof + 1), comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: /fields/snapshots does not match this mesh", path.c_str());
  PetscCheck(!has_probe || (psdims.size() == 2 && psdims[1] == 4 && phdims.size() == 2 && phdims[1] == 2),
             comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: malformed probe history", path.c_str());
  const ull nrec = hdims[0], nsnap = has_snap ? sdims[0] : 0;
  const ull nps = has_probe ? psdims[0] : 0, nph = has_probe ? phdims[0] : 0;
  std::vector<double> psync(4 * nps), phap(2 * nph);
  s->u.assign(n, 0.0), s->v.assign(n, 0.0), s->a.assign(n, 0.0);
  std::vector<double> hist(nrec * kHistoryColumns), snaps(nsnap * (ndof + 1));
  std::vector<suite::CheckpointField> f;
  for (const auto& [name, vec] :
       {std::make_pair("u", &s->u), std::make_pair("v", &s->v), std::make_pair("a", &s->a)})
    f.push_back({name, {n}, {0}, {root ? n : 0}, vec->data()});
  f.push_back({"history",
               {nrec, (ull)kHistoryColumns},
               {0, 0},
               {root ? nrec : 0, (ull)kHistoryColumns},
               hist.data()});
  if (nsnap > 0)
    f.push_back({"snapshots", {nsnap, ndof + 1}, {0, 0}, {root ? nsnap : 0, ndof + 1}, snaps.data()});
  double dt_tangent = 0;
  if (has_tangent) {
    s->u_tangent.assign(n, 0.0);
    f.push_back({"u_tangent", {n}, {0}, {root ? n : 0}, s->u_tangent.data()});
    f.push_back({"dt_tangent", {1}, {0}, {root ? 1ull : 0ull}, &dt_tangent});
  } else {
    s->u_tangent.clear();
  }
  if (has_probe) {
    f.push_back({"probe_sync", {nps, 4}, {0, 0}, {root ? nps : 0, 4}, psync.data()});
    f.push_back({"probe_haptic", {nph, 2}, {0, 0}, {root ? nph : 0, 2}, phap.data()});
  }
  PetscCall(suite::readCheckpoint(comm, path, checkpointHeader(), &found, f));
  if (nps > 0) PetscCallMPI(MPI_Bcast(psync.data(), (int)psync.size(), MPI_DOUBLE, 0, comm));
  if (nph > 0) PetscCallMPI(MPI_Bcast(phap.data(), (int)phap.size(), MPI_DOUBLE, 0, comm));
  auto& pr = res_.probe;
  pr.sync_time.clear(), pr.force_full.clear(), pr.force_predicted.clear(), pr.compliance_yy.clear();
  pr.haptic_time.clear(), pr.haptic_force.clear();
  for (ull i = 0; i < nps; ++i) {
    pr.sync_time.push_back(psync[4 * i]), pr.force_full.push_back(psync[4 * i + 1]);
    pr.force_predicted.push_back(psync[4 * i + 2]), pr.compliance_yy.push_back(psync[4 * i + 3]);
  }
  for (ull i = 0; i < nph; ++i)
    pr.haptic_time.push_back(phap[2 * i]), pr.haptic_force.push_back(phap[2 * i + 1]);
  pr.ticks = (long long)nph;
  for (auto* vec : {&s->u, &s->v, &s->a}) PetscCallMPI(MPI_Bcast(vec->data(), (int)n, MPI_DOUBLE, 0, comm));
  if (has_tangent) {
    PetscCallMPI(MPI_Bcast(s->u_tangent.data(), (int)n, MPI_DOUBLE, 0, comm));
    PetscCallMPI(MPI_Bcast(&dt_tangent, 1, MPI_DOUBLE, 0, comm));
  }
  s->dt_tangent = dt_tangent;
  PetscCallMPI(MPI_Bcast(hist.data(), (int)hist.size(), MPI_DOUBLE, 0, comm));
  if (nsnap > 0) PetscCallMPI(MPI_Bcast(snaps.data(), (int)snaps.size(), MPI_DOUBLE, 0, comm));
  PetscCheck(found.dt == opt_.dt, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: written with -dt %.17g, this run has -dt %.17g", path.c_str(), found.dt, opt_.dt);
  PetscCheck(found.step <= opt_.steps, comm, PETSC_ERR_ARG_INCOMP,
             "restart %s: checkpoint is at step %lld, beyond -steps %d", path.c_str(), found.step,
             (int)opt_.steps);
  PetscCheck((long long)nrec == found.step + 1, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: history has %llu records for step %lld", path.c_str(), nrec, found.step);
  s->t = found.time;
  *step = found.step;
  res_.steps.clear();
  for (ull i = 0; i < nrec; ++i) res_.steps.push_back(unpackRecord(hist.data() + i * kHistoryColumns));
  res_.snapshots.clear();
  for (ull i = 0; i < nsnap; ++i)
    res_.snapshots.push_back(
        {snaps[i * (ndof + 1)],
         std::vector<double>(snaps.begin() + i * (ndof + 1) + 1, snaps.begin() + (i + 1) * (ndof + 1))});
  PetscCall(suite::logInfo(comm, ctx_.quiet(), "femdyn: restarted from %s at step %lld (t = %.17g)",
                           path.c_str(), found.step, found.time));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
