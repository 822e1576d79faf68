// femdyn -material auto: the cheapest law that meets -target_error. Each step is taken with the linear law
// (its K_eff factorised once per dt, kept in its own solver) unless the policy (fem/law_switch.hpp) asks for
// the nonlinear law (-material_auto_law, default stvk; its own Newmark integrator and solver on the same
// state u, v, a). After each step the geometric-nonlinearity estimate (fem/nonlinearity_estimate.hpp) of
// the result gives the estimated relative error of the linear law; a linear step whose estimate exceeds
// up * target is redone with the nonlinear law (so no linear step above the band is kept), and the run goes
// back to the linear law when a nonlinear step's estimate falls below down * target (hysteresis).
//
// The error measure the target bounds (-target_error E): max_t |tip(t) - tip_nl(t)| / max_t |tip_nl(t)|, tip
// = mean -u_y over the end-face nodes, tip_nl the run with -material <the nonlinear law> at the same -dt.
// Output: /material_auto/{law (0 linear, 1 nonlinear), estimate} per step (step 0 first), attributes target,
// nonlinear_law, switches, steps and CPU seconds per law; one summary line.
#include "core/clocks.hpp"
#include "core/log.hpp"
#include "fem/nonlinearity_estimate.hpp"
#include "femdyn_dynamics.hpp"
#include "io/h5_output.hpp"

#include <algorithm>
#include <string>

namespace femdyn_app {

using namespace suite::fem;

// -target_error and -material_auto_law belong to -material auto; what it does not support is refused.
PetscErrorCode FemdynRun::checkMaterialAuto() const {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  PetscCheck(opt_.materialAuto() || opt_.dt_adapt || !opt_.target_set, comm, PETSC_ERR_ARG_INCOMP,
             "-target_error is the accuracy target of -material auto or -dt_adapt (the material is -material "
             "%s, fixed -dt)",
             opt_.material.c_str());
  if (!opt_.materialAuto()) PetscFunctionReturn(0);
  PetscCall(checkLawSwitchPolicy(comm, opt_.law_policy));
  PetscCheck(opt_.auto_law != "linear", comm, PETSC_ERR_ARG_WRONG,
             "-material_auto_law linear: the law to switch to must be nonlinear (stvk or corotational)");
  PetscCheck(!opt_.is_static, comm, PETSC_ERR_ARG_INCOMP,
             "-material auto switches laws between time steps: not with -static (use -material stvk)");
  PetscCheck(!opt_.probe, comm, PETSC_ERR_ARG_INCOMP, "-material auto is not available with -probe");
  PetscCheck(!policy_.enabled() && !policy_.restartRequested(), comm, PETSC_ERR_ARG_INCOMP,
             "-material auto runs are not checkpointed (the law history is not in the checkpoint): drop "
             "-checkpoint_dir/-restart");
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynDynamics::setupMaterialAuto(const std::vector<double>& mass) {
  FemdynRun& r = run_;
  PetscFunctionBeginUser;
  PetscCall(nm_nl_.setup(r.ctx_.comm(), &r.model_nl_, r.solver_nl_.get(), mass, r.opt_.newmark, r.loadAt()));
  law_ = Fidelity::cheap;
  PetscFunctionReturn(0);
}

// The estimated relative error of the linear law at the current displacement.
PetscErrorCode FemdynDynamics::linearLawError(double* err) const {
  NonlinearityEstimate est;
  PetscFunctionBeginUser;
  const std::vector<double> u = run_.model_.fullVector(s_.u);
  PetscCall(estimateNonlinearity(run_.ctx_.comm(), run_.model_, u.data(), &est));
  *err = suite::fem::linearLawError(est.ratio());
  PetscFunctionReturn(0);
}

void FemdynDynamics::recordLaw(Fidelity used, double estimate, double cpu) {
  Results& res = run_.res_;
  const int k = static_cast<int>(used);
  if (!res.law.empty() && res.law.back() != k) ++res.law_switches;
  res.law.push_back(k);
  res.law_estimate.push_back(estimate);
  if (res.law.size() > 1) res.law_cpu[k] += cpu, ++res.law_steps[k]; // not step 0 (the initial state)
}

// At a switch of law: u += K_eff^{-1} (f_from(u) - f_to(u)) with the linear law's factorised K_eff =
// M / (beta dt^2) + K0 (solver_ holds it: every run starts linear and the linear law never refactorises): the
// correction that makes the new law's internal force match the old one in the components that are stiff on
// the scale of dt -- mostly the axial shortening the linear law lacks, or that it would read as a
// compression -- and leaves the slow (bending) ones almost as they are (M / (beta dt^2) dominates there).
// Without it the force mismatch rings undamped in the axial modes after each switch (Newmark's trapezoidal
// rule does not damp them) and the nonlinear law's Newton needs about twice the iterations (measured on the
// cantilever at -tip_load 0.5: 8 instead of 4-5 per step). A static correction with K0 alone was tried and
// is far worse (K0 is soft in bending: the transverse part of the mismatch moves the whole beam).
PetscErrorCode FemdynDynamics::projectState(ElasticModel& from, ElasticModel& to) {
  const int n = static_cast<int>(s_.u.size());
  std::vector<double> f_from(n), f_to(n);
  double e;
  PetscFunctionBeginUser;
  from.internalForce(s_.u.data(), f_from.data(), nullptr, &e);
  to.internalForce(s_.u.data(), f_to.data(), nullptr, &e);
  for (int i = 0; i < n; ++i) f_from[i] -= f_to[i];
  if (run_.partial_)
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, f_from.data(), n, MPI_DOUBLE, MPI_SUM, run_.ctx_.comm()));
  PetscCall(run_.solver_->solve(f_from.data(), f_to.data()));
  for (int i = 0; i < n; ++i) s_.u[i] += f_to[i];
  PetscFunctionReturn(0);
}

// One step with the law the policy picked; a linear step above the band is redone with the nonlinear law.
// The law used and its estimate come back for the record (recordLaw, once the step is accepted).
PetscErrorCode FemdynDynamics::stepMaterialAuto(double dt, StepTimings* tm, Fidelity* law_used,
                                                double* estimate) {
  const LawSwitchPolicy& pol = run_.opt_.law_policy;
  double est = 0;
  PetscFunctionBeginUser;
  Fidelity used = law_;
  if (law_ == Fidelity::cheap) {
    const NewmarkState saved = s_;
    PetscCall(nm_.step(&s_, dt, tm));
    run_.res_.law_factorizations[0] += tm->factorizations;
    PetscCall(linearLawError(&est));
    if (pol.cheapRejected(est)) {
      s_ = saved;
      PetscCall(projectState(run_.model_, run_.model_nl_));
      StepTimings lin = *tm;
      PetscCall(nm_nl_.step(&s_, dt, tm));
      run_.res_.law_factorizations[1] += tm->factorizations;
      tm->assemble += lin.assemble, tm->factor += lin.factor, tm->solve += lin.solve;
      used = Fidelity::accurate;
      PetscCall(linearLawError(&est));
    }
  } else {
    PetscCall(nm_nl_.step(&s_, dt, tm));
    run_.res_.law_factorizations[1] += tm->factorizations;
    PetscCall(linearLawError(&est));
  }
  law_ = pol.next(used, est);
  if (used == Fidelity::accurate && law_ == Fidelity::cheap)
    PetscCall(projectState(run_.model_nl_, run_.model_));
  *law_used = used, *estimate = est;
  PetscFunctionReturn(0);
}

namespace {
// The law sequence as runs, e.g. "linear x12, stvk x30, linear x58" (at most 8 runs, then "...").
std::string lawRuns(const std::vector<int>& law, const std::string& nl) {
  std::string s;
  int shown = 0;
  for (size_t i = 1, j; i < law.size(); i = j) {
    for (j = i; j < law.size() && law[j] == law[i]; ++j) {
    }
    if (shown++ == 8) return s + ", ...";
    s += (s.empty() ? "" : ", ") + (law[i] ? nl : std::string("linear")) + " x" + std::to_string(j - i);
  }
  return s;
}
} // namespace

PetscErrorCode FemdynDynamics::logMaterialAuto() const {
  const Results& res = run_.res_;
  const double emax = *std::max_element(res.law_estimate.begin(), res.law_estimate.end());
  PetscFunctionBeginUser;
  PetscCall(suite::logInfo(
      run_.ctx_.comm(), run_.ctx_.quiet(),
      "femdyn material auto: target %.3g, %d switches, linear %d steps (%.3f s cpu), %s %d steps (%.3f s "
      "cpu), max estimate %.3g; laws: %s",
      run_.opt_.law_policy.target, res.law_switches, res.law_steps[0], res.law_cpu[0],
      run_.opt_.auto_law.c_str(), res.law_steps[1], res.law_cpu[1], emax,
      lawRuns(res.law, run_.opt_.auto_law).c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeMaterialAuto(suite::H5Output& out) const {
  const auto n = static_cast<unsigned long long>(res_.law.size());
  const char* g = "/material_auto";
  PetscFunctionBeginUser;
  PetscCall(out.createGroup(g));
  PetscCall(out.writeReplicated("/material_auto/law", res_.law.data(), {n}, ""));
  PetscCall(out.writeReplicated("/material_auto/estimate", res_.law_estimate.data(), {n}, ""));
  PetscCall(out.writeAttribute(g, "target", opt_.law_policy.target));
  PetscCall(out.writeAttribute(g, "switch_up", opt_.law_policy.up));
  PetscCall(out.writeAttribute(g, "switch_down", opt_.law_policy.down));
  PetscCall(out.writeAttribute(g, "nonlinear_law", opt_.auto_law));
  PetscCall(out.writeAttribute(g, "law_codes", "0 linear, 1 nonlinear_law"));
  PetscCall(out.writeAttribute(g, "error_measure",
                               "max_t |tip(t) - tip_nl(t)| / max_t |tip_nl(t)|, tip = mean -u_y of the end "
                               "face, tip_nl: -material nonlinear_law at the same dt"));
  PetscCall(out.writeAttribute(g, "switches", res_.law_switches));
  PetscCall(out.writeAttribute(g, "steps_linear", res_.law_steps[0]));
  PetscCall(out.writeAttribute(g, "steps_nonlinear", res_.law_steps[1]));
  PetscCall(out.writeAttribute(g, "cpu_seconds_linear", res_.law_cpu[0]));
  PetscCall(out.writeAttribute(g, "cpu_seconds_nonlinear", res_.law_cpu[1]));
  PetscCall(out.writeAttribute(g, "factorizations_linear", res_.law_factorizations[0]));
  PetscCall(out.writeAttribute(g, "factorizations_nonlinear", res_.law_factorizations[1]));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
