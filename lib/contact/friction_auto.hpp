// -friction auto -target_error E: each contact problem of a step (each island with -contact_islands on, else
// the whole scene) is solved by the cheapest friction model of a fixed ladder whose measured Coulomb-cone
// violation sum_i max(0, |lambda_t,i| - mu lambda_n,i) / sum_i lambda_n,i (forceMeasures, the measure of the
// speed-accuracy table, /steps/cone_violation) is <= E. The ladder (cheap and approximate first):
//   mu = 0:  none (the only rung: no friction rows, no violation);
//   mu > 0:  box, scaled_box, splitting 2 passes, splitting 5 passes, polyhedral d = 4, polyhedral d = 8 (the
//            full model; the d-gon is inscribed in the cone, so both polyhedral rungs violate it only by the
//            cone-row compliance, ~0.3 -polyhedral_gamma_reg). No converged-splitting rung: on the 40-log heap
//            it is chosen for 2 of 383 problems, and each failed probe of a large island from polyhedral_4
//            costs up to -splitting_max_it box solves (auto 25 s against 11.5 s with the 2/5-pass rungs).
// A problem's violation is +inf when friction acts on it without any normal impulse (box bounds from the
// weight estimate on separating contacts), so that every problem within E bounds the step's violation by E.
// Warm choice: a problem starts at the highest rung its contacts used at the previous step (matched contacts;
// the bottom rung when none matches) and climbs while the violation exceeds E. Coming back down: every
// kProbeEvery-th step (the stepper's step count) a problem starts one rung below its warm rung. A rung whose
// solver chain fails counts as a miss (the next rung is tried; the rungs below the start one only when no rung
// above solved the problem); when no rung meets E, the answer of the smallest violation is taken and the miss
// recorded (StepStats::target_missed); when no rung solves, the problem fails. The problem's statistics (rows,
// iterations, solver, ...) are the chosen rung's; StepStats::auto_solves counts every rung solve. Everything depends only on the problem's data and the step count, never on the rank that
// solves it, so results are the same at any rank count. References: the models' files (friction_*.cpp).
#pragma once

#include "contact/friction_formulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace suite::contact {

struct AutoRung {
  std::string name; // as recorded (/friction_auto attribute rungs)
  FrictionModel model;
  int passes = 0;     // splitting pass cap (0: the options')
  int directions = 0; // polyhedral directions
};

class AutoFriction {
public:
  static constexpr int kProbeEvery = 10;
  explicit AutoFriction(const StepperOptions& o);
  int size() const { return (int)rungs_.size(); }
  const AutoRung& rung(int r) const { return rungs_[r]; }
  const FrictionFormulation& formulation(int r) const { return *forms_[r]; }
  const StepperOptions& options(int r) const { return opts_[r]; }
  // The first rung to try: the highest of prev_rung (-1: contact without a predecessor), one lower when
  // probe is set, clamped to the ladder.
  int startRung(const std::vector<int>& prev_rung, bool probe) const;

private:
  std::vector<AutoRung> rungs_;
  std::vector<StepperOptions> opts_;
  std::vector<std::unique_ptr<FrictionFormulation>> forms_;
};

// The ladder of these options (names in order), for output attributes and messages.
std::vector<std::string> autoRungNames(const StepperOptions& o);

} // namespace suite::contact
