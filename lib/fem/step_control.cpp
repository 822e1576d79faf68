// The Zienkiewicz-Xie estimate and the step controller (see step_control.hpp).
#include "fem/step_control.hpp"

#include <algorithm>
#include <cmath>

namespace suite::fem {

void zienkiewiczXieError(double beta, double dt, const double* a0, const double* a1, int n, double* e) {
  const double c = dt * dt * (beta - 1.0 / 6.0);
  for (int i = 0; i < n; ++i) e[i] = c * (a1[i] - a0[i]);
}

double cutoffFrequency(double dt, double t_final) {
  return std::cbrt(12.0 / (t_final * dt * dt));
}

StepDecision StepController::decide(double dt, double est, double scale, bool* below_min) {
  StepDecision d;
  const double tol = kPhaseFactor * p_.target * scale * dt / p_.t_final;
  d.ratio = est > 0 ? (tol > 0 ? est / tol : HUGE_VAL) : 0.0;
  d.accept = d.ratio <= 1;
  double f = d.ratio > 0 ? p_.safety / std::sqrt(d.ratio) : p_.grow;
  f = std::clamp(f, p_.shrink, p_.grow);
  if (d.accept) {
    if (last_rejected_) f = std::min(f, 1.0);
    if (f >= 1 && f < p_.hold) f = 1;
  }
  const double dt_max = p_.dt_max > 0 ? p_.dt_max : p_.t_final;
  d.dt_next = std::min(dt * f, dt_max);
  *below_min = !d.accept && d.dt_next < p_.dt_min;
  if (d.accept) d.dt_next = std::max(d.dt_next, p_.dt_min);
  last_rejected_ = !d.accept;
  return d;
}

StepDecision StepController::keep(double dt) {
  StepDecision d;
  d.ratio = -1, d.dt_next = dt;
  last_rejected_ = false;
  return d;
}

PetscErrorCode checkStepControl(MPI_Comm comm, const StepControlParams& p, double beta) {
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(p.target) && p.target > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-target_error %g: must be a finite number > 0", p.target);
  PetscCheck(p.t_final > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-dt_adapt: the run's length -steps x -dt = %g must be > 0", p.t_final);
  const double dt_max = p.dt_max > 0 ? p.dt_max : p.t_final;
  PetscCheck(p.dt_min > 0 && p.dt_min <= dt_max, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-dt_min %g and -dt_max %g: need 0 < dt_min <= dt_max", p.dt_min, dt_max);
  PetscCheck(p.safety > 0 && p.safety < 1 && p.shrink > 0 && p.shrink < 1 && p.hold >= 1 && p.grow >= p.hold,
             comm, PETSC_ERR_ARG_OUTOFRANGE,
             "step controller: need 0 < safety %g < 1, 0 < shrink %g < 1 <= hold %g <= grow %g", p.safety,
             p.shrink, p.hold, p.grow);
  PetscCheck(std::abs(beta - 1.0 / 6.0) > 1e-3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-dt_adapt: the Zienkiewicz-Xie estimate dt^2 (beta - 1/6) (a_{n+1} - a_n) vanishes at "
             "-newmark_beta %g (1/6): use beta = 1/4",
             beta);
  PetscFunctionReturn(0);
}

} // namespace suite::fem
