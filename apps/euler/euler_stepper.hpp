// The PETSc TS an Euler run steps with, one TSStep per step of the suite's time loop: SSP-RK3 (registered as
// "ssprk3"), RK4, or implicit beuler/cn/bdf2 through Jacobian-free Newton-Krylov; a failed Newton solve is
// retried inside TSStep at a smaller step (TSSetMaxSNESFailures -1). The table of integrators documents -time.
#pragma once

#include "core/named_choice.hpp"

#include <petscts.h>

#include <string>
#include <vector>

namespace euler_app {

// -time: name and one-line description of every integrator.
const std::vector<suite::Choice>& timeIntegrators();
bool isImplicit(const std::string& time);

struct StepperSettings {
  std::string time;     // one of timeIntegrators()
  double t_final = 0.0; // TSSetMaxTime (TSStep requires a limit; the loop ends the run)
  double dt = 0.0;      // first time step (each step sets its own)
};

// Creates *ts on da with the right-hand side rhs(ctx), its solution vector U, set up for TSStep.
PetscErrorCode createStepper(MPI_Comm comm, DM da, Vec U, const StepperSettings& s, TSRHSFunction rhs,
                             void* ctx, TS* ts);

} // namespace euler_app
