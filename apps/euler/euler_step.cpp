// One step of the Euler run under the suite's TimeLoop (see euler_run.hpp): the CFL time step from the
// largest wave speeds (or -dt), one TSStep of PETSc TS (an implicit step's Newton retries stay inside it), and
// the collective check of the new state. A step is retried at half dt (TimeLoop, at most -max_retries times,
// counted in the run's summary and output) from the state before it when a stage state (explicit integrators)
// or the new state has a non-finite or non-positive density or pressure, or when the positivity limiter met a
// face it could not make safe (a stage above its CFL bound, lib/euler/direction_sweep.hpp). When the retries
// are exhausted the job stops with the last attempt's message, naming step, time and cell. With -filter_alpha the
// new state is filtered (euler_filter.cpp) before that check.
#include "euler_run.hpp"

#include "core/field_check.hpp"
#include "core/log.hpp"
#include "euler_state.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace euler_app {

namespace {
void takeSpeeds(const double* q, int dim, double gamma, double a[3]) {
  double s[3];
  waveSpeeds(q, dim, gamma, s);
  for (int d = 0; d < dim; ++d) // NaN wins: it stops the run in proposeDt
    a[d] = (std::isnan(s[d]) || s[d] > a[d]) ? (std::isnan(a[d]) ? a[d] : s[d]) : a[d];
}
} // namespace

// The ghost states of Custom faces (an inflow such as the jet's) enter the domain within the step: their speeds
// count too (else the first step of a jet entering ambient gas at rest would be ~80 times the stable one).
void EulerRun::customGhostSpeeds(const double* u, double t, double a[3]) const {
  const int nv = this->nv();
  for (int d = 0; d < dim(); ++d)
    for (int side = 0; side < 2; ++side) {
      const PetscInt n = opt_.n[d], edge = side == 0 ? 0 : n - 1;
      if (problem_.bc[d][side] != suite::euler::BcN::Custom || edge < s_[d] || edge >= s_[d] + m_[d])
        continue;
      PetscInt lo[3] = {s_[0], s_[1], s_[2]}, hi[3] = {s_[0] + m_[0], s_[1] + m_[1], s_[2] + m_[2]};
      lo[d] = edge, hi[d] = edge + 1;
      for (PetscInt k = lo[2]; k < hi[2]; ++k)
        for (PetscInt j = lo[1]; j < hi[1]; ++j)
          for (PetscInt i = lo[0]; i < hi[0]; ++i)
            for (PetscInt gi = 0; gi < suite::euler::kLineGhost; ++gi) {
              const PetscInt cell[3] = {i, j, k}; // next to the face
              PetscInt idx[3] = {i, j, k}, mirror[3] = {i, j, k};
              idx[d] = side == 0 ? -1 - gi : n + gi;
              mirror[d] = side == 0 ? gi : n - 1 - gi; // owned: every rank holds >= kLineGhost cells
              auto local = [&](const PetscInt* c) {
                return u + (((c[2] - s_[2]) * m_[1] + (c[1] - s_[1])) * m_[0] + (c[0] - s_[0])) * nv;
              };
              double x[3], qg[5];
              cellCentre(idx[0], idx[1], idx[2], x);
              const PrimN w = problem_.ghost(d, side, x, t, primitive(local(mirror), dim(), problem_.gamma),
                                             primitive(local(cell), dim(), problem_.gamma));
              conservative(w, dim(), problem_.gamma, qg);
              takeSpeeds(qg, dim(), problem_.gamma, a);
            }
    }
}

PetscErrorCode EulerRun::maxWaveSpeeds(Vec U, double t, double amax[3]) const {
  const PetscScalar* u;
  double a[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt c = 0; c < localCells(); ++c)
    if (!solidCell(c)) takeSpeeds(u + c * nv(), dim(), problem_.gamma, a);
  customGhostSpeeds(u, t, a);
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

PetscErrorCode EulerRun::findInvalidState(Vec U, PetscInt step, double time, std::string* message) const {
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
  PetscCall(suite::findNotAbove(ctx_.comm(), rho.data(), ncell, 1, 0, 0.0, where, message));
  if (message->empty() && dim() == 1) {
    where.field = "u";
    PetscCall(suite::findNonFinite(ctx_.comm(), u.data(), ncell, 1, 0, where, message));
  }
  where.field = "p";
  if (message->empty())
    PetscCall(suite::findNotAbove(ctx_.comm(), p.data(), ncell, 1, 0, 0.0, where, message));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::checkState(Vec U, PetscInt step, double time) const {
  std::string message;
  PetscFunctionBeginUser;
  PetscCall(findInvalidState(U, step, time, &message));
  PetscCheck(message.empty(), ctx_.comm(), PETSC_ERR_FP, "%s: stopping the run", message.c_str());
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
    PetscCall(suite::logInfo(ctx_.comm(), quiet(), "euler: BDF2 restarts with a BDF1 step: not bitwise"));
  PetscCall(checkState(U_, step, t));
  if (opt_.output_initial && !restarted) PetscCall(writeInitial());
  // The x-t image starts with the state the run starts from (recorded at t = 0 as before the time loop).
  if (opt_.spacetime_every > 0) PetscCall(recordSpacetime(U_, 0.0));
  if (dim() == 1)
    PetscCall(suite::logInfo(
        ctx_.comm(), quiet(),
        "euler: problem %s, scheme %s, time %s, nx %" PetscInt_FMT ", t_final %g, %d rank(s)",
        opt_.problem.c_str(), opt_.scheme.c_str(), opt_.time.c_str(), opt_.n[0], opt_.t_final, ctx_.size()));
  else
    PetscCall(suite::logInfo(ctx_.comm(), quiet(),
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
    PetscCall(maxWaveSpeeds(U_, t, amax));
    *dt = cflTimeStep(amax);
    PetscCheck(std::isfinite(*dt) && *dt > 0.0, ctx_.comm(), PETSC_ERR_FP,
               "Wave speed is not finite at step %" PetscInt_FMT ", time %g", step, t);
  }
  PetscFunctionReturn(0);
}

// Why the step just taken must be retried ("" to accept it), the same on every rank: a stage state that was not
// admissible (explicit integrators, rhs), the new state not admissible, or (positivity limiter) a face the limiter
// could not make safe at a stage above its CFL bound; the last is accepted on the last attempt when the state is
// admissible (the retries are for positivity, not for the bound itself).
PetscErrorCode EulerRun::stepProblem(PetscInt step, double t_new, std::string* why) {
  PetscFunctionBeginUser;
  *why = stage_failure_;
  if (why->empty()) PetscCall(findInvalidState(U_, step + 1, t_new, why));
  if (!why->empty() || !opt_.positivity || retry_attempt_ >= opt_.max_retries) PetscFunctionReturn(0);
  long long faces = unattainableFaces() - unattainable0_;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &faces, 1, MPI_LONG_LONG, MPI_SUM, ctx_.comm()));
  if (faces > 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "a stage above the positivity limiter's CFL bound %g at %lld face(s)",
                  suite::euler::kPositivityCfl, faces);
    *why = buf;
  }
  PetscFunctionReturn(0);
}

// Back to the state, time and step number before the step; TSRestartStep: a multistep integrator (BDF2) starts
// again from this state with its one-step method.
PetscErrorCode EulerRun::rollBack(PetscInt step, double t) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(U0_, U_));
  PetscCall(TSSetTime(ts_, t));
  PetscCall(TSSetStepNumber(ts_, step));
  PetscCall(TSRestartStep(ts_));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::advance(PetscInt step, double t, double dt, suite::StepOutcome* out) {
  TSConvergedReason reason;
  PetscReal t_new;
  std::string why;
  PetscFunctionBeginUser;
  step_ = step;
  dt_limiter_ = dt; // the positivity limiter's dt
  retry_attempt_ = retry_step_ == step ? retry_attempt_ + 1 : 0;
  retry_step_ = step;
  if (!U0_) PetscCall(VecDuplicate(U_, &U0_));
  PetscCall(VecCopy(U_, U0_));
  stage_failure_.clear();
  unattainable0_ = unattainableFaces();
  PetscCall(TSSetTimeStep(ts_, dt));
  PetscCall(TSStep(ts_));
  PetscCall(TSGetConvergedReason(ts_, &reason));
  if (reason < 0) { // reached only with -ts_error_if_step_fails false: TSStep errors itself otherwise
    out->status = suite::StepStatus::Failed;
    out->message = std::string("PETSc TS step diverged (") + TSConvergedReasons[reason] + ")";
    PetscFunctionReturn(0);
  }
  PetscCall(TSGetTime(ts_, &t_new));
  if (stage_failure_.empty())
    PetscCall(applyFilter(t_new, t_new - t, U_)); // -filter_alpha (euler_filter.cpp)
  PetscCall(stepProblem(step, t_new, &why));
  if (!why.empty()) { // TimeLoop retries at dt / 2 (at most -max_retries times) or stops with this message
    PetscCall(rollBack(step, t));
    out->status = suite::StepStatus::Retry;
    out->message = why;
    if (retry_attempt_ >= opt_.max_retries)
      out->message += " (after " + std::to_string(retry_attempt_) + " retries at half dt)";
    PetscFunctionReturn(0);
  }
  retry_step_ = -1;
  if (opt_.spacetime_every > 0 && (step + 1) % opt_.spacetime_every == 0)
    PetscCall(recordSpacetime(U_, t_new));
  step_ = step + 1, time_ = t_new;
  out->status = suite::StepStatus::Done;
  out->t_new = t_new;
  PetscFunctionReturn(0);
}

} // namespace euler_app
