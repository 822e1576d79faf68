// One step of the Euler run under the suite's TimeLoop (see euler_run.hpp): the CFL time step from the
// largest wave speeds (or -dt), one TSStep of PETSc TS (an implicit step's Newton retries stay inside it), and
// the collective check of the new state: a non-finite or non-positive density or pressure stops the job naming
// step, time and cell.
#include "euler_run.hpp"

#include "core/field_check.hpp"
#include "core/log.hpp"
#include "euler_state.hpp"

#include <cmath>

namespace euler_app {

PetscErrorCode EulerRun::maxWaveSpeeds(Vec U, double amax[3]) const {
  const PetscScalar* u;
  double a[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt c = 0; c < localCells(); ++c) {
    double s[3];
    waveSpeeds(u + c * nv(), dim(), problem_.gamma, s);
    for (int d = 0; d < dim(); ++d) // NaN wins: it stops the run in proposeDt
      a[d] = (std::isnan(s[d]) || s[d] > a[d]) ? (std::isnan(a[d]) ? a[d] : s[d]) : a[d];
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, a, 3, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  for (int d = 0; d < 3; ++d) amax[d] = a[d];
  PetscFunctionReturn(0);
}

// 1D: cfl dx / max(|u| + c); 2D/3D: cfl / sum_d(max(|u_d| + c) / dx_d).
double EulerRun::cflTimeStep(const double amax[3]) const {
  if (dim() == 1) return opt_.cfl * dx_[0] / amax[0];
  double s = 0.0;
  for (int d = 0; d < dim(); ++d) s += amax[d] / dx_[d];
  return opt_.cfl / s;
}

PetscErrorCode EulerRun::checkState(Vec U, PetscInt step, double time) const {
  const PetscScalar* a;
  const PetscInt ncell = localCells();
  std::vector<double> rho(ncell), u(ncell), p(ncell), x;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < ncell; ++c) {
    const PrimN w = primitive(a + c * nv(), dim(), problem_.gamma);
    rho[c] = w.rho, u[c] = w.u[0], p[c] = w.p;
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  // 1D: the message names the cell and its centre; 2D/3D: this rank's cell number in its block (x fastest).
  suite::FieldLocation where{"rho", step, time, 0, nullptr};
  if (dim() == 1) {
    for (PetscInt i = 0; i < ncell; ++i) x.push_back(problem_.lo[0] + (s_[0] + i + 0.5) * dx_[0]);
    where.global_offset = s_[0], where.coords = x.data();
  }
  PetscCall(suite::checkAbove(ctx_.comm(), rho.data(), ncell, 1, 0, 0.0, where));
  if (dim() == 1) {
    where.field = "u";
    PetscCall(suite::checkFinite(ctx_.comm(), u.data(), ncell, 1, 0, where));
  }
  where.field = "p";
  PetscCall(suite::checkAbove(ctx_.comm(), p.data(), ncell, 1, 0, 0.0, where));
  PetscFunctionReturn(0);
}

// -spacetime_every (1D): this state's density as one row of the x-t image.
PetscErrorCode EulerRun::recordSpacetime(Vec U, double t) {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt k = 0; k < m_[0]; ++k) spacetime_rho_.push_back(a[3 * k]);
  PetscCall(VecRestoreArrayRead(U, &a));
  spacetime_t_.push_back(t);
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::start(PetscInt step, double t, bool restarted) {
  PetscFunctionBeginUser;
  step_ = step, time_ = t;
  // TSSolve's start of a fresh solve (a multistep integrator starts with its one-step method).
  if (!restarted) PetscCall(TSRestartStep(ts_));
  if (restarted && opt_.time == "bdf2")
    PetscCall(
        suite::logInfo(ctx_.comm(), ctx_.quiet(), "euler: BDF2 restarts with a BDF1 step: not bitwise"));
  PetscCall(checkState(U_, step, t));
  // The x-t image starts with the state the run starts from (recorded at t = 0 as before the time loop).
  if (opt_.spacetime_every > 0) PetscCall(recordSpacetime(U_, 0.0));
  if (dim() == 1)
    PetscCall(suite::logInfo(
        ctx_.comm(), ctx_.quiet(),
        "euler: problem %s, scheme %s, time %s, nx %" PetscInt_FMT ", t_final %g, %d rank(s)",
        opt_.problem.c_str(), opt_.scheme.c_str(), opt_.time.c_str(), opt_.n[0], opt_.t_final, ctx_.size()));
  else
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "euler: problem %s, dim %d, scheme %s, time %s, grid %" PetscInt_FMT
                             " x %" PetscInt_FMT " x %" PetscInt_FMT ", t_final %g, %d rank(s)",
                             opt_.problem.c_str(), dim(), opt_.scheme.c_str(), opt_.time.c_str(), opt_.n[0],
                             opt_.n[1], opt_.n[2], opt_.t_final, ctx_.size()));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::proposeDt(PetscInt step, double t, double* dt) {
  PetscFunctionBeginUser;
  *dt = opt_.dt;
  if (*dt <= 0.0) {
    double amax[3];
    PetscCall(maxWaveSpeeds(U_, amax));
    *dt = cflTimeStep(amax);
    PetscCheck(std::isfinite(*dt) && *dt > 0.0, ctx_.comm(), PETSC_ERR_FP,
               "Wave speed is not finite at step %" PetscInt_FMT ", time %g", step, t);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::advance(PetscInt step, double t, double dt, suite::StepOutcome* out) {
  TSConvergedReason reason;
  PetscReal t_new;
  PetscFunctionBeginUser;
  (void)t;
  step_ = step;
  dt_limiter_ = dt; // the positivity limiter's dt
  PetscCall(TSSetTimeStep(ts_, dt));
  PetscCall(TSStep(ts_));
  PetscCall(TSGetConvergedReason(ts_, &reason));
  if (reason < 0) { // reached only with -ts_error_if_step_fails false: TSStep errors itself otherwise
    out->status = suite::StepStatus::Failed;
    out->message = std::string("PETSc TS step diverged (") + TSConvergedReasons[reason] + ")";
    PetscFunctionReturn(0);
  }
  PetscCall(TSGetTime(ts_, &t_new));
  PetscCall(checkState(U_, step + 1, t_new));
  if (opt_.spacetime_every > 0 && (step + 1) % opt_.spacetime_every == 0)
    PetscCall(recordSpacetime(U_, t_new));
  step_ = step + 1, time_ = t_new;
  out->status = suite::StepStatus::Done;
  out->t_new = t_new;
  PetscFunctionReturn(0);
}

} // namespace euler_app
