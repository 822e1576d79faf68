// Switching policy with hysteresis (see law_switch.hpp): the band [down, up] * target keeps a run near the
// threshold from switching at every step.
#include "fem/law_switch.hpp"

#include <cmath>

namespace suite::fem {

Fidelity LawSwitchPolicy::next(Fidelity current, double estimate) const {
  if (current == Fidelity::cheap) return cheapRejected(estimate) ? Fidelity::accurate : Fidelity::cheap;
  return estimate < down * target ? Fidelity::cheap : Fidelity::accurate;
}

PetscErrorCode checkLawSwitchPolicy(MPI_Comm comm, const LawSwitchPolicy& p) {
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(p.target) && p.target > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-target_error %g: must be a finite number > 0", p.target);
  PetscCheck(p.down > 0 && p.down < p.up && p.up <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "law switch thresholds -target_switch_down %g, -target_switch_up %g: need 0 < down < up <= 1",
             p.down, p.up);
  PetscFunctionReturn(0);
}

} // namespace suite::fem
