// femdyn: the run's phases (options, setup, solve, output in their log stages), the static solve and the
// dynamic run on the suite's time loop (suite::TimeLoop with femdyn's TimeStepped side and the haptic probe
// as an observer).
#include "femdyn_run.hpp"

#include "core/log.hpp"
#include "core/log_stages.hpp"
#include "core/time_loop.hpp"
#include "fem/cpu_timer.hpp"
#include "femdyn_dynamics.hpp"

#include <algorithm>

namespace femdyn_app {

using namespace suite::fem;

std::vector<double> FemdynRun::fullDisplacement(const std::vector<double>& free) const {
  std::vector<double> full(model_.numDofs(), 0.0);
  model_.scatterFree(free.data(), full.data());
  return full;
}

double FemdynRun::tipDeflection(const std::vector<double>& u) const {
  double s = 0;
  for (int v : tip_nodes_) s -= u[3 * v + 1];
  return tip_nodes_.empty() ? 0.0 : s / tip_nodes_.size();
}

PetscErrorCode FemdynRun::solveStaticCase() {
  std::vector<double> u;
  PetscFunctionBeginUser;
  const double t0 = wallSeconds();
  PetscCall(solveStatic(ctx_.comm(), &model_, solver_.get(), f_ext_, (int)opt_.load_steps,
                        (int)opt_.newmark.newton_max_it, opt_.newmark.newton_rtol, &u, &res_.stat, partial_));
  res_.loop_time = wallSeconds() - t0;
  res_.u_full = fullDisplacement(u);
  res_.tip_deflection = tipDeflection(res_.u_full);
  double ux = 0;
  for (int v : tip_nodes_) ux += res_.u_full[3 * v];
  ux /= std::max<size_t>(1, tip_nodes_.size());
  res_.tip_ux = ux;
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                           "femdyn static: tip_deflection %.6f (mean -u_y on %zu tip nodes), tip u_x %.6f, "
                           "%d load steps, %d Newton iterations, residual %.3e, strain energy %.6e, %.3f s",
                           res_.tip_deflection, tip_nodes_.size(), ux, res_.stat.load_steps,
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
  set.t_final = 0.0; // femdyn counts steps
  set.max_steps = opt_.steps;
  set.snapshot_every = opt_.snapshot_every;
  set.eta_time = opt_.steps * opt_.dt;
  suite::TimeLoop loop(ctx_, policy_, set);
  if (dyn.probe()) loop.addObserver(dyn.probe());
  PetscCall(loop.run(dyn));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::writeOutputStage() const {
  suite::LogStages stages;
  PetscFunctionBeginUser;
  PetscCall(suite::LogStages::get(&stages));
  PetscCall(PetscLogStagePush(stages.output));
  PetscCall(writeOutput());
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::solve() {
  PetscFunctionBeginUser;
  if (!opt_.is_static && opt_.steps > 0) {
    PetscCall(solveDynamic());
    PetscFunctionReturn(0);
  }
  if (opt_.is_static)
    PetscCall(solveStaticCase());
  else
    res_.u_full.assign(model_.numDofs(), 0.0); // -steps 0: setup, ordering and analysis only
  PetscCall(writeOutputStage());
  PetscFunctionReturn(0);
}

PetscErrorCode runFemdyn(const suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  suite::LogStages stages;
  PetscCall(suite::LogStages::get(&stages));
  FemdynRun run(ctx);
  PetscCall(PetscLogStagePush(stages.setup));
  PetscCall(run.readOptions());
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) {
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(stages.solve));
  PetscCall(run.solve()); // ends with the output (in the output stage)
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
