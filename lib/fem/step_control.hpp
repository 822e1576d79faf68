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
// The caller measures e after a filter and in the mass norm (femdyn: e_f = K_eff^{-1} (c0 M e), the step's
// effective matrix, Newmark::filterWithEffective; ||x||_M = sqrt(x^T M x)). Per mode the filter is
// 1 / (1 + beta (omega dt)^2): ~1 on the modes dt resolves (there e is the ZX estimate), ~1 / (omega dt)^2 on
// the others, whose estimate would otherwise be (omega dt)^2 times their amplitude although their error is
// at most about it. The mass norm weighs the displacement by the mass that carries it, so that the bending
// modes that make the tip's motion dominate, not one node's local vibration (the infinity norm let local
// high-frequency modes set dt 40x below what the tip error needs on the cantilever).
//
// The error is controlled per unit time (Zienkiewicz & Xie sec. 4): a step of dt is accepted when
// ||e_f|| <= target * scale * dt / T, scale = max(||K0^{-1} f_ext||, the largest ||u|| so far) (the scale of
// the error measure max_t |tip - tip_ref| / max_t |tip_ref|), T = the run's length. The accepted local
// estimates then add up to at most target * scale; for a resolved mode their sum is its leading phase error
// omega T (omega dt)^2 / 12 (trapezoidal rule), so the bound is the global error of the modes dt resolves,
// and an upper bound where a mode's phase error saturates at its amplitude (conservative, see the docs).
// With r = ||e_f|| / (target * scale * dt / T) ~ dt^2 the step changes by dt_new = dt * safety * r^(-1/2)
// (the standard controller for an estimate of order 2 in dt), bounded by [shrink, grow]; an accepted step
// whose factor lies in [1, hold) keeps its dt (the linear law refactorises K_eff = M / (beta dt^2) + K0 only
// when dt changes); no growth right after a rejection; dt within [dt_min, dt_max], dt_min reached is an error.
#pragma once

#include <petscsys.h>

namespace suite::fem {

// e = dt^2 (beta - 1/6) (a1 - a0) over n values.
void zienkiewiczXieError(double beta, double dt, const double* a0, const double* a1, int n, double* e);

struct StepControlParams {
  double target = 0;  // the relative displacement error the run's steps may add up to (> 0)
  double t_final = 0; // the run's length T (> 0)
  double safety = 0.8, grow = 2, shrink = 0.2, hold = 1.25;
  double dt_min = 0, dt_max = 0; // dt_max 0: T
};

struct StepDecision {
  bool accept = true;
  double ratio = 0;   // ||e|| / (target * scale * dt / T)
  double dt_next = 0; // the next try (after a rejection: the same step again)
};

class StepController {
public:
  explicit StepController(const StepControlParams& p) : p_(p) {}
  // The step of dt from t with its estimate est (||e||_inf) at the displacement scale; the decision is a
  // function of the arguments (and whether the last decision rejected): identical inputs on every rank give
  // identical decisions. dt_next < dt_min after a rejection: *below_min is set (the caller errors).
  StepDecision decide(double dt, double est, double scale, bool* below_min);
  const StepControlParams& params() const { return p_; }

private:
  StepControlParams p_;
  bool last_rejected_ = false;
};

// Errors (naming the options) unless target is finite and > 0, T > 0, 0 < dt_min <= dt_max, and the factors
// satisfy 0 < shrink < 1 <= hold <= grow, 0 < safety < 1.
PetscErrorCode checkStepControl(MPI_Comm comm, const StepControlParams& p, double beta);

} // namespace suite::fem
