// femdyn's time-stepped side (see femdyn_dynamics.hpp): integrator setup, the start of a fresh run, one
// Newmark step with its timings and step record, snapshots, the summary line and the final output.
#include "femdyn_dynamics.hpp"

#include "core/log.hpp"
#include "core/run_summary.hpp"
#include "io/xdmf.hpp"
#include "core/clocks.hpp"

#include <algorithm>

namespace femdyn_app {

using namespace suite::fem;

PetscErrorCode FemdynDynamics::setup() {
  FemdynRun& r = run_;
  PetscFunctionBeginUser;
  SecondOrderSystem* sys = &r.model_;
  if (r.opt_.probe) {
    HapticProbeSettings set = r.opt_.probe_set;
    set.dt = r.opt_.dt, set.dirichlet = r.opt_.dirichlet;
    PetscCall(HapticProbeObserver::create(r.ctx_, set, r.mesh_, &r.model_, r.solver_.get(), r.partial_, s_,
                                          &r.res_.probe, &probe_));
    sys = probe_->system();
  }
  const double rho = r.opt_.density;
  auto mass = r.opt_.mass == "lumped" ? r.model_.lumpedMass(rho) : r.model_.consistentMass(rho);
  if (r.opt_.materialAuto()) PetscCall(setupMaterialAuto(mass));
  PetscCall(nm_.setup(r.ctx_.comm(), sys, r.solver_.get(), std::move(mass), r.opt_.newmark, r.loadAt()));
  if (r.opt_.dt_adapt) {
    control_ = std::make_unique<StepController>(r.opt_.step_control);
    const auto& c = r.opt_.step_control; // the first try: -dt within [dt_min, dt_max]
    dt_next_ = std::clamp(r.opt_.dt, c.dt_min, c.dt_max > 0 ? c.dt_max : c.t_final);
  }
  s_.u.assign(r.model_.numFree(), 0.0);
  s_.v.assign(r.model_.numFree(), 0.0);
  PetscFunctionReturn(0);
}

// A fresh run: the initial acceleration and the record of step 0 (a restart has its history already).
PetscErrorCode FemdynDynamics::start(PetscInt, double, bool restarted) {
  PetscFunctionBeginUser;
  if (restarted) PetscFunctionReturn(0);
  if (run_.opt_.dt_adapt) PetscCall(staticScale(&scale_)); // before initialize (it factorises M)
  PetscCall(nm_.initialize(&s_));
  record(StepTimings(), 0.0, 0.0);
  if (run_.opt_.materialAuto()) recordLaw(Fidelity::cheap, 0.0, 0.0);
  if (run_.opt_.dt_adapt) {
    Results& res = run_.res_;
    res.adapt_dt.push_back(0.0), res.adapt_ratio.push_back(0.0), res.adapt_rejected.push_back(0);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynDynamics::proposeDt(PetscInt, double t, double* dt) {
  PetscFunctionBeginUser;
  *dt = run_.opt_.dt_adapt ? endingDt(t) : run_.opt_.dt;
  PetscFunctionReturn(0);
}

// -dt_adapt: the controller's next dt, except near t_final: the rest when dt reaches it, half the rest when
// dt covers more than half of it (no sliver of a last step: Newton's relative test fails on round-off at
// dt ~ 1e-4 x the step; the second half then ends on t_final exactly, t_final - t being exact there).
double FemdynDynamics::endingDt(double t) const {
  const double rest = run_.opt_.step_control.t_final - t;
  if (dt_next_ >= rest * (1 - 1e-12)) return rest;
  return dt_next_ > 0.5 * rest ? 0.5 * rest : dt_next_;
}

// One step of dt with the run's law (-material auto: the law the policy picks, redone with the nonlinear law
// above its band; otherwise the one law).
PetscErrorCode FemdynDynamics::stepOnce(double dt, StepTimings* tm, Fidelity* used, double* est) {
  PetscFunctionBeginUser;
  if (run_.opt_.materialAuto())
    PetscCall(stepMaterialAuto(dt, tm, used, est));
  else
    PetscCall(nm_.step(&s_, dt, tm));
  PetscFunctionReturn(0);
}

// One step (Newton with its own dt halvings; a step that cannot converge is an error of the job).
PetscErrorCode FemdynDynamics::advance(PetscInt, double, double dt, suite::StepOutcome* out) {
  StepTimings tm;
  PetscFunctionBeginUser;
  Fidelity used = Fidelity::cheap;
  double est = 0;
  std::string failed;
  const double ts = suite::wallSeconds(), tc = suite::threadCpuSeconds();
  if (run_.opt_.dt_adapt)
    PetscCall(stepAdaptive(dt, &tm, &used, &est, &failed));
  else
    PetscCall(stepOnce(dt, &tm, &used, &est));
  if (!failed.empty()) { // the state is the one before the step; the loop writes it and stops the job
    out->status = suite::StepStatus::Failed;
    out->message = failed;
    PetscFunctionReturn(0);
  }
  run_.res_.adapt_factorizations += tm.factorizations;
  const double dt_wall = suite::wallSeconds() - ts, dt_cpu = suite::threadCpuSeconds() - tc;
  if (run_.opt_.materialAuto()) recordLaw(used, est, dt_cpu);
  stepping_ += dt_wall;
  stepping_cpu_ += dt_cpu;
  if (!tm.converged && run_.opt_.newmark.newton_max_it > 1) ++unconverged_;
  record(tm, dt_wall, dt_cpu);
  out->status = suite::StepStatus::Done;
  out->t_new = s_.t;
  PetscFunctionReturn(0);
}

void FemdynDynamics::record(const StepTimings& tm, double total, double cpu) {
  StepRecord r{};
  r.time = s_.t;
  r.assemble = tm.assemble, r.factor = tm.factor, r.solve = tm.solve, r.total = total, r.cpu = cpu;
  // -material auto: the energies of the law this step used (recordLaw ran first)
  const auto& law = run_.res_.law;
  Newmark& nm = !law.empty() && law.back() == static_cast<int>(Fidelity::accurate) ? nm_nl_ : nm_;
  r.kinetic = nm.kineticEnergy(s_);
  r.strain = nm.strainEnergy(s_);
  double w = 0;
  if (!run_.released(s_.t))
    for (size_t i = 0; i < run_.f_ext_.size(); ++i) w += run_.f_ext_[i] * s_.u[i];
  r.external = w;
  r.newton = tm.newton_iterations, r.rejected = tm.rejected, r.converged = tm.converged ? 1 : 0;
  r.residual = tm.residual, r.factorizations = tm.factorizations;
  r.tip_uy = nodalMean(run_.model_.fullVector(s_.u), run_.tip_nodes_, 1, -1);
  run_.res_.steps.push_back(r);
}

PetscErrorCode FemdynDynamics::writeSnapshot(PetscInt, double) {
  PetscFunctionBeginUser;
  run_.res_.snapshots.push_back({s_.t, run_.model_.fullVector(s_.u)});
  PetscFunctionReturn(0);
}

// Rates over the steps of this run (a restarted run continues a history that it did not time).
PetscErrorCode FemdynDynamics::logSummary(const suite::LoopSummary& summary) const {
  const std::vector<StepRecord>& steps = run_.res_.steps;
  const int n = (int)summary.stepsTaken();
  double as = 0, fa = 0, so = 0;
  int newton = 0;
  PetscFunctionBeginUser;
  for (size_t i = 1 + summary.first_step; i < steps.size(); ++i)
    as += steps[i].assemble, fa += steps[i].factor, so += steps[i].solve, newton += steps[i].newton;
  const auto& e0 = steps.front();
  const auto& e1 = steps.back();
  const double E0 = e0.kinetic + e0.strain - e0.external, E1 = e1.kinetic + e1.strain - e1.external;
  PetscCall(suite::logInfo(
      run_.ctx_.comm(), run_.ctx_.quiet(),
      "femdyn: %d steps, %.2f Newton iterations/step, %.1f Hz cpu (%.3f ms/step: assemble %.3f, "
      "factor %.3f, solve %.3f; wall %.1f Hz), tip -u_y %.6f, energy %.6e -> %.6e%s",
      n, n ? (double)newton / n : 0.0, n && stepping_cpu_ > 0 ? n / stepping_cpu_ : 0.0,
      n ? 1e3 * stepping_cpu_ / n : 0.0, n ? 1e3 * as / n : 0.0, n ? 1e3 * fa / n : 0.0,
      n ? 1e3 * so / n : 0.0, n && stepping_ > 0 ? n / stepping_ : 0.0, e1.tip_uy, E0, E1,
      unconverged_ ? " (some steps did not converge: see /steps/converged)" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynDynamics::writeFinal(const suite::LoopSummary& summary) {
  PetscFunctionBeginUser;
  run_.res_.loop_time = summary.wall;
  run_.res_.status = suite::runStatus(summary);
  run_.res_.u_full = run_.model_.fullVector(s_.u);
  PetscCall(logSummary(summary));
  if (probe_) PetscCall(probe_->logSummary());
  if (run_.opt_.materialAuto()) PetscCall(logMaterialAuto());
  if (run_.opt_.dt_adapt) {
    run_.res_.adapt_error = estimatedError();
    run_.res_.adapt_unresolved = unresolvedBound();
    run_.res_.adapt_factorizations = factorizations();
    PetscCall(logTimeAdapt());
  }
  PetscCall(run_.writeOutput());
  PetscCall(suite::logRunSummary(run_.ctx_, run_.res_.status, suite::stepsText(summary),
                                 suite::outputWithSidecar(run_.opt_.output)));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
