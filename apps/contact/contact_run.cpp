// The contact app's run (see contact_run.hpp): setup, then the steps on the suite's one time loop
// (core/time_loop.hpp) through ContactStepping, the app's side of it.
#include "contact_run.hpp"

#include "core/run_summary.hpp"
#include "io/xdmf.hpp"

#include "contact_checkpoint.hpp"
#include "contact_options.hpp"
#include "contact_output.hpp"
#include "contact_size_check.hpp"

#include "contact/friction_auto.hpp"
#include "contact/mjcf.hpp"
#include "core/log.hpp"
#include "core/log_stages.hpp"

#include <cstdio>
#include "core/task_dealer.hpp"
#include "core/time_loop.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/h5_output.hpp"
#include "lcp/readers.hpp"

#include <algorithm>
#include <chrono>

namespace contact_app {

namespace {

// The contact app on the time loop: fixed dt, one Stepper::step per step, frames every -output_every steps,
// the problems of each step dumped on request, a failed step's problem dumped next to the output.
// A step whose joint projection did not converge is retried at dt / 2, dt / 4 and dt / 8.
constexpr int kJointRetries = 3;

class ContactStepping : public suite::TimeStepped {
public:
  ContactStepping(const suite::RunContext& ctx, const AppOptions& o, Model model)
      : ctx_(ctx), o_(o), bodies_(std::move(model.bodies)), stepper_(o.step),
        scheme_(checkpointScheme(o.scene.scene, o.step.friction)) {
    stepper_.setJoints(std::move(model.joints)); // checked by buildModel below
    stepper_.keepProblems(!o.dump.empty());
    if (o.step.friction == FrictionModel::Auto)
      for (const std::string& n : autoRungNames(o.step))
        rec_.auto_rungs += (rec_.auto_rungs.empty() ? "" : ",") + n;
    if (o.step.islands) {
      PetscCallAbort(ctx.comm(), suite::TaskDealer::create(ctx.comm(), &dealer_));
      stepper_.setTaskRunner(
          [this](int n, const suite::TaskSolve& solve, std::vector<std::vector<double>>* res) {
            return dealer_->deal(n, solve, res) ? std::string("dealing over ranks failed") : "";
          });
    }
  }
  // a fresh run's first frame is its step-0 snapshot
  PetscErrorCode start(PetscInt step, double t, bool restarted) override {
    if (restarted) rec_.frame(bodies_, step, t);
    return 0;
  }
  PetscErrorCode proposeDt(PetscInt, double, double* dt) override {
    *dt = o_.step.dt;
    return 0;
  }
  PetscErrorCode advance(PetscInt step, double t, double dt, suite::StepOutcome* out) override;
  PetscErrorCode saveState(const std::string& path, PetscInt step, double t) override {
    return writeContactCheckpoint(ctx_.comm(), path, scheme_, step, t, o_.step.dt, bodies_, stepper_);
  }
  PetscErrorCode loadState(const std::string& path, PetscInt* step, double* t) override {
    long long s = 0;
    PetscFunctionBeginUser;
    PetscCall(readContactCheckpoint(ctx_.comm(), path, scheme_, o_.step.dt, &bodies_, &stepper_, &s, t));
    *step = (PetscInt)s;
    PetscFunctionReturn(0);
  }
  PetscErrorCode writeSnapshot(PetscInt step, double t) override {
    rec_.frame(bodies_, step, t);
    return 0;
  }
  PetscErrorCode writeFinal(const suite::LoopSummary& sum) override;

private:
  PetscErrorCode dumpProblems(PetscInt step);
  PetscErrorCode failed(PetscInt step, const StepStats& st, suite::StepOutcome* out);
  PetscErrorCode autoSummary() const;
  PetscErrorCode phaseSummary() const;

  const suite::RunContext& ctx_;
  const AppOptions& o_;
  std::vector<Body> bodies_;
  Stepper stepper_;
  const std::string scheme_;
  Recorder rec_;
  long long dumped_ = 0;
  std::string failure_;                       // "step N: why; problem dumped to FILE"
  std::unique_ptr<suite::TaskDealer> dealer_; // -contact_islands on: the islands over ranks
};

PetscErrorCode ContactStepping::advance(PetscInt step, double t, double dt, suite::StepOutcome* out) {
  PetscFunctionBeginUser;
  if (dt != stepper_.options().dt) stepper_.setDt(dt); // a retry at half dt, or back after one
  const auto t0 = std::chrono::steady_clock::now();
  const StepStats st = stepper_.step(&bodies_);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PetscCall(dumpProblems(step + 1));
  // -friction auto: an unsolved problem once more at half dt; joints: a projection that did not converge at
  // half, a quarter and an eighth of dt (TimeLoop's retries, kJointRetries)
  const bool retry = (o_.step.friction == FrictionModel::Auto && dt == o_.step.dt) ||
                     (st.retry_smaller_dt && dt > o_.step.dt / (1 << kJointRetries) * 1.5);
  if (st.failed && retry) {
    out->status = suite::StepStatus::Retry;
    out->message = st.message;
    PetscFunctionReturn(0);
  }
  if (st.failed) {
    StepStats f = st; // a retry: say that this was one
    if (dt != o_.step.dt) f.message = "at dt " + std::to_string(dt) + " s as well: " + f.message;
    PetscCall(failed(step + 1, f, out));
    PetscFunctionReturn(0);
  }
  out->status = suite::StepStatus::Done;
  out->t_new = t + dt;
  rec_.step(st, out->t_new, mechanicalEnergy(bodies_, o_.step.gravity), wall);
  if (!stepper_.joints().empty()) rec_.jointStep(st, stepper_, bodies_);
  PetscFunctionReturn(0);
}

// -dump_problems: every problem of the step (one per splitting pass), at most -dump_max in the run.
PetscErrorCode ContactStepping::dumpProblems(PetscInt step) {
  PetscFunctionBeginUser;
  if (o_.dump.empty()) PetscFunctionReturn(0);
  const auto& ps = stepper_.lastProblems();
  for (size_t k = 0; k < ps.size() && dumped_ < o_.dump_max; ++k, ++dumped_) {
    char tag[64];
    std::snprintf(tag, sizeof tag, "_step%06d_pass%02d.h5", (int)step, (int)k + 1);
    const std::string name = o_.dump + std::string(tag);
    PetscCall(suite::lcp::writeProblemH5(ctx_.comm(), name, ps[k]));
  }
  PetscFunctionReturn(0);
}

// A failed step: the bodies are unchanged; its (last) problem is dumped next to the output (without -output:
// contact.failed_stepN.h5 in the working directory).
PetscErrorCode ContactStepping::failed(PetscInt step, const StepStats& st, suite::StepOutcome* out) {
  PetscFunctionBeginUser;
  const std::string stem = o_.output.empty() ? std::string("contact") : o_.output;
  const std::string dump = stem + ".failed_step" + std::to_string(step) + ".h5";
  std::string why = st.message;
  if (!stepper_.lastProblems().empty()) {
    PetscCall(suite::lcp::writeProblemH5(ctx_.comm(), dump, stepper_.lastProblems().back()));
    why += "problem dumped to " + dump;
  }
  failure_ = "step " + std::to_string(step) + ": " + why;
  out->status = suite::StepStatus::Failed;
  out->message = why; // TimeLoop adds "(output up to step N in FILE)"
  PetscFunctionReturn(0);
}

PetscErrorCode ContactStepping::writeFinal(const suite::LoopSummary& sum) {
  suite::LogStages stages;
  PetscFunctionBeginUser;
  PetscCall(suite::LogStages::get(&stages));
  PetscCall(PetscLogStagePush(stages.output));
  const std::string status = suite::runStatus(sum);
  if (rec_.frame_step.back() != sum.steps) rec_.frame(bodies_, sum.steps, sum.t);
  PetscCall(autoSummary());
  PetscCall(phaseSummary());
  std::vector<std::string> written;
  if (!o_.output.empty()) {
    PetscCall(
        writeContactOutput(ctx_, o_.output, o_.scene, o_.step, bodies_, rec_,
                           {status, sum.failed ? failure_ : "", (long long)o_.steps, (long long)sum.steps}));
    written = suite::outputWithSidecar(o_.output);
  }
  PetscCall(PetscLogStagePop());
  PetscCall(suite::logRunSummary(
      ctx_, status, suite::stepsText(sum) + " (" + std::to_string(bodies_.size()) + " bodies)", written));
  PetscFunctionReturn(0);
}

// -friction auto: the run summary line (the full model's time on the same run: scripts/bench/contact-friction-auto).
PetscErrorCode ContactStepping::autoSummary() const {
  PetscFunctionBeginUser;
  if (o_.step.friction != FrictionModel::Auto) PetscFunctionReturn(0);
  const std::vector<std::string> names = autoRungNames(o_.step);
  std::vector<long long> count(names.size(), 0);
  for (double r : rec_.problem_rung) count[(size_t)r] += 1;
  std::string rungs;
  for (size_t k = 0; k < names.size(); ++k)
    rungs += (k ? ", " : "") + names[k] + " " + std::to_string(count[k]);
  long long missed = 0, solves = 0;
  for (int m : rec_.target_missed) missed += m;
  for (int n : rec_.auto_solves) solves += n;
  double worst = 0.0, solve_time = 0.0, step_time = 0.0;
  for (double v : rec_.cone_violation) worst = std::max(worst, v);
  for (double t : rec_.problem_time) solve_time += t;
  for (double t : rec_.step_wall) step_time += t;
  PetscCall(
      suite::logInfo(ctx_.comm(), ctx_.quiet(),
                     "contact: friction auto (target_error %g): %zu problems (%s), %lld rung solves, %lld "
                     "missed the target; largest step cone violation %.3e; problem solves %.3f s (summed "
                     "over islands), steps %.3f s (saving against polyhedral d = 8: "
                     "scripts/bench/contact-friction-auto)",
                     o_.step.target_error, rec_.problem_rung.size(), rungs.c_str(), solves, missed, worst,
                     solve_time, step_time));
  PetscFunctionReturn(0);
}

// -contact_phase_times: each rank's wall time per step and phase (lib/contact/phase_times.hpp), rank order.
PetscErrorCode ContactStepping::phaseSummary() const {
  const suite::contact::PhaseTimes& p = stepper_.phaseTimes();
  const double n = (double)std::max(1LL, p.steps), ms = 1e3 / n;
  double steps = 0.0;
  for (double t : rec_.step_wall) steps += t;
  int rank = 0;
  PetscFunctionBeginUser;
  if (!o_.phase_times) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(ctx_.comm(), &rank));
  PetscCall(PetscSynchronizedPrintf(
      ctx_.comm(),
      "contact phase times, rank %d, ms per step over %lld steps: step %.2f = collision %.2f + match and "
      "split %.2f + dealing %.2f (own island solves %.2f, %.1f of %.1f islands; waiting and gather %.2f) + "
      "unpack %.2f + integration %.2f + rest %.2f; CPU ms per step: step %.2f, own island solves %.2f, "
      "waiting and gather %.2f, busy (step less waiting) %.2f\n",
      rank, p.steps, ms * steps, ms * p.collision, ms * p.match, ms * p.dealing, ms * p.own_solves,
      p.own_islands / n, p.islands / n, ms * (p.dealing - p.own_solves), ms * p.unpack, ms * p.integration,
      ms * (steps - p.collision - p.match - p.dealing - p.unpack - p.integration), ms * p.cpu_steps,
      ms * p.cpu_own_solves, ms * (p.cpu_dealing - p.cpu_own_solves),
      ms * (p.cpu_steps - p.cpu_dealing + p.cpu_own_solves)));
  PetscCall(PetscSynchronizedFlush(ctx_.comm(), PETSC_STDOUT));
  PetscFunctionReturn(0);
}

// A model file's settings (time step, gravity, friction) where the command line gave none, logged.
PetscErrorCode applyModelSettings(MPI_Comm comm, bool quiet, const Model& m, AppOptions* o) {
  PetscFunctionBeginUser;
  if (m.timestep > 0 && !o->given.dt) {
    o->step.dt = m.timestep;
    PetscCall(suite::logInfo(comm, quiet, "contact: time step %g from the model file", m.timestep));
  }
  if (m.has_gravity && !o->given.gravity) {
    PetscCheck(
        m.gravity.x() == 0 && m.gravity.y() == 0 && m.gravity.z() <= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
        "the model file's gravity (%g, %g, %g) is not along -z, the only direction the contact app takes",
        m.gravity.x(), m.gravity.y(), m.gravity.z());
    o->step.gravity = m.gravity;
    PetscCall(suite::logInfo(comm, quiet, "contact: gravity %g m/s^2 from the model file", -m.gravity.z()));
  }
  if (m.friction >= 0 && !o->given.mu) {
    o->step.mu = m.friction;
    PetscCall(
        suite::logInfo(comm, quiet, "contact: friction coefficient %g from the model file", m.friction));
  }
  PetscFunctionReturn(0);
}

// The scene, validated, its settings applied, and its joints accepted by the stepper (a collective error on a
// bad one).
PetscErrorCode buildModel(MPI_Comm comm, bool quiet, AppOptions* o, Model* model) {
  std::string scene_error;
  PetscFunctionBeginUser;
  try {
    *model = buildValidModel(o->scene, o->overlap_tol);
  } catch (const std::runtime_error& e) {
    scene_error = e.what();
  }
  PetscCheck(scene_error.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", scene_error.c_str());
  PetscCall(applyModelSettings(comm, quiet, *model, o));
  try {
    Stepper(o->step).setJoints(model->joints);
  } catch (const std::runtime_error& e) {
    scene_error = e.what();
  }
  PetscCheck(scene_error.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", scene_error.c_str());
  PetscFunctionReturn(0);
}

// -write_mjcf: the model with the run's time step, gravity and friction, written by rank 0 under PATH.tmp and
// renamed (every rank builds the same text, so a model MJCF cannot express fails on all of them).
PetscErrorCode writeModelFile(MPI_Comm comm, bool quiet, const AppOptions& o, Model model) {
  std::string text, error;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  model.timestep = o.step.dt, model.has_gravity = true, model.gravity = o.step.gravity;
  model.friction = o.step.mu;
  try {
    text = writeMjcf(model, o.scene.scene);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  PetscCheck(error.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "-write_mjcf: %s", error.c_str());
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int ok = 1;
  if (rank == 0) {
    const std::string tmp = o.write_mjcf + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    ok = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (f) ok = std::fclose(f) == 0 && ok;
    ok = ok && std::rename(tmp.c_str(), o.write_mjcf.c_str()) == 0;
    if (!ok) std::remove(tmp.c_str());
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, PETSC_ERR_FILE_WRITE, "-write_mjcf %s: cannot write the file", o.write_mjcf.c_str());
  PetscCall(suite::logInfo(comm, quiet, "contact: wrote the %s model (%zu bodies, %zu joints) to %s",
                           o.scene.scene.c_str(), model.bodies.size(), model.joints.size(),
                           o.write_mjcf.c_str()));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode run(suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  suite::LogStages stages;
  PetscCall(suite::LogStages::get(&stages));
  PetscCall(PetscLogStagePush(stages.setup));
  AppOptions o;
  PetscCall(readOptions(ctx.comm(), &o));
  suite::CheckpointPolicy policy;
  PetscCall(policy.setFromOptions(ctx.comm(), "contact"));
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) {
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }
  if (!o.output.empty()) PetscCall(suite::checkOutputWritable(ctx.comm(), o.output, "output"));
  const SceneSize size = sceneSize(o.scene); // known before the scene is built, except from a file
  if (size.bodies > 0) PetscCall(checkContactSizes(ctx.comm(), o, size));
  Model model;
  PetscCall(buildModel(ctx.comm(), ctx.quiet(), &o, &model));
  if (size.bodies <= 0) PetscCall(checkContactSizes(ctx.comm(), o, sceneSize(model.bodies)));
  if (!o.write_mjcf.empty()) {
    PetscCall(writeModelFile(ctx.comm(), ctx.quiet(), o, std::move(model)));
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(),
                           "contact: scene %s, %zu bodies, %zu joints, friction %s (mu %g), solver %s",
                           o.scene.scene.c_str(), model.bodies.size(), model.joints.size(),
                           frictionName(o.step.friction), o.step.mu, o.step.lcp_solver.c_str()));
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(stages.solve));
  const bool joints = !model.joints.empty();
  ContactStepping app(ctx, o, std::move(model));
  suite::TimeLoopSettings set;
  set.app = "contact";
  set.max_steps = o.steps;
  set.max_retries = o.step.friction == FrictionModel::Auto ? 1 : 0; // an unsolved problem: once at half dt
  if (joints) set.max_retries = std::max<PetscInt>(set.max_retries, kJointRetries);
  set.snapshot_every = o.output_every;
  set.eta_time = o.steps * o.step.dt;
  set.output = o.output.c_str();
  suite::TimeLoop loop(ctx, policy, set);
  const PetscErrorCode ierr = loop.run(app);
  PetscCall(PetscLogStagePop());
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

} // namespace contact_app
