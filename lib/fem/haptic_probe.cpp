// The haptic probe observer (see haptic_probe.hpp): probe node, target height, the synchronisation
// after each FEM step (full-model force, compliance solves, local-model haptic ticks) and its summary line.
#include "fem/haptic_probe.hpp"

#include "core/log.hpp"
#include "core/clocks.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace suite::fem {

namespace {
// The node nearest to -probe_point (default: top of the free end, middle of z); it must not be fixed in y.
PetscErrorCode findProbeNode(MPI_Comm comm, const HapticProbeSettings& opt, const TetMesh& mesh,
                             const ElasticModel& model, int* node) {
  PetscFunctionBeginUser;
  std::array<double, 3> p = {opt.point[0], opt.point[1], opt.point[2]};
  if (p[0] > 1e299) { // default: top of the free end, middle of z
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& x : mesh.nodes)
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], x[i]), hi[i] = std::max(hi[i], x[i]);
    p = {hi[0], hi[1], 0.5 * (lo[2] + hi[2])};
  }
  double best = 1e300;
  *node = -1;
  for (int v = 0; v < mesh.numNodes(); ++v) {
    const auto& x = mesh.nodes[v];
    const double d =
        (x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]);
    if (d < best) best = d, *node = v;
  }
  PetscCheck(*node >= 0 && model.eq()[3 * *node + 1] >= 0, comm, PETSC_ERR_ARG_WRONG,
             "-probe_point: the nearest node %d is fixed by -dirichlet %s", *node, opt.dirichlet.c_str());
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode HapticProbeObserver::create(const RunContext& ctx, const HapticProbeSettings& opt,
                                           const TetMesh& mesh, ElasticModel* model, LinearSolver* solver,
                                           bool partial, const NewmarkState& state, HapticProbeRecord* record,
                                           std::unique_ptr<HapticProbeObserver>* out) {
  PetscFunctionBeginUser;
  PetscCall(findProbeNode(ctx.comm(), opt, mesh, *model, &record->node));
  out->reset(new HapticProbeObserver(ctx, opt, mesh, *model, solver, state, record));
  HapticProbeObserver& o = **out;
  for (int c = 0; c < 3; ++c) o.dofs_[c] = model->eq()[3 * record->node + c];
  // Distributed assembly: only rank 0 adds the penalty to the partial sums.
  o.probe_ = std::make_unique<ProbeSystem>(model, o.dofs_[1], mesh.nodes[record->node][1], opt.stiffness,
                                           !partial || ctx.rank() == 0);
  PetscFunctionReturn(0);
}

double HapticProbeObserver::height(double t) const {
  // Relative to the node's initial height: down at -probe_speed until -probe_depth, then it holds.
  return mesh_.nodes[rec_->node][1] + -std::min(set_.speed * t, set_.depth);
}

PetscErrorCode HapticProbeObserver::beforeStep(PetscInt, double t, double dt) {
  PetscFunctionBeginUser;
  placeAt(t + dt);
  PetscFunctionReturn(0);
}

// The compliance of the probe node along y, e_y^T K_eff^{-1} e_y, from the current factorisation: one solve
// (the local model uses the yy entry only).
PetscErrorCode HapticProbeObserver::complianceYY(double* c_yy) const {
  PetscFunctionBeginUser;
  std::vector<double> e(model_.numFree(), 0.0), x(model_.numFree());
  e[dofs_[1]] = 1.0; // the probe node is free along y (findProbeNode)
  PetscCall(solver_->solve(e.data(), x.data()));
  *c_yy = x[dofs_[1]];
  PetscFunctionReturn(0);
}

// The haptic ticks at -haptic_rate up to the next synchronisation time (at least one per FEM step).
double HapticProbeObserver::hapticTicks(const HapticLocalModel& hm) {
  const double h = 1.0 / set_.haptic_rate;
  const int m = std::max(1, (int)std::lround(set_.dt / h));
  const double tt0 = threadCpuSeconds();
  double fh = 0;
  for (int j = 1; j <= m; ++j) {
    const double t = s_.t + j * (set_.dt / m);
    fh = hm.force(t, height(t));
    rec_->haptic_time.push_back(t);
    rec_->haptic_force.push_back(fh);
  }
  rec_->tick_seconds += threadCpuSeconds() - tt0;
  rec_->ticks += m;
  return fh;
}

// Synchronisation: the full-model probe force, then the local model for the ticks up to the next step (they
// would run concurrently with it), with the compliance of the probe node from the current factorisation.
PetscErrorCode HapticProbeObserver::afterStep(PetscInt, double, double) {
  PetscFunctionBeginUser;
  const double f_full = probe_->force(s_.u.data());
  rec_->sync_time.push_back(s_.t);
  rec_->force_full.push_back(f_full);
  const double tc0 = threadCpuSeconds();
  double c_yy;
  PetscCall(complianceYY(&c_yy));
  rec_->compliance_seconds += threadCpuSeconds() - tc0;
  rec_->compliance_yy.push_back(c_yy);
  HapticLocalModel hm;
  hm.t = s_.t, hm.y = probe_->position(s_.u.data()), hm.v = s_.v[dofs_[1]], hm.f = f_full, hm.c = c_yy;
  hm.k = set_.stiffness;
  rec_->force_predicted.push_back(hapticTicks(hm)); // the local model's force at the next synchronisation
  PetscFunctionReturn(0);
}

PetscErrorCode HapticProbeObserver::logSummary() const {
  const HapticProbeRecord& pr = *rec_;
  PetscFunctionBeginUser;
  if (pr.sync_time.size() <= 1) PetscFunctionReturn(0);
  double err = 0, fmax = 0;
  for (size_t i = 1; i < pr.sync_time.size(); ++i) {
    err = std::max(err, std::abs(pr.force_predicted[i - 1] - pr.force_full[i]));
    fmax = std::max(fmax, std::abs(pr.force_full[i]));
  }
  PetscCall(logInfo(ctx_.comm(), ctx_.quiet(),
                    "femdyn probe: node %d, final force %.6g; haptic %lld ticks at %.0f Hz (model rate "
                    "%.3g Hz cpu, %.3f ms/step for the compliance solves); local model vs full model at "
                    "the synchronisations: max |df| %.3e (%.3e of max force %.4g)",
                    pr.node, pr.force_full.back(), pr.ticks, set_.haptic_rate,
                    pr.tick_seconds > 0 ? pr.ticks / pr.tick_seconds : 0.0,
                    1e3 * pr.compliance_seconds / pr.sync_time.size(), err, fmax > 0 ? err / fmax : 0.0,
                    fmax));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
