// femdyn: the run's phases (options, setup, solve, output in their log stages), the static solve and the
// dynamic run on the suite's time loop (suite::TimeLoop with femdyn's TimeStepped side and the haptic probe
// as an observer).
#include "femdyn_run.hpp"

#include "core/log.hpp"
#include "core/log_stages.hpp"
#include "core/run_summary.hpp"
#include "io/xdmf.hpp"
#include "core/time_loop.hpp"
#include "core/clocks.hpp"
#include "femdyn_dynamics.hpp"

namespace femdyn_app {

using namespace suite::fem;

PetscErrorCode FemdynRun::solveStaticCase() {
  std::vector<double> u;
  PetscFunctionBeginUser;
  const double t0 = suite::wallSeconds();
  PetscCall(solveStatic(ctx_.comm(), &model_, solver_.get(), f_ext_, (int)opt_.load_steps,
                        (int)opt_.newmark.newton_max_it, opt_.newmark.newton_rtol, &u, &res_.stat, partial_));
  res_.loop_time = suite::wallSeconds() - t0;
  res_.u_full = model_.fullVector(u);
  res_.tip_deflection = nodalMean(res_.u_full, tip_nodes_, 1, -1);
  res_.tip_ux = nodalMean(res_.u_full, tip_nodes_, 0);
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                           "femdyn static: tip_deflection %.6f (mean -u_y on %zu tip nodes), tip u_x %.6f, "
                           "%d load steps, %d Newton iterations, residual %.3e, strain energy %.6e, %.3f s",
                           res_.tip_deflection, tip_nodes_.size(), res_.tip_ux, res_.stat.load_steps,
                           res_.stat.newton_iterations, res_.stat.residual, res_.stat.energy,
                           res_.loop_time));
  PetscFunctionReturn(0);
}

// -steps steps of -dt on the suite's time loop; its final write (FemdynDynamics::writeFinal) writes the output.
PetscErrorCode FemdynRun::solveDynamic() {
  PetscFunctionBeginUser;
  FemdynDynamics dyn(*this);
  PetscCall(dyn.setup());
  suite::TimeLoopSettings set;
  set.app = "femdyn";
  set.t_final = opt_.dt_adapt ? opt_.steps * opt_.dt : 0.0; // fixed dt: femdyn counts steps
  set.max_steps = opt_.dt_adapt ? -1 : opt_.steps;
  set.snapshot_every = opt_.snapshot_every;
  set.eta_time = opt_.steps * opt_.dt;
  set.output = opt_.output.c_str();
  suite::TimeLoop loop(ctx_, policy_, set);
  if (dyn.probe()) loop.addObserver(dyn.probe());
  PetscCall(loop.run(dyn));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::solve() {
  char what[160];
  PetscFunctionBeginUser;
  if (!opt_.is_static && opt_.steps > 0) {
    PetscCall(solveDynamic());
    PetscFunctionReturn(0);
  }
  if (opt_.is_static)
    PetscCall(solveStaticCase());
  else
    res_.u_full.assign(model_.numDofs(), 0.0); // -steps 0: setup, ordering and analysis only
  PetscCall(writeOutput());
  if (opt_.is_static)
    PetscCall(PetscSNPrintf(what, sizeof what, "static solve, tip deflection %.6g in %.3f s",
                            res_.tip_deflection, res_.loop_time));
  else
    PetscCall(PetscSNPrintf(what, sizeof what, "setup and ordering only (-steps 0)"));
  PetscCall(suite::logRunSummary(ctx_, res_.status, what, suite::outputWithSidecar(opt_.output)));
  PetscFunctionReturn(0);
}

PetscErrorCode runFemdyn(const suite::RunContext& ctx) {
  suite::LogStages stages;
  FemdynRun run(ctx);
  PetscFunctionBeginUser;
  PetscCall(suite::LogStages::get(&stages));
  {
    suite::StageScope setup(stages.setup);
    PetscCall(run.readOptions());
    if (run.options().backend == "plex" && !ctx.helpRequested()) { // checks unused options after SNES's
      PetscCall(runPlexFemdyn(ctx, run.options(), run.checkpointPolicy()));
      PetscFunctionReturn(0);
    }
    PetscCall(ctx.checkUnusedOptions());
    if (ctx.helpRequested()) PetscFunctionReturn(0);
    PetscCall(run.setup());
  }
  suite::StageScope solve(stages.solve);
  PetscCall(run.solve()); // ends with the output (in the output stage)
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
