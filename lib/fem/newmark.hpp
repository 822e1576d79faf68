// Newmark time integration (Newmark 1959, J. Eng. Mech. Div. 85; beta = 1/4, gamma = 1/2 by default) and
// generalized-alpha (Chung & Hulbert 1993, J. Appl. Mech. 60:371, alpha_m/alpha_f weights) of
// M a + C v + f_int(u) = f_ext(t) with a Newton loop on the effective tangent K_eff = M/(beta dt^2) +
// gamma/(beta dt) C + K_T (newton_max_it = 1: the linearly implicit variant), Rayleigh damping C = alpha M +
// beta K0, and step rejection with dt halving when an element inverts (det F <= 0) or Newton fails.
#pragma once

#include "core/named_choice.hpp"
#include "fem/linear_solver.hpp"
#include "fem/second_order_system.hpp"

#include <functional>
#include <string>

namespace suite::fem {

struct NewmarkParams {
  double beta = 0.25, gamma = 0.5;
  // Generalized-alpha (Chung & Hulbert 1993): equilibrium at t_{n+1-alpha_f} with the inertia at
  // a_{n+1-alpha_m}; 0, 0 is Newmark. Set all four from rho_inf with generalizedAlpha().
  double alpha_m = 0, alpha_f = 0;
  int newton_max_it = 10;
  double newton_rtol = 1e-9, newton_atol = 1e-12;
  double rayleigh_mass = 0, rayleigh_stiffness = 0; // C = a M + b K0
  int max_halvings = 10;
  bool initial_jacobian = false; // modified Newton: K_eff from K0 (factor once per dt)
  // Tangent predictor (full Newton only): the constant-acceleration predictor is corrected once with the last
  // factorised effective tangent (previous step, same dt): one solve and one force evaluation, no assembly of
  // a tangent, no factorisation. The Newton iterations that follow are unchanged (consistent tangent,
  // refactorised every iteration) and so is the stopping test (relative to the residual at the
  // constant-acceleration predictor, as without the correction); at least one Newton iteration is done.
  bool tangent_predictor = false;
  // Lagged tangent (modified Newton, -jacobian lagged): every correction solves with the effective tangent
  // factorised last, possibly at an earlier step; it is refreshed (the consistent tangent assembled at the
  // iterate and refactorised before the correction) only when there is none for this dt, or, after the first
  // correction with it in a step, when the residual contraction q = |r_k| / |r_{k-1}| exceeds
  // refresh_contraction or when the corrections made with it plus those q predicts to reach the Newton test
  // exceed refresh_iterations (Newmark::refreshDue). The stopping test is Newton's.
  bool lagged = false;
  double refresh_contraction = 0.5;
  int refresh_iterations = 6;
  // Work cap (0: none): at most max_corrections corrections per step; then the step is accepted with the
  // residual at its last iterate recorded (StepTimings::residual, converged = false), never rejected for it.
  // With the lagged tangent, the step after one that ended above the tolerance refactorises at its predictor
  // (the unconverged residuals would otherwise accumulate): a step costs at most max_corrections solves and
  // one factorisation.
  int max_corrections = 0;
  // Distributed assembly: the system's force, tangent, energy and the mass are this rank's partial sums; the
  // residual (and energies, admissibility) are summed over the ranks of comm; the external force counts once.
  bool partial_sums = false;
};

// Chung & Hulbert (1993), J. Appl. Mech. 60:371, eqs. (25) and (17): alpha_m = (2 rho - 1)/(rho + 1),
// alpha_f = rho/(rho + 1), gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4 for the
// spectral radius rho = rho_inf in [0, 1] at omega dt -> infinity (second order, unconditionally stable).
NewmarkParams generalizedAlpha(NewmarkParams p, double rho_inf);

// The named choices of the integrator's options, each with its one-line help (for suite::optionsChoice):
// -time_scheme, -jacobian, -newton_predictor and -mass.
std::vector<suite::Choice> timeSchemeChoices();
std::vector<suite::Choice> jacobianChoices();
std::vector<suite::Choice> predictorChoices();
std::vector<suite::Choice> massChoices();

struct StepTimings { // CPU seconds of the calling thread (core/clocks.hpp)
  double assemble = 0, factor = 0, solve = 0;
  int newton_iterations = 0, factorizations = 0, rejected = 0;
  double residual = 0; // |r| at the accepted iterate
  bool capped = false; // the work cap ended a step (max_corrections)
  bool converged = true;
};

struct NewmarkState {
  std::vector<double> u, v, a;
  double t = 0;
  // Tangent predictor: the point (and dt) at which the last accepted step factorised its effective tangent
  // (empty: none). Part of the state so that a restart can refactorise it (Newmark::restoreTangent).
  std::vector<double> u_tangent;
  double dt_tangent = 0;
};

class Newmark {
public:
  // mass values on sys.pattern(); f_ext(t, f) fills the external force (free DOFs).
  PetscErrorCode setup(MPI_Comm comm, SecondOrderSystem* sys, LinearSolver* solver, std::vector<double> mass,
                       const NewmarkParams& p, std::function<void(double, double*)> f_ext);
  // Consistent initial acceleration a0 = M^{-1} (f_ext(t0) - C v0 - f_int(u0)).
  PetscErrorCode initialize(NewmarkState* s);
  // Advances s by dt (substeps with halved dt on rejection). Errors after max_halvings rejections in a row.
  PetscErrorCode step(NewmarkState* s, double dt, StepTimings* tm);
  // After a restart (tangent predictor): refactorise the effective tangent at s.u_tangent, dt_tangent, as the
  // uninterrupted run holds it (the system must be in the same state, e.g. the probe position). Collective.
  PetscErrorCode restoreTangent(const NewmarkState& s);
  // x = (M + K0 / wc^2)^{-1} M e with the filter's own solver (analysed on the system's pattern; refactorised
  // when wc changes): per mode the low-pass factor 1 / (1 + (omega / wc)^2) (the filter of the time-step
  // error estimate, fem/step_control.hpp). e and x are replicated; collective.
  PetscErrorCode lowPass(LinearSolver* filter, double wc, const double* e, double* x);
  // sqrt(x^T M x) of a replicated x (collective with partial sums).
  double massNorm(const double* x) const;
  // Kinetic energy 1/2 v^T M v, strain energy from the last force evaluation.
  double kineticEnergy(const NewmarkState& s) const;
  double strainEnergy(const NewmarkState& s);

private:
  struct Attempt; // one attempt's predictor, iterate and Newton bookkeeping (newmark.cpp)
  enum class Verdict { iterate, converged, rejected };
  PetscErrorCode attempt(NewmarkState* s, double dt, StepTimings* tm, bool* ok);
  // The steps of an attempt: predictor, residual at the iterate, the tangent predictor's correction, the test
  // of an iterate, the refactorisation, the Newton correction, the acceptance.
  void predict(Attempt& a);
  void restartFromPredictor(Attempt& a);
  void ratesAt(Attempt& a);
  PetscErrorCode residualAt(Attempt& a, bool want_tangent, bool* admissible);
  PetscErrorCode correctPredictor(Attempt& a);
  PetscErrorCode testIterate(Attempt& a, int it, bool fused, Verdict* v);
  Verdict convergence(Attempt& a, int it);
  PetscErrorCode refactorize(Attempt& a, int it, bool fused, Verdict* v);
  PetscErrorCode applyCorrection(Attempt& a);
  bool refreshDue(const Attempt& a) const;
  PetscErrorCode acceptCapped(Attempt& a, bool* ok);
  void reject(const Attempt& a, const std::string& why);
  void accept(Attempt& a);
  PetscErrorCode factorEffective(double dt, const std::vector<double>& Kt, StepTimings* tm, bool* ok);
  // Partial sums: sum r over the ranks, AND the admissibility, zero the external force on ranks > 0.
  PetscErrorCode sumResidual();
  PetscErrorCode allAdmissible(bool* ok) const;
  double sumScalar(double x) const;

  MPI_Comm comm_ = MPI_COMM_SELF;
  int rank_ = 0;
  SecondOrderSystem* sys_ = nullptr;
  LinearSolver* solver_ = nullptr;
  NewmarkParams p_;
  std::function<void(double, double*)> fext_;
  std::vector<double> M_, C_, K0_, Kt_, Keff_vals_;
  SymCsc Keff_;
  std::string reject_reason_; // why the last attempt was rejected
  double filter_wc_ = -1;     // cutoff of the low-pass filter's factorisation (lowPass)
  double factored_dt_ = -1; // dt of the current factorisation when it is reusable (linear / modified Newton)
  bool keff_current_ = false; // the solver holds K_eff at the state's (u_tangent, dt_tangent)
  bool damped_ = false;       // C != 0
  int last_newton_ = 1;       // Newton iterations of the last accepted attempt (when to assemble the tangent)
  bool refresh_next_ = false; // lagged + work cap: the last step ended above the tolerance
  std::vector<double> u_factored_; // evaluation point of the last factorisation in this attempt
  std::vector<double> r_, du_, f_, fe_, tmp_, tmp2_, ua_, va_, aa_;
};

// Static equilibrium f_int(u) = f_ext with load stepping (nsteps increments) and Newton per increment.
struct StaticResult {
  int load_steps = 0, newton_iterations = 0;
  double residual = 0, energy = 0;
};
PetscErrorCode solveStatic(MPI_Comm comm, SecondOrderSystem* sys, LinearSolver* solver,
                           const std::vector<double>& f_ext, int nsteps, int newton_max_it, double rtol,
                           std::vector<double>* u, StaticResult* res, bool partial_sums = false);

} // namespace suite::fem
