// Adaptive time step of Newmark / generalized-alpha from the a-posteriori local error estimate of
// Zienkiewicz & Xie (1991), "A simple error estimator and adaptive time stepping procedure for dynamic
// analysis", Earthquake Eng. Struct. Dyn. 20:871-887: the Newmark displacement update
// u_{n+1} = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1}) against the Taylor series with a linear
// acceleration over the step leaves the local displacement error
//
//   e = dt^2 (beta - 1/6) (a_{n+1} - a_n)                                   (ZX eq. 11)
//
// Generalized-alpha (Chung & Hulbert 1993) updates u with the same formula (its beta), so the same estimate
// applies to its accelerations (second-order accurate approximations of the physical ones).
//
// The caller measures e after a low-pass filter and in the mass norm (femdyn: e_f = (M + K0 / wc^2)^{-1} M e,
// Newmark::lowPass; ||x||_M = sqrt(x^T M x)). The cutoff wc = cutoffFrequency(dt, T) is the frequency whose
// trapezoidal phase error over the run, omega T (omega dt)^2 / 12, is 1 rad: below it a mode's phase error
// grows linearly in time (what the per-unit-time criterion below adds up), above it the phase over the run is
// lost at this dt anyway and the mode's error saturates at about twice its amplitude, however the local
// errors add up. Per mode the filter is 1 / (1 + (omega / wc)^2). Without it the modes the step load excites
// between wc and 1/dt (small amplitude, large acceleration) set dt: 7-14x more steps on the cantilever than the
// fixed step that meets the target. The saturated part is bounded, not controlled: femdyn records
// 2 ||u - lowpass(u)||_M / scale (/time_adapt unresolved_bound). The mass norm weighs the displacement by the
// mass that carries it, so that the bending modes that make the tip's motion dominate, not one node's local
// vibration.
//
// The error is controlled per unit time (Zienkiewicz & Xie sec. 4): a step of dt is accepted when
// ||e_f|| <= kPhaseFactor * target * scale * dt / T, scale = max(||K0^{-1} f_ext||, the largest ||u|| so far)
// (the scale of the error measure max_t |tip - tip_ref| / max_t |tip_ref|), T = the run's length. The accepted
// local estimates then add up to at most kPhaseFactor * target * scale. For a resolved mode e is the
// displacement part of its local phase error, the phase error dt^3 omega^3 / 12 times |sin| of the phase (the
// velocity part is not estimated), 2/pi of it on average over a period: the global (phase) error is about
// pi/2 times the sum of the estimates. kPhaseFactor = 1/2 (2/pi with a margin for the start and the partial
// periods; 1-DOF oscillator: global error 0.78 / 0.86 x target at 1e-2 / 1e-3, and 1.06 x target with 2/pi;
// tests/unit/fem/test_step_control.cpp). Where a mode's phase error saturates at its amplitude the bound is
// an upper bound (conservative: measured in docs/fem_target_error.md).
// With r = ||e_f|| / (target * scale * dt / T) ~ dt^2 the step changes by dt_new = dt * safety * r^(-1/2)
// (the standard controller for an estimate of order 2 in dt), bounded by [shrink, grow]; an accepted step
// whose factor lies in [1, hold) keeps its dt (the linear law refactorises K_eff = M / (beta dt^2) + K0 only
// when dt changes); no growth right after a rejection; dt within [dt_min, dt_max], dt_min reached is an error.
#pragma once

#include <petscsys.h>

namespace suite::fem {

// e = dt^2 (beta - 1/6) (a1 - a0) over n values.
void zienkiewiczXieError(double beta, double dt, const double* a0, const double* a1, int n, double* e);

// wc = (12 / (T dt^2))^(1/3): omega T (omega dt)^2 / 12 = 1 at omega = wc.
double cutoffFrequency(double dt, double t_final);

inline constexpr double kPhaseFactor = 0.5; // 2 / pi with a margin (see above)

struct StepControlParams {
  double target = 0;  // the relative displacement error the run's steps may add up to (> 0)
  double t_final = 0; // the run's length T (> 0)
  double safety = 0.8, grow = 2, shrink = 0.2, hold = 1.25;
  double dt_min = 0, dt_max = 0; // dt_max 0: T
};

struct StepDecision {
  bool accept = true;
  double ratio = 0;   // ||e|| / ((2/pi) target * scale * dt / T)
  double dt_next = 0; // the next try (after a rejection: the same step again)
};

class StepController {
public:
  explicit StepController(const StepControlParams& p) : p_(p) {}
  // The step of dt from t with its estimate est (||e||_inf) at the displacement scale; the decision is a
  // function of the arguments (and whether the last decision rejected): identical inputs on every rank give
  // identical decisions. dt_next < dt_min after a rejection: *below_min is set (the caller errors).
  StepDecision decide(double dt, double est, double scale, bool* below_min);
  // A step accepted without an estimate (ratio -1; the caller knows it is not the time step's error): the
  // same dt next.
  StepDecision keep(double dt);
  const StepControlParams& params() const { return p_; }

private:
  StepControlParams p_;
  bool last_rejected_ = false;
};

// Errors (naming the options) unless target is finite and > 0, T > 0, 0 < dt_min <= dt_max, and the factors
// satisfy 0 < shrink < 1 <= hold <= grow, 0 < safety < 1.
PetscErrorCode checkStepControl(MPI_Comm comm, const StepControlParams& p, double beta);

} // namespace suite::fem
