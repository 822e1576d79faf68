// The Euler app's accuracy-target mode (see euler_target.hpp): its options and the runner that the
// model_choice chooser calls for every pilot and final run.
#include "euler_target.hpp"

#include "core/comma_list.hpp"
#include "core/log.hpp"
#include "core/option_value.hpp"
#include "euler/schemes.hpp"
#include "euler_run.hpp"
#include "model_choice/choice_output.hpp"
#include "io/xdmf.hpp"
#include "model_choice/chooser.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace euler_app {

namespace mc = suite::model_choice;

PetscErrorCode readTargetOptions(MPI_Comm comm, int dim, TargetOptions* t) {
  PetscBool set_e = PETSC_FALSE, set_w = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Euler accuracy-target runs", "");
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-target_error",
                         "Accuracy target: the cheapest (scheme, N) whose estimated L1 density error at "
                         "t_final is <= this (pilot runs measure the observed order)",
                         "", t->error, &t->error, &set_e));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-target_walltime",
                         "Accuracy-target run: the most accurate (scheme, N) predicted to finish within "
                         "this many seconds, pilots included",
                         "", t->walltime, &t->walltime, &set_w));
  PetscCall(suite::optionsString(PetscOptionsObject, "-target_schemes",
                                 "Accuracy-target run: the candidate schemes (comma list)", &t->schemes));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-target_pilot_n",
                              "Accuracy-target run: cells of the coarsest pilot (pilots at N, 2N, 4N; 0: 32 "
                              "in 1D, 16 in 2D/3D)",
                              "", t->pilot_n, &t->pilot_n, nullptr));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-target_max_n",
                              "Accuracy-target run: the finest candidate resolution (0: 6400 in 1D, 512 in "
                              "2D, 128 in 3D)",
                              "", t->max_n, &t->max_n, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-target_safety",
                               "Accuracy-target run: a candidate must be predicted to reach target/this", "",
                               t->safety, &t->safety, nullptr));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-target_escalations",
                              "Accuracy-target run: finer runs at most when the final estimate misses", "",
                              t->escalations, &t->escalations, nullptr));
  PetscCall(suite::optionsString(PetscOptionsObject, "-cost_model",
                                 "Accuracy-target run: HDF5 file of an earlier target run whose "
                                 "/model_choice/pilots give the cost model (default: time the pilots)",
                                 &t->cost_model));
  PetscOptionsEnd();
  PetscCheck(!set_e || t->error > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -target_error %g: must be > 0 (an L1 density error)", t->error);
  PetscCheck(!set_w || t->walltime > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -target_walltime %g: must be > 0 seconds", t->walltime);
  if (t->pilot_n == 0) t->pilot_n = dim == 1 ? 32 : 16;
  if (t->max_n == 0) t->max_n = dim == 1 ? 6400 : dim == 2 ? 512 : 128;
  PetscCheck(t->pilot_n >= 8 && t->max_n >= 4 * t->pilot_n, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -target_pilot_n %" PetscInt_FMT " / -target_max_n %" PetscInt_FMT
             ": need pilot_n >= 8 and max_n >= 4 pilot_n",
             t->pilot_n, t->max_n);
  PetscCheck(t->safety >= 1.0 && t->escalations >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -target_safety %g (>= 1) or -target_escalations %" PetscInt_FMT " (>= 0)", t->safety,
             t->escalations);
  PetscFunctionReturn(0);
}

namespace {
PetscErrorCode targetFamilies(MPI_Comm comm, const TargetOptions& t, std::vector<mc::Family>* fams) {
  PetscFunctionBeginUser;
  for (const std::string& s : suite::splitCommaList(t.schemes)) {
    PetscCheck(suite::euler::findScheme(s) != nullptr, comm, PETSC_ERR_ARG_WRONG,
               "Unknown scheme '%s' in -target_schemes: enopade6, crweno5, weno5 or muscl2", s.c_str());
    fams->push_back({s, {{"-scheme", s}, {"-time", "ssprk3"}}});
  }
  PetscCheck(!fams->empty(), comm, PETSC_ERR_ARG_WRONG, "-target_schemes: no scheme given");
  PetscFunctionReturn(0);
}

// The options of one run of family f at resolution n (pilots and timing runs: no output, no errors, no
// snapshots; timing runs: mc::kTimingSteps steps after a first one that is not timed, runCandidate).
PetscErrorCode applyRunOptions(const mc::Family& f, long long n, mc::RunKind kind, const PetscInt aspect[3],
                               int dim, mc::ScopedOptions* so) {
  const char* axes[3] = {"-nx", "-ny", "-nz"};
  PetscFunctionBeginUser;
  PetscCall(so->setAll(f.options));
  for (int d = 0; d < dim;
       ++d) { // the options' aspect ratio, at least 6 cells across (the stencil) or as given
    const long long scaled = std::llround((double)n * aspect[d] / aspect[0]);
    PetscCall(
        so->set(axes[d], std::to_string(d == 0 ? n : std::max(scaled, std::min<long long>(aspect[d], 6)))));
  }
  if (kind == mc::RunKind::final) PetscFunctionReturn(0);
  if (kind == mc::RunKind::timing) PetscCall(so->set("-max_steps", std::to_string(mc::kTimingSteps + 1)));
  PetscCall(so->unset("-output"));
  PetscCall(so->set("-error", "false"));
  PetscCall(so->set("-snapshot_every", "0"));
  PetscCall(so->set(dim == 1 ? "-spacetime_every" : "-spectrum", dim == 1 ? "0" : "false"));
  PetscFunctionReturn(0);
}
} // namespace

namespace {
// The run's own options (read once, checked like a plain run, the unused-option check included): the grid's
// aspect ratio and the output file.
PetscErrorCode probeOptions(const suite::RunContext& ctx, int dim, PetscInt aspect[3], std::string* output) {
  PetscFunctionBeginUser;
  EulerRun probe(ctx, dim);
  PetscCall(probe.readOptions());
  PetscCall(probe.setup());
  PetscCall(ctx.checkUnusedOptions());
  for (int d = 0; d < 3; ++d) aspect[d] = probe.options().n[d];
  *output = probe.options().output;
  PetscFunctionReturn(0);
}

// Every pilot and final run must reach t_final (their differences are the error estimate): options that stop a
// run early or start it from a checkpoint do not go with a target.
PetscErrorCode checkRunsComplete(MPI_Comm comm) {
  PetscFunctionBeginUser;
  for (const char* name : {"-max_steps", "-restart"}) {
    PetscBool has = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &has));
    PetscCheck(
        !has, comm, PETSC_ERR_ARG_INCOMP,
        "%s cannot be combined with -target_error / -target_walltime: every run of the choice must go from "
        "the initial state to t_final",
        name);
  }
  PetscFunctionReturn(0);
}

mc::ChooserSettings chooserSettings(const TargetOptions& t) {
  mc::ChooserSettings s;
  s.target_error = t.error;
  s.target_walltime = t.walltime;
  s.safety = t.safety;
  s.max_escalations = (int)t.escalations;
  s.n0 = t.pilot_n;
  s.n_max = t.max_n;
  return s;
}
} // namespace

namespace {
// run.solve(), with a failed run (a non-physical state: PETSC_ERR_FP; a step that failed after its retries:
// PETSC_ERR_NOT_CONVERGED; both raised collectively, so every rank gets the same code) reported in *r instead
// of ending the target run: the chooser leaves that scheme out. Any other error is raised again as it was.
PetscErrorCode solveOrFail(const suite::RunContext& ctx, EulerRun& run, mc::RunResult* r) {
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode ierr = run.solve();
  PetscCall(PetscPopErrorHandler());
  if (!ierr) PetscFunctionReturn(0);
  char* specific = nullptr;
  PetscCall(PetscErrorMessage(ierr, nullptr, &specific));
  const std::string why = specific ? specific : "";
  PetscCheck(ierr == PETSC_ERR_FP || ierr == PETSC_ERR_NOT_CONVERGED, ctx.comm(), ierr, "%s", why.c_str());
  r->failed = true;
  r->failure = why;
  PetscFunctionReturn(0);
}

// One run of the choice (the chooser's Runner): family f at resolution n in this process, its final density on
// every rank, its solve's CPU seconds (maximum over the ranks) and steps, or that it failed (solveOrFail);
// *exact_l1: a final run's -error.
PetscErrorCode runCandidate(const suite::RunContext& ctx, int dim, const PetscInt aspect[3],
                            const mc::Family& f, long long n, mc::RunKind kind, mc::RunResult* r,
                            double* exact_l1) {
  mc::ScopedOptions so;
  PetscFunctionBeginUser;
  PetscCall(applyRunOptions(f, n, kind, aspect, dim, &so));
  EulerRun run(ctx, dim);
  run.setQuiet(kind != mc::RunKind::final);
  PetscCall(run.readOptions());
  PetscCall(run.setup());
  PetscCall(solveOrFail(ctx, run, r));
  if (r->failed) {
    PetscCall(run.solveSeconds(&r->seconds));
    PetscCall(so.restore());
    PetscFunctionReturn(0);
  }
  const double t_final = run.options().t_final;
  PetscCheck(
      kind == mc::RunKind::timing || std::abs(run.finalTime() - t_final) <= 1e-12 * std::max(1.0, t_final),
      ctx.comm(), PETSC_ERR_NOT_CONVERGED,
      "accuracy-target run: the run of %s at N = %lld stopped at t = %g before t_final = %g (-max_walltime "
      "or a signal)",
      f.name.c_str(), n, run.finalTime(), t_final);
  if (kind != mc::RunKind::timing) PetscCall(run.densityField(&r->density));
  // a timing run's steady cost per step: its first step touches the work arrays first and costs as much as 2-4
  // later ones (weno5 at 1024 cells: 0.52 ms against 0.13 ms), which made weno5's 3 timed steps 2x too dear
  const bool steady = kind == mc::RunKind::timing && run.steps() > 1;
  PetscCall(run.solveSeconds(&r->seconds, steady));
  r->steps = run.steps() - (steady ? 1 : 0);
  if (kind == mc::RunKind::final) *exact_l1 = run.l1DensityError();
  PetscCall(so.restore());
  PetscFunctionReturn(0);
}

// Why a target run stopped without meeting its target, and where its last run's output went (a user then
// knows which limit to raise and that the result is there, /model_choice included).
std::string missExplanation(const mc::ModelChooser& chooser, const std::string& output) {
  const mc::ChooserSettings& s = chooser.settings();
  const mc::CandidateRow& c = chooser.chosen();
  // the finest of its family's candidates (the ladder's top may lie below n_max itself)
  const bool finest =
      std::none_of(chooser.table().begin(), chooser.table().end(),
                   [&](const mc::CandidateRow& r) { return r.family == c.family && r.n > c.n; });
  std::string why;
  if ((int)chooser.finals().size() - 1 >= s.max_escalations)
    why = "-target_escalations " + std::to_string(s.max_escalations) + " used up";
  else if (finest)
    why = "no finer candidate within -target_max_n " + std::to_string(s.n_max);
  else
    why = "no other candidate predicted to do better";
  return why + "; best reachable is about that" +
         (output.empty() ? std::string() : "; that run's output, with /model_choice, is in " + output);
}

// The summary line (with the error against the exact solution under -error), and a miss as the run's error.
PetscErrorCode reportChoice(MPI_Comm comm, const mc::ModelChooser& chooser, double target, double exact_l1,
                            const std::string& output) {
  char exact[64] = "";
  PetscFunctionBeginUser;
  if (std::isfinite(exact_l1))
    PetscCall(PetscSNPrintf(exact, sizeof exact, "; L1 error against the exact solution %.3e", exact_l1));
  const std::string wrote = output.empty() ? "; no output file (-output FILE writes one)"
                                           : "; wrote " + output + ", " + suite::xdmfPathFor(output);
  PetscCall(suite::logInfo(comm, false, "%s%s%s", chooser.summary().c_str(), exact, wrote.c_str()));
  PetscCheck(
      chooser.met(), comm, PETSC_ERR_NOT_CONVERGED,
      "-target_error %g missed: the final run's estimated error is %.3e after %zu escalations (%s): %s",
      target, chooser.finals().back().estimate, chooser.finals().size() - 1,
      chooser.label(chooser.chosen().family, chooser.chosen().n).c_str(),
      missExplanation(chooser, output).c_str());
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode runTargetEuler(const suite::RunContext& ctx, int dim, const TargetOptions& t) {
  std::vector<mc::Family> fams;
  PetscInt aspect[3] = {1, 1, 1};
  std::string output;
  mc::CostModel cost;
  double exact_l1 = NAN;
  PetscFunctionBeginUser;
  PetscCall(targetFamilies(ctx.comm(), t, &fams));
  PetscCall(checkRunsComplete(ctx.comm()));
  PetscCall(probeOptions(ctx, dim, aspect, &output));
  if (!t.cost_model.empty()) PetscCall(cost.load(ctx.comm(), t.cost_model));
  auto runner = [&](const mc::Family& f, long long n, mc::RunKind kind, mc::RunResult* r) {
    return runCandidate(ctx, dim, aspect, f, n, kind, r, &exact_l1);
  };
  mc::ModelChooser chooser(ctx.comm(), fams, chooserSettings(t), cost);
  PetscCall(chooser.run(runner));
  if (!output.empty()) PetscCall(mc::writeModelChoice(ctx.comm(), output, chooser));
  PetscCall(reportChoice(ctx.comm(), chooser, t.error, exact_l1, output));
  PetscFunctionReturn(0);
}

} // namespace euler_app
