// The haptic probe as an observer of femdyn's time loop (suite::StepObserver): a rigid point pressing along
// -y on one surface node with a penalty spring (fem/probe_contact.hpp). Before each step it moves the probe to
// its target height at the step's end time; after each step (a synchronisation point) it records the
// full-model probe force, the probe node's compliance from the current factorisation (one solve per
// direction) and the haptic local model's force ticks up to the next step (which would run concurrently
// with it).
#pragma once

#include "core/time_loop.hpp"
#include "fem/probe_contact.hpp"
#include "femdyn_run.hpp"

#include <memory>

namespace femdyn_app {

class HapticProbeObserver final : public suite::StepObserver {
public:
  // Finds the probe node (nearest to -probe_point; collective error if it is fixed) and wraps the elastic
  // model in the probe's penalty system. state: the Newmark state the loop advances; record: the output.
  static PetscErrorCode create(const suite::RunContext& ctx, const Options& opt,
                               const suite::fem::TetMesh& mesh, suite::fem::ElasticModel* model,
                               suite::fem::LinearSolver* solver, bool partial,
                               const suite::fem::NewmarkState& state, ProbeRecord* record,
                               std::unique_ptr<HapticProbeObserver>* out);
  // The system the integrator steps: elasticity plus the probe's penalty force.
  suite::fem::SecondOrderSystem* system() { return probe_.get(); }
  // The probe at its target height at time t (also on restart, before the tangent is refactorised).
  void placeAt(double t) { probe_->setProbe(height(t)); }
  PetscErrorCode beforeStep(PetscInt step, double t, double dt) override;
  PetscErrorCode afterStep(PetscInt step, double t, double dt) override;
  // The summary line: final force, haptic rate, local vs full model at the synchronisations.
  PetscErrorCode logSummary() const;

private:
  HapticProbeObserver(const suite::RunContext& ctx, const Options& opt, const suite::fem::TetMesh& mesh,
                      const suite::fem::ElasticModel& model, suite::fem::LinearSolver* solver,
                      const suite::fem::NewmarkState& state, ProbeRecord* record)
      : ctx_(ctx), opt_(opt), mesh_(mesh), model_(model), solver_(solver), s_(state), rec_(record) {}
  double height(double t) const; // probe tip height y_d(t)
  PetscErrorCode complianceYY(double* c_yy) const;
  double hapticTicks(const suite::fem::HapticLocalModel& hm); // returns the force at the last tick

  const suite::RunContext& ctx_;
  const Options& opt_;
  const suite::fem::TetMesh& mesh_;
  const suite::fem::ElasticModel& model_;
  suite::fem::LinearSolver* solver_;
  const suite::fem::NewmarkState& s_;
  ProbeRecord* rec_;
  int dofs_[3] = {-1, -1, -1}; // free DOFs of the probe node (-1: fixed)
  std::unique_ptr<suite::fem::ProbeSystem> probe_;
};

} // namespace femdyn_app
