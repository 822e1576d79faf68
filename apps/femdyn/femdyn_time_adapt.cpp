// femdyn -dt_adapt: the time step from the Zienkiewicz & Xie (1991) local error estimate (fem/step_control.hpp)
// so that the time discretisation's share of -target_error is met over t_final = -steps x -dt (-dt: the first
// try). Each step is tried with the controller's dt; a try whose estimate exceeds the tolerance is rejected,
// the state (u, v, a, the law of -material auto) restored and the step redone with a smaller dt.
//
// One user target E: with -material auto the budget is split, E/2 for the law (the policy's target) and E/2
// for the time steps; without it the time steps get E. Both bound the same measure, max_t |tip(t) -
// tip_ref(t)| / max_t |tip_ref(t)| against the nonlinear law at a fine fixed step, so their sum is <= E.
//
// Refactorisations: the linear law's K_eff = M / (beta dt^2) + gamma / (beta dt) C + K0 depends on dt and is
// refactorised at every change of dt (the controller keeps dt within its hold band to save them); modified
// Newton (-jacobian initial) likewise; full Newton refactorises every iteration anyway; the tangent
// predictor's factorisation is used only at the dt it was made with (after a rejection: not at all); the
// estimate's low-pass filter M + K0 / wc^2 (its own solver) at every change of dt.
//
// Output: /time_adapt/{dt, estimate, rejected} per step record (step 0 first; estimate = ||e|| / tolerance),
// /time_adapt/tries/{time, dt, estimate, accepted} per try, attributes (target_error, time_budget, counts,
// estimated_error = sum of the accepted local estimates / final displacement scale, unresolved_bound,
// target_met); one summary line.
#include "core/log.hpp"
#include "femdyn_dynamics.hpp"
#include "io/h5_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace femdyn_app {

using namespace suite::fem;

// -dt_adapt's option combinations and the split of -target_error between the law and the time steps.
PetscErrorCode FemdynRun::checkTimeAdapt() {
  MPI_Comm comm = ctx_.comm();
  auto& c = opt_.step_control;
  PetscFunctionBeginUser;
  if (!opt_.dt_adapt) PetscFunctionReturn(0);
  PetscCheck(opt_.target_set, comm, PETSC_ERR_ARG_WRONG,
             "-dt_adapt needs the accuracy target -target_error E (relative tip-displacement history error)");
  PetscCheck(!opt_.is_static, comm, PETSC_ERR_ARG_INCOMP, "-dt_adapt adapts the time step: not with -static");
  PetscCheck(!opt_.probe, comm, PETSC_ERR_ARG_INCOMP,
             "-dt_adapt is not available with -probe (the probe runs at the fixed -dt)");
  PetscCheck(!policy_.enabled() && !policy_.restartRequested(), comm, PETSC_ERR_ARG_INCOMP,
             "-dt_adapt runs are not checkpointed (the controller's state is not in the checkpoint): drop "
             "-checkpoint_dir/-restart");
  opt_.target_error = opt_.law_policy.target;
  c.target = opt_.materialAuto() ? 0.5 * opt_.target_error : opt_.target_error;
  if (opt_.materialAuto()) opt_.law_policy.target = 0.5 * opt_.target_error;
  c.t_final = opt_.steps * opt_.dt;
  if (c.dt_min <= 0) c.dt_min = 1e-6 * c.t_final;
  PetscCall(checkStepControl(comm, c, opt_.newmark.beta));
  PetscFunctionReturn(0);
}

// The displacement scale's floor: ||K0^{-1} f_ext||_M, the static response to the load (the dynamic
// response to a load applied at rest oscillates about it, up to twice it; a released load vibrates at it).
// Without it the scale would start at ||u_1|| ~ dt^2 ||a_0|| and the first steps could never be accepted.
PetscErrorCode FemdynDynamics::staticScale(double* scale) const {
  ElasticModel& m = run_.model_;
  const int n = m.numFree();
  SymCsc K0 = m.pattern();
  std::vector<double> zero(n, 0.0), f(n), u(n);
  double e;
  bool ok;
  PetscFunctionBeginUser;
  m.internalForce(zero.data(), f.data(), &K0.val, &e); // partial model: this rank's sums (the solver adds)
  PetscCall(run_.solver_->factor(K0, &ok));
  PetscCheck(
      ok, run_.ctx_.comm(), PETSC_ERR_MAT_CH_ZRPVT,
      "-dt_adapt: K0 is not positive definite (is the Dirichlet set empty?): no static displacement scale");
  PetscCall(run_.solver_->solve(run_.f_ext_.data(), u.data()));
  *scale = nm_.massNorm(u.data()); // collective: the same on every rank
  PetscFunctionReturn(0);
}

// The filtered estimate ||lowpass(e)||_M of the try of dt from the acceleration a0, the displacement scale
// max(scale_, ||u||_M) and the bound 2 ||u - lowpass(u)||_M of the modes above the cutoff (fem/step_control.hpp;
// the linear law's M and K0 for either law); mass-weighted sums over the ranks, then the max over the ranks
// (the values agree; the reduction makes the decision collective by design).
PetscErrorCode FemdynDynamics::adaptEstimate(const std::vector<double>& a0, double dt, double* est,
                                             double* scale, double* unresolved) {
  const int n = static_cast<int>(a0.size());
  const double wc = cutoffFrequency(dt, run_.opt_.step_control.t_final);
  std::vector<double> e(n), ef(n);
  PetscFunctionBeginUser;
  zienkiewiczXieError(run_.opt_.newmark.beta, dt, a0.data(), s_.a.data(), n, e.data());
  PetscCall(nm_.lowPass(run_.solver_filter_.get(), wc, e.data(), ef.data()));
  double v[3] = {nm_.massNorm(ef.data()), std::max(scale_, nm_.massNorm(s_.u.data())), 0};
  PetscCall(nm_.lowPass(run_.solver_filter_.get(), wc, s_.u.data(), ef.data()));
  for (int i = 0; i < n; ++i) ef[i] = s_.u[i] - ef[i];
  v[2] = 2 * nm_.massNorm(ef.data());
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, v, 3, MPI_DOUBLE, MPI_MAX, run_.ctx_.comm())); // same on every rank
  *est = v[0], *scale = v[1], *unresolved = v[2];
  PetscFunctionReturn(0);
}

// Of all tries: -material auto counts per law (both solvers), otherwise the steps' own count.
int FemdynDynamics::factorizations() const {
  const Results& r = run_.res_;
  return run_.opt_.materialAuto() ? r.law_factorizations[0] + r.law_factorizations[1]
                                  : r.adapt_factorizations;
}

void FemdynDynamics::recordTry(double t, double dt, double ratio, bool accepted) {
  Results& r = run_.res_;
  r.try_time.push_back(t), r.try_dt.push_back(dt), r.try_ratio.push_back(ratio);
  r.try_accepted.push_back(accepted ? 1 : 0);
}

namespace {
void addTimings(StepTimings* sum, const StepTimings& t) {
  sum->assemble += t.assemble, sum->factor += t.factor, sum->solve += t.solve;
  sum->newton_iterations += t.newton_iterations, sum->factorizations += t.factorizations;
  sum->rejected += t.rejected, sum->residual = t.residual, sum->converged = t.converged;
}

// The message of a rejected step whose next try is below -dt_min, with the error reachable at dt_min
// (estimate ~ dt^2 at the time budget's tolerance).
std::string belowMinMessage(size_t step, double t, const StepDecision& d, double h,
                            const StepControlParams& c) {
  char msg[512];
  const double q = c.dt_min / h;
  std::snprintf(
      msg, sizeof msg,
      "-dt_adapt: step %zu at t = %.6g: the estimate is %.3g x the tolerance at dt = %.3g and the next "
      "try %.3g is below -dt_min %.3g; the best reachable time error at dt_min is about %.3g (time "
      "budget %.3g): raise -target_error or lower -dt_min",
      step, t, d.ratio, h, d.dt_next, c.dt_min, c.target * d.ratio * q * q, c.target);
  return msg;
}
} // namespace

// One try of h from the state saved: the step with the run's law(s), its estimate, the decision, its record;
// an accepted try updates the scale, the next dt and the sums. -material auto: a step in another law than the
// last one starts from a projected state whose a is the other law's; its a_{n+1} - a_n is the laws'
// difference, not the time step's error: kept at its dt, not estimated (without this the controller shrinks
// dt at a switch until Newton stalls on round-off).
PetscErrorCode FemdynDynamics::tryStep(double h, const NewmarkState& saved, StepTimings* total,
                                       Fidelity* used, double* est_law, StepDecision* d, bool* below_min) {
  StepTimings one;
  double est, scale, unresolved;
  PetscFunctionBeginUser;
  *below_min = false;
  PetscCall(stepOnce(h, &one, used, est_law));
  addTimings(total, one);
  PetscCall(adaptEstimate(saved.a, h, &est, &scale, &unresolved));
  const bool switched = run_.opt_.materialAuto() && static_cast<int>(*used) != run_.res_.law.back();
  *d = switched ? control_->keep(h) : control_->decide(h, est, scale, below_min);
  recordTry(saved.t, h, d->ratio, d->accept);
  if (d->accept) {
    scale_ = scale, dt_next_ = d->dt_next, estimate_sum_ += switched ? 0.0 : est;
    unresolved_ = std::max(unresolved_, unresolved);
  }
  PetscFunctionReturn(0);
}

// Tries from dt until the controller accepts; *failed (with the message) when the next try is below dt_min.
PetscErrorCode FemdynDynamics::stepAdaptive(double dt, StepTimings* tm, Fidelity* used, double* est_law,
                                            std::string* failed) {
  Results& res = run_.res_;
  StepTimings total;
  int rejected = 0;
  PetscFunctionBeginUser;
  for (double h = dt;;) {
    const NewmarkState saved = s_;
    const Fidelity law = law_;
    StepDecision d;
    bool below_min;
    PetscCall(tryStep(h, saved, &total, used, est_law, &d, &below_min));
    if (d.accept) {
      res.adapt_dt.push_back(h), res.adapt_ratio.push_back(d.ratio), res.adapt_rejected.push_back(rejected);
      break;
    }
    s_ = saved, law_ = law;
    s_.u_tangent.clear(); // the solver holds the rejected try's factorisation
    ++rejected;
    if (below_min) {
      *failed = belowMinMessage(res.steps.size(), s_.t, d, h, run_.opt_.step_control);
      break;
    }
    h = d.dt_next;
  }
  total.rejected += rejected;
  *tm = total;
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynDynamics::logTimeAdapt() const {
  const Results& r = run_.res_;
  const auto acc = std::count(r.try_accepted.begin(), r.try_accepted.end(), 1);
  const auto rej = static_cast<long>(r.try_accepted.size()) - acc;
  double lo = HUGE_VAL, hi = 0;
  for (size_t i = 1; i < r.adapt_dt.size(); ++i)
    lo = std::min(lo, r.adapt_dt[i]), hi = std::max(hi, r.adapt_dt[i]);
  PetscFunctionBeginUser;
  PetscCall(
      suite::logInfo(run_.ctx_.comm(), run_.ctx_.quiet(),
                     "femdyn dt adapt: target %.3g (time steps %.3g%s), %ld steps accepted, %ld rejected, "
                     "dt %.3g .. %.3g, estimated time error %.3g, %d K_eff factorisations",
                     run_.opt_.target_error, run_.opt_.step_control.target,
                     run_.opt_.materialAuto() ? ", law the other half" : "", (long)acc, (long)rej,
                     acc ? lo : 0.0, hi, r.adapt_error, r.adapt_factorizations));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeTimeAdapt(suite::H5Output& out) const {
  using ull = unsigned long long;
  const char* g = "/time_adapt";
  const auto& c = opt_.step_control;
  const auto n = (ull)res_.adapt_dt.size(), m = (ull)res_.try_dt.size();
  const auto acc = (long long)std::count(res_.try_accepted.begin(), res_.try_accepted.end(), 1);
  PetscFunctionBeginUser;
  PetscCall(out.createGroup(g));
  PetscCall(out.writeReplicated("/time_adapt/dt", res_.adapt_dt.data(), {n}, "s"));
  PetscCall(out.writeReplicated("/time_adapt/estimate", res_.adapt_ratio.data(), {n}, ""));
  PetscCall(out.writeReplicated("/time_adapt/rejected", res_.adapt_rejected.data(), {n}, ""));
  PetscCall(out.createGroup("/time_adapt/tries"));
  PetscCall(out.writeReplicated("/time_adapt/tries/time", res_.try_time.data(), {m}, "s"));
  PetscCall(out.writeReplicated("/time_adapt/tries/dt", res_.try_dt.data(), {m}, "s"));
  PetscCall(out.writeReplicated("/time_adapt/tries/estimate", res_.try_ratio.data(), {m}, ""));
  PetscCall(out.writeReplicated("/time_adapt/tries/accepted", res_.try_accepted.data(), {m}, ""));
  PetscCall(out.writeAttribute(g, "target_error", opt_.target_error));
  PetscCall(out.writeAttribute(g, "time_budget", c.target));
  PetscCall(out.writeAttribute(g, "model_budget", opt_.materialAuto() ? opt_.law_policy.target : 0.0));
  PetscCall(out.writeAttribute(g, "t_final", c.t_final));
  PetscCall(out.writeAttribute(g, "steps_accepted", acc));
  PetscCall(out.writeAttribute(g, "tries_rejected", (long long)m - acc));
  PetscCall(out.writeAttribute(g, "factorizations", (long long)res_.adapt_factorizations));
  PetscCall(out.writeAttribute(g, "estimated_error", res_.adapt_error));
  PetscCall(out.writeAttribute(g, "unresolved_bound", res_.adapt_unresolved));
  PetscCall(out.writeAttribute(g, "target_met", res_.adapt_error <= c.target ? 1LL : 0LL));
  PetscCall(out.writeAttribute(g, "dt_min", c.dt_min));
  PetscCall(out.writeAttribute(g, "dt_max", c.dt_max > 0 ? c.dt_max : c.t_final));
  PetscCall(out.writeAttribute(g, "safety", c.safety));
  PetscCall(
      out.writeAttribute(g, "estimator",
                         "Zienkiewicz & Xie 1991: e = dt^2 (beta - 1/6) (a_{n+1} - a_n), low-pass "
                         "(M + K0 / wc^2)^{-1} M e with wc = (12 / (t_final dt^2))^(1/3), accepted when "
                         "||e||_M <= 0.5 time_budget scale dt / t_final (scale: max(||K0^{-1} f||_M, "
                         "max_t ||u||_M)); estimate = ||e||_M / that tolerance; unresolved_bound = max_t "
                         "2 ||u - lowpass(u)||_M / scale (the modes above wc, not controlled)"));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
