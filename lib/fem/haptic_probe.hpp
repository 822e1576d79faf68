// The haptic probe as an observer of a time loop (suite::StepObserver; femdyn adds it): a rigid point pressing
// along -y on one surface node with a penalty spring (fem/probe_contact.hpp). Before each step it moves the probe to
// its target height at the step's end time; after each step (a synchronisation point) it records the
// full-model probe force, the probe node's compliance from the current factorisation (one solve per
// direction) and the haptic local model's force ticks up to the next step (which would run concurrently
// with it).
#pragma once

#include "core/run_context.hpp"
#include "core/time_loop.hpp"
#include "fem/assembly.hpp"
#include "fem/linear_solver.hpp"
#include "fem/mesh.hpp"
#include "fem/newmark.hpp"
#include "fem/probe_contact.hpp"

#include <memory>
#include <string>
#include <vector>

namespace suite::fem {

struct HapticProbeSettings {
  double point[3] = {1e300, 1e300, 1e300}; // contact point (nearest node); default: top of the free end
  double stiffness = 1000, speed = 0.5, depth = 0.2; // penalty k, indentation speed along -y, travel
  double haptic_rate = 1000, dt = 0.01;              // haptic output rate (Hz), FEM step
  std::string dirichlet;                             // the clamped set (for the message on a fixed node)
};

struct HapticProbeRecord {
  int node = -1;
  std::vector<double> sync_time, force_full, force_predicted, compliance_yy; // per FEM step (sync point)
  std::vector<double> haptic_time, haptic_force;                             // per haptic tick
  double tick_seconds = 0, compliance_seconds = 0;                           // CPU totals
  long long ticks = 0;
};

class HapticProbeObserver final : public suite::StepObserver {
public:
  // Finds the probe node (nearest to -probe_point; collective error if it is fixed) and wraps the elastic
  // model in the probe's penalty system. state: the Newmark state the loop advances; record: the output.
  static PetscErrorCode create(const RunContext& ctx, const HapticProbeSettings& opt, const TetMesh& mesh,
                               ElasticModel* model, LinearSolver* solver, bool partial,
                               const NewmarkState& state, HapticProbeRecord* record,
                               std::unique_ptr<HapticProbeObserver>* out);
  // The system the integrator steps: elasticity plus the probe's penalty force.
  SecondOrderSystem* system() { return probe_.get(); }
  // The probe at its target height at time t (also on restart, before the tangent is refactorised).
  void placeAt(double t) { probe_->setProbe(height(t)); }
  PetscErrorCode beforeStep(PetscInt step, double t, double dt) override;
  PetscErrorCode afterStep(PetscInt step, double t, double dt) override;
  // The summary line: final force, haptic rate, local vs full model at the synchronisations.
  PetscErrorCode logSummary() const;

private:
  HapticProbeObserver(const RunContext& ctx, const HapticProbeSettings& set, const TetMesh& mesh,
                      const ElasticModel& model, LinearSolver* solver, const NewmarkState& state,
                      HapticProbeRecord* record)
      : ctx_(ctx), set_(set), mesh_(mesh), model_(model), solver_(solver), s_(state), rec_(record) {}
  double height(double t) const; // probe tip height y_d(t)
  PetscErrorCode complianceYY(double* c_yy) const;
  double hapticTicks(const HapticLocalModel& hm); // returns the force at the last tick

  const RunContext& ctx_;
  const HapticProbeSettings set_;
  const TetMesh& mesh_;
  const ElasticModel& model_;
  LinearSolver* solver_;
  const NewmarkState& s_;
  HapticProbeRecord* rec_;
  int dofs_[3] = {-1, -1, -1}; // free DOFs of the probe node (-1: fixed)
  std::unique_ptr<ProbeSystem> probe_;
};

} // namespace suite::fem
