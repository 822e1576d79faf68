// The contact app's run (see contact_run.hpp).
#include "contact_run.hpp"

#include "contact_checkpoint.hpp"
#include "contact_options.hpp"
#include "contact_output.hpp"

#include "core/log.hpp"
#include "core/log_stages.hpp"
#include "core/progress.hpp"
#include "core/run_context.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/h5_output.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace contact_app {

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
  PetscCall(suite::checkOutputWritable(ctx.comm(), o.output, "output"));
  std::vector<Body> bodies;
  std::string scene_error;
  try {
    bodies = buildScene(o.scene);
    validateScene(bodies, o.overlap_tol);
    // every pair the scene can produce must have a contact generator
    for (size_t i = 0; i < bodies.size(); ++i)
      for (size_t j = i + 1; j < bodies.size(); ++j) {
        std::vector<Contact> tmp;
        collide(bodies, (int)i, (int)j, -INFINITY, &tmp);
      }
  } catch (const SceneError& e) {
    scene_error = e.what();
  }
  PetscCheck(scene_error.empty(), ctx.comm(), PETSC_ERR_ARG_OUTOFRANGE, "%s", scene_error.c_str());
  PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(),
                           "contact: scene %s, %zu bodies, friction %s (mu %g), solver %s",
                           o.scene.scene.c_str(), bodies.size(), frictionName(o.step.friction), o.step.mu,
                           o.step.lcp_solver.c_str()));
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(stages.solve));
  Stepper stepper(o.step);
  stepper.keepProblems(o.dump[0] != 0);
  const std::string scheme = checkpointScheme(o.scene.scene, o.step.friction);
  long long s0 = 0;
  double t = 0.0;
  if (policy.restartRequested()) {
    std::string path;
    PetscCall(policy.restartPath(&path));
    PetscCall(readContactCheckpoint(ctx.comm(), path, scheme, o.step.dt, &bodies, &stepper, &s0, &t));
    PetscCheck(s0 <= o.steps, ctx.comm(), PETSC_ERR_ARG_OUTOFRANGE,
               "restart %s: checkpoint at step %lld is past -steps %d", path.c_str(), s0, (int)o.steps);
    PetscCall(suite::logInfo(ctx.comm(), ctx.quiet(), "restarted from %s at step %lld (t = %g)", path.c_str(),
                             s0, t));
  }
  Recorder rec;
  OutputInfo info{o.scene.scene,
                  frictionName(o.step.friction),
                  o.step.lcp_solver,
                  "completed",
                  "",
                  o.step.dt,
                  o.step.mu,
                  o.scene.theta_deg,
                  (long long)o.steps,
                  0};
  info.simplifications = simplifications(o, bodies);
  rec.frame(bodies, s0, t);
  suite::Progress progress(ctx.comm(), ctx.quiet(), ctx.progressInterval(), o.steps * o.step.dt);
  long long dumped = 0;
  std::string failure;
  PetscInt s = (PetscInt)s0;
  for (; s < o.steps; ++s) {
    bool stop = false;
    PetscCall(ctx.stopRequested(&stop));
    if (stop) {
      if (policy.enabled()) {
        PetscCall(writeContactCheckpoint(ctx.comm(), policy.pathForStep(s), scheme, s, t, o.step.dt, bodies,
                                         stepper));
        PetscCall(policy.written(s));
        PetscCall(suite::logInfo(ctx.comm(), false, "final checkpoint %s", policy.pathForStep(s).c_str()));
      }
      info.status = "stopped at step " + std::to_string(s) + " (" + ctx.stopReason() + ")";
      PetscCall(suite::logInfo(ctx.comm(), false, "stop requested (%s) at step %d", ctx.stopReason().c_str(),
                               (int)s));
      break;
    }
    const auto t0 = std::chrono::steady_clock::now();
    StepStats st = stepper.step(&bodies);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o.dump[0]) {
      const auto& ps = stepper.lastProblems();
      for (size_t k = 0; k < ps.size() && dumped < o.dump_max; ++k, ++dumped) {
        char name[PETSC_MAX_PATH_LEN];
        std::snprintf(name, sizeof name, "%s_step%06d_pass%02d.h5", o.dump, (int)(s + 1), (int)k + 1);
        PetscCall(suite::lcp::writeProblemH5(ctx.comm(), name, ps[k]));
      }
    }
    if (st.failed) {
      std::string dump = std::string(o.output) + ".failed_step" + std::to_string(s + 1) + ".h5";
      if (!stepper.lastProblems().empty())
        PetscCall(suite::lcp::writeProblemH5(ctx.comm(), dump, stepper.lastProblems().back()));
      else
        dump = "(no problem)";
      failure = "step " + std::to_string(s + 1) + ": " + st.message + "problem dumped to " + dump;
      info.status = "failed: " + failure;
      break;
    }
    t += o.step.dt;
    rec.step(st, t, mechanicalEnergy(bodies, o.step.gravity), wall);
    if ((s + 1) % o.output_every == 0 || s + 1 == o.steps) rec.frame(bodies, s + 1, t);
    bool due = false;
    PetscCall(policy.due(s + 1, &due));
    if (due) {
      PetscCall(writeContactCheckpoint(ctx.comm(), policy.pathForStep(s + 1), scheme, s + 1, t, o.step.dt,
                                       bodies, stepper));
      PetscCall(policy.written(s + 1));
    }
    PetscCall(progress.update(s + 1, t, o.step.dt));
  }
  info.steps_done = s;
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(stages.output));
  if (rec.frame_step.back() != s) rec.frame(bodies, s, t);
  PetscCall(writeContactOutput(ctx, o.output, bodies, rec, info));
  PetscCall(PetscLogStagePop());
  PetscCheck(failure.empty(), ctx.comm(), PETSC_ERR_NOT_CONVERGED, "%s (output up to step %d in %s)",
             failure.c_str(), (int)s, o.output);
  PetscFunctionReturn(0);
}

} // namespace contact_app
