// The switching policy of an accuracy-target run between a cheap model and an accurate one (femdyn
// -material auto: the linear law and a geometrically nonlinear law), with hysteresis: switch up when the
// estimated error of the cheap model exceeds up * target, back down when it falls below down * target
// (0 < down < up <= 1). The estimate is whatever the caller calibrated to the error measure of the target.
#pragma once

#include <petscsys.h>

namespace suite::fem {

enum class Fidelity { cheap = 0, accurate = 1 };

struct LawSwitchPolicy {
  double target = 1e-2; // the error the run must stay below (> 0, finite)
  double up = 0.3;      // switch to the accurate model when estimate > up * target
  double down = 0.1;    // back to the cheap model when estimate < down * target
  // The model for the next step given the current one and the estimated error of the cheap model now.
  Fidelity next(Fidelity current, double estimate) const;
  // True when the cheap model's result with this estimate must not be accepted (estimate > up * target).
  bool cheapRejected(double estimate) const { return estimate > up * target; }
};

// Errors (naming -target_error) unless target is finite and > 0, and 0 < down < up <= 1.
PetscErrorCode checkLawSwitchPolicy(MPI_Comm comm, const LawSwitchPolicy& p);

} // namespace suite::fem
