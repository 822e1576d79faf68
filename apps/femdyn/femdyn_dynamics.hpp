// femdyn's side of the suite's time loop (suite::TimeStepped): the Newmark / generalized-alpha integrator with
// Newton on the elastic model (plus the haptic probe's penalty when -probe), a fixed -dt, one step record
// (timings, energies, tip deflection) per step, snapshots, checkpoints (femdyn_checkpoint.cpp) and the final
// summary lines and output. The haptic probe itself is an observer of the loop (fem/haptic_probe.hpp).
#pragma once

#include "core/time_loop.hpp"
#include "femdyn_run.hpp"
#include "io/checkpoint.hpp"

#include <memory>
#include <string>

namespace femdyn_app {

class FemdynDynamics final : public suite::TimeStepped {
public:
  explicit FemdynDynamics(FemdynRun& run) : run_(run) {}
  // The probe (if any), the mass matrix and the integrator; before the loop (a restart needs them).
  PetscErrorCode setup();
  suite::fem::HapticProbeObserver* probe() { return probe_.get(); }

  PetscErrorCode start(PetscInt step, double t, bool restarted) override;
  PetscErrorCode proposeDt(PetscInt step, double t, double* dt) override;
  PetscErrorCode advance(PetscInt step, double t, double dt, suite::StepOutcome* out) override;
  PetscErrorCode saveState(const std::string& path, PetscInt step, double t) override;
  PetscErrorCode loadState(const std::string& path, PetscInt* step, double* t) override;
  PetscErrorCode writeSnapshot(PetscInt step, double t) override;
  PetscErrorCode writeFinal(const suite::LoopSummary& summary) override;

private:
  // -material auto (femdyn_material_auto.cpp): the nonlinear law's integrator on the same state, one step
  // with the law the policy picks, the estimate and its record, the summary line.
  PetscErrorCode setupMaterialAuto(const std::vector<double>& mass);
  PetscErrorCode stepMaterialAuto(double dt, suite::fem::StepTimings* tm, suite::fem::Fidelity* law_used,
                                  double* estimate);
  PetscErrorCode linearLawError(double* err) const;
  PetscErrorCode projectState(suite::fem::ElasticModel& from, suite::fem::ElasticModel& to);
  void recordLaw(suite::fem::Fidelity used, double estimate, double cpu);
  PetscErrorCode logMaterialAuto() const;
  void record(const suite::fem::StepTimings& tm, double total, double cpu);
  PetscErrorCode logSummary(const suite::LoopSummary& summary) const;
  // One step with the run's law(s) (femdyn_dynamics.cpp); -material auto: the law used and its estimate.
  PetscErrorCode stepOnce(double dt, suite::fem::StepTimings* tm, suite::fem::Fidelity* used, double* est);
  // -dt_adapt (femdyn_time_adapt.cpp): tries of the step from dt until the controller accepts one (each
  // counted in tm), the records of the tries, the next dt; the summary line.
  PetscErrorCode tryStep(double h, const suite::fem::NewmarkState& saved, suite::fem::StepTimings* total,
                         suite::fem::Fidelity* used, double* est_law, suite::fem::StepDecision* d,
                         bool* below_min);
  PetscErrorCode stepAdaptive(double dt, suite::fem::StepTimings* tm, suite::fem::Fidelity* used, double* est,
                              std::string* failed);
  // The sum of the accepted local estimates over the final displacement scale; the K_eff factorisations.
  double estimatedError() const { return scale_ > 0 ? estimate_sum_ / scale_ : 0.0; }
  double unresolvedBound() const { return scale_ > 0 ? unresolved_ / scale_ : 0.0; }
  int factorizations() const;
  PetscErrorCode staticScale(double* scale) const;
  double endingDt(double t) const;
  PetscErrorCode adaptEstimate(const std::vector<double>& a0, double dt, double* est, double* scale,
                               double* unresolved);
  void recordTry(double t, double dt, double ratio, bool accepted);
  PetscErrorCode logTimeAdapt() const;
  suite::CheckpointHeader checkpointHeader() const; // femdyn_checkpoint.cpp

  FemdynRun& run_;
  suite::fem::Newmark nm_;
  suite::fem::Newmark nm_nl_; // -material auto: the nonlinear law (model_nl_, solver_nl_), same state s_
  suite::fem::Fidelity law_ = suite::fem::Fidelity::cheap; // -material auto: the law of the next step
  suite::fem::NewmarkState s_;
  std::unique_ptr<suite::fem::HapticProbeObserver> probe_;
  std::unique_ptr<suite::fem::StepController> control_; // -dt_adapt
  double dt_next_ = 0, scale_ = 0, estimate_sum_ = 0,
         unresolved_ = 0;                  // -dt_adapt: next try, max ||u||_inf so far, sum of e
  double stepping_ = 0, stepping_cpu_ = 0; // wall and CPU seconds in the steps of this run
  int unconverged_ = 0;
};

} // namespace femdyn_app
