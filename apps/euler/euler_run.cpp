// 1D Euler run: options, DMDA setup, boundary ghosts, TS callbacks (see euler_run.hpp).
#include "euler_run.hpp"

#include "core/field_check.hpp"
#include "core/log.hpp"
#include "core/resource_checks.hpp"
#include "euler/gas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>

namespace euler_app {

using namespace suite::euler;

namespace {
const char* const kLineSolves[] = {"substructured", "gather"};
} // namespace

EulerRun::~EulerRun() {
  TSDestroy(&ts_);
  VecDestroy(&U_);
  DMDestroy(&da_);
}

PetscErrorCode EulerRun::readOptions() {
  MPI_Comm comm = ctx_.comm();
  char buf[PETSC_MAX_PATH_LEN];
  PetscBool set;
  PetscInt line_solve = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buf, opt_.problem.c_str(), sizeof(buf)));
  PetscOptionsBegin(comm, "", "Euler 1D options", "");
  PetscCall(PetscOptionsString("-problem", "Problem", "", buf, buf, sizeof(buf), nullptr));
  opt_.problem = buf;
  PetscCall(PetscStrncpy(buf, opt_.scheme.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-scheme", "Spatial scheme: enopade6, crweno5, weno5, muscl2", "", buf, buf,
                               sizeof(buf), nullptr));
  opt_.scheme = buf;
  PetscCall(PetscStrncpy(buf, opt_.time.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-time",
                               "Time integrator: ssprk3, rk4, beuler, cn, bdf2 (then -ts_* refine it)", "",
                               buf, buf, sizeof(buf), nullptr));
  opt_.time = buf;
  PetscCall(PetscOptionsInt("-scheme_spectrum",
                            "Measure the scheme's modified wavenumber on N periodic points instead of a run",
                            "", opt_.scheme_spectrum, &opt_.scheme_spectrum, nullptr));
  PetscOptionsEnd();
  PetscCall(createProblem(comm, opt_.problem, &problem_));
  scheme_ = findScheme(opt_.scheme);
  PetscCheck(scheme_, comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "Unknown scheme '%s' (option -scheme); known schemes: %s", opt_.scheme.c_str(),
             schemeNames().c_str());
  PetscCheck(isKnownTimeScheme(opt_.time), comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "Unknown time integrator '%s' (option -time); known: %s", opt_.time.c_str(), kTimeSchemes);
  opt_.implicit = isImplicit(opt_.time);

  opt_.nx = problem_.default_nx;
  opt_.t_final = problem_.t_final;
  opt_.max_steps = problem_.default_max_steps;
  opt_.dt = problem_.default_dt;
  opt_.spacetime_every = problem_.default_spacetime_every;
  if (opt_.implicit) opt_.positivity = PETSC_FALSE;
  double xmin = problem_.xmin, xmax = problem_.xmax;
  char bcl[64], bcr[64];
  PetscCall(PetscStrncpy(bcl, bcName(problem_.bc_left), sizeof(bcl)));
  PetscCall(PetscStrncpy(bcr, bcName(problem_.bc_right), sizeof(bcr)));
  buf[0] = 0;
  char ref[PETSC_MAX_PATH_LEN] = "";
  PetscOptionsBegin(comm, "", "Euler 1D discretisation and output options", "");
  PetscCall(PetscOptionsInt("-nx", "Number of cells", "", opt_.nx, &opt_.nx, nullptr));
  PetscCall(PetscOptionsReal("-t_final", "End time", "", opt_.t_final, &opt_.t_final, nullptr));
  PetscCall(PetscOptionsReal("-xmin", "Left end of the domain", "", xmin, &xmin, nullptr));
  PetscCall(PetscOptionsReal("-xmax", "Right end of the domain", "", xmax, &xmax, nullptr));
  PetscCall(PetscOptionsString("-bc_left", "Left boundary: periodic, outflow, reflecting, inflow", "", bcl,
                               bcl, sizeof(bcl), nullptr));
  PetscCall(PetscOptionsString("-bc_right", "Right boundary: periodic, outflow, reflecting, inflow", "", bcr,
                               bcr, sizeof(bcr), nullptr));
  PetscCall(
      PetscOptionsReal("-cfl", "CFL number: dt = cfl dx / max(|u| + c)", "", opt_.cfl, &opt_.cfl, nullptr));
  PetscCall(PetscOptionsReal("-dt", "Fixed time step (0: CFL-controlled)", "", opt_.dt, &opt_.dt, nullptr));
  PetscCall(PetscOptionsInt("-max_steps", "Maximum number of steps (-1: no limit)", "", opt_.max_steps,
                            &opt_.max_steps, nullptr));
  PetscCall(PetscOptionsBool("-characteristic", "Characteristic-wise reconstruction (false: component-wise)",
                             "", opt_.characteristic, &opt_.characteristic, nullptr));
  // Implicit steps default to the global alpha: the local one (a max over the stencil) is not
  // differentiable, and Newton stalls on it at shocks (Sod N = 200, weno5, BDF2: stagnates at 1e-4 relative).
  if (opt_.implicit) opt_.local_lf = PETSC_FALSE;
  PetscCall(PetscOptionsBool("-local_lf", "Local Lax-Friedrichs splitting (false: global; implicit default)",
                             "", opt_.local_lf, &opt_.local_lf, nullptr));
  PetscCall(PetscOptionsBool("-positivity", "Hu-Adams-Shu positivity-preserving flux limiter", "",
                             opt_.positivity, &opt_.positivity, nullptr));
  PetscCall(PetscOptionsReal("-shock_threshold", "ENO-Pade switch threshold (0: CRWENO rows everywhere)", "",
                             opt_.shock_threshold, &opt_.shock_threshold, nullptr));
  char line_solve_text[32];
  PetscCall(PetscStrncpy(line_solve_text, kLineSolves[opt_.gather_lines ? 1 : 0], sizeof line_solve_text));
  PetscCall(PetscOptionsString("-line_solve",
                               "Distributed compact line solve: substructured (O(N/P) per rank) or gather "
                               "(whole line on every rank, for comparison)",
                               "", line_solve_text, line_solve_text, sizeof line_solve_text, nullptr));
  PetscCall(suite::checkChoice(comm, "-line_solve", line_solve_text, kLineSolves, 2, &line_solve));
  opt_.gather_lines = line_solve == 1;
  PetscCall(PetscOptionsString("-output", "HDF5 output file", "", buf, buf, sizeof(buf), &set));
  if (set) opt_.output = buf;
  PetscCall(PetscOptionsInt("-snapshot_every", "Write a snapshot every N steps (0: none)", "",
                            opt_.snapshot_every, &opt_.snapshot_every, nullptr));
  PetscCall(PetscOptionsInt("-spacetime_every", "Record density every N steps for the x-t image (0: none)",
                            "", opt_.spacetime_every, &opt_.spacetime_every, nullptr));
  PetscCall(PetscOptionsBool("-error", "Compute L1/L2/Linf errors against the exact solution (or -reference)",
                             "", opt_.error, &opt_.error, nullptr));
  PetscCall(PetscOptionsString("-reference", "HDF5 file of a finer (or equal) grid run to compare with", "",
                               ref, ref, sizeof(ref), &set));
  if (set) opt_.reference = ref;
  PetscOptionsEnd();
  PetscCall(ckpt_.setFromOptions(comm, "euler"));

  PetscCheck(
      parseBc(bcl, &problem_.bc_left), comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
      "Unknown boundary condition '%s' (option -bc_left); known: periodic, outflow, reflecting, inflow", bcl);
  PetscCheck(
      parseBc(bcr, &problem_.bc_right), comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
      "Unknown boundary condition '%s' (option -bc_right); known: periodic, outflow, reflecting, inflow",
      bcr);
  PetscCheck((problem_.bc_left == Bc::Periodic) == (problem_.bc_right == Bc::Periodic), comm,
             PETSC_ERR_ARG_WRONG, "Periodic boundaries must be set on both ends (-bc_left %s, -bc_right %s)",
             bcl, bcr);
  periodic_ = problem_.bc_left == Bc::Periodic;
  problem_.xmin = xmin;
  problem_.xmax = xmax;
  PetscCheck(xmax > xmin, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid domain: -xmax %g must exceed -xmin %g",
             xmax, xmin);
  // 3 unknowns per cell must fit the 32-bit PetscInt; PETSc itself wraps larger values silently.
  PetscCall(suite::checkIntOptionRange(comm, "-nx", 1));
  PetscCheck(opt_.nx <= PETSC_MAX_INT / 3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": 3 nx unknowns exceed the 32-bit PetscInt (at most %d cells)",
             opt_.nx, (int)(PETSC_MAX_INT / 3));
  PetscCall(suite::checkIntOptionRange(comm, "-max_steps", -1));
  PetscCall(suite::checkIntOptionRange(comm, "-snapshot_every", 0));
  // Measured peak memory: ~1.0 kB per cell explicit, ~1.6 kB implicit (GMRES(30) vectors), Sod N = 1e6.
  char what[64];
  std::snprintf(what, sizeof what, "-nx %lld", (long long)opt_.nx);
  PetscCall(suite::checkMemoryEstimate(comm, (opt_.implicit ? 2000.0 : 1200.0) * opt_.nx / ctx_.size() + 5e7,
                                       what));
  const PetscInt width = 2 * kLineGhost;
  PetscCheck(opt_.nx >= width, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": below the stencil width %" PetscInt_FMT " of the schemes",
             opt_.nx, width);
  PetscCheck(opt_.nx >= kLineGhost * ctx_.size(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": each of the %d ranks needs at least %d cells", opt_.nx,
             ctx_.size(), kLineGhost);
  PetscCheck(opt_.cfl > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -cfl %g: must be > 0", opt_.cfl);
  PetscCheck(opt_.dt >= 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -dt %g: must be >= 0 (0: CFL-controlled)", opt_.dt);
  PetscCheck(opt_.t_final > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -t_final %g: must be > 0",
             opt_.t_final);
  PetscCheck(opt_.snapshot_every >= 0 && opt_.spacetime_every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -snapshot_every/-spacetime_every: must be >= 0");
  PetscCheck(!opt_.error || problem_.exact || !opt_.reference.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-error: problem '%s' has no exact solution; give -reference FILE.h5 of a fine-grid run",
             opt_.problem.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::setup() {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  const DMBoundaryType bt = periodic_ ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
  PetscCall(DMDACreate1d(comm, bt, opt_.nx, 3, kLineGhost, nullptr, &da_));
  PetscCall(DMSetUp(da_));
  PetscCall(DMDASetFieldName(da_, 0, "rho"));
  PetscCall(DMDASetFieldName(da_, 1, "rho_u"));
  PetscCall(DMDASetFieldName(da_, 2, "E"));
  PetscCall(DMDAGetCorners(da_, &xs_, nullptr, nullptr, &xm_, nullptr, nullptr));
  dx_ = (problem_.xmax - problem_.xmin) / opt_.nx;
  LineOptions lo;
  lo.gamma = problem_.gamma;
  lo.characteristic = opt_.characteristic;
  lo.local_lf = opt_.local_lf;
  lo.shock_threshold = opt_.shock_threshold;
  lo.positivity = opt_.positivity;
  lo.gather_lines = opt_.gather_lines;
  op_ = std::make_unique<DirectionSweep<3>>(scheme_, lo);
  q_.resize(xm_ + 2 * kLineGhost);
  h_.resize(xm_ + 1);
  xc_.resize(xm_);
  PetscCall(DMCreateGlobalVector(da_, &U_));
  PetscScalar* u;
  PetscCall(VecGetArray(U_, &u));
  for (PetscInt k = 0; k < xm_; ++k) {
    xc_[k] = problem_.xmin + (xs_ + k + 0.5) * dx_;
    const Vec3 q = toCons(problem_.initial(xc_[k]), problem_.gamma);
    for (int c = 0; c < 3; ++c) u[3 * k + c] = q[c];
  }
  PetscCall(VecRestoreArray(U_, &u));
  PetscCall(totals(U_, &totals0_));
  PetscCall(setupTimeStepper());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::setupTimeStepper() {
  PetscFunctionBeginUser;
  double amax;
  PetscCall(maxWaveSpeed(U_, &amax));
  StepperSettings s{opt_.time, opt_.t_final, opt_.max_steps, opt_.dt > 0 ? opt_.dt : opt_.cfl * dx_ / amax};
  PetscCall(createStepper(ctx_.comm(), da_, s, rhsCallback<EulerRun>, this, preStepCallback<EulerRun>,
                          postStepCallback<EulerRun>, &ts_));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::fillGhosts(Vec3* q) const {
  PetscFunctionBeginUser;
  if (periodic_) PetscFunctionReturn(0);
  const int g = kLineGhost;
  const double gam = problem_.gamma;
  if (xs_ == 0) {
    for (int m = 0; m < g; ++m) {
      Vec3& ghost = q[g - 1 - m];
      switch (problem_.bc_left) {
      case Bc::Outflow:
        ghost = q[g];
        break;
      case Bc::Reflecting:
        ghost = q[g + m], ghost[1] = -ghost[1];
        break;
      case Bc::Inflow:
        ghost = toCons(problem_.inflow_left, gam);
        break;
      case Bc::Periodic:
        break;
      }
    }
  }
  if (xs_ + xm_ == opt_.nx) {
    const int last = g + xm_ - 1;
    for (int m = 0; m < g; ++m) {
      Vec3& ghost = q[last + 1 + m];
      switch (problem_.bc_right) {
      case Bc::Outflow:
        ghost = q[last];
        break;
      case Bc::Reflecting:
        ghost = q[last - m], ghost[1] = -ghost[1];
        break;
      case Bc::Inflow:
        ghost = toCons(problem_.inflow_right, gam);
        break;
      case Bc::Periodic:
        break;
      }
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::maxWaveSpeed(Vec U, double* amax) const {
  const PetscScalar* u;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  double a = 0.0;
  for (PetscInt k = 0; k < xm_; ++k) {
    const double s = suite::euler::maxWaveSpeed({u[3 * k], u[3 * k + 1], u[3 * k + 2]}, problem_.gamma);
    a = (std::isnan(s) || s > a) ? (std::isnan(a) ? a : s) : a;
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &a, 1, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  *amax = a;
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::rhs(double, Vec U, Vec F) {
  Vec Ul;
  const PetscScalar* u;
  PetscScalar* f;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da_, &Ul));
  PetscCall(DMGlobalToLocal(da_, U, INSERT_VALUES, Ul));
  PetscCall(VecGetArrayRead(Ul, &u));
  const int g = kLineGhost;
  double amax = 0.0;
  for (PetscInt k = 0; k < xm_ + 2 * g; ++k) {
    const bool ghost_at_end = !periodic_ && ((xs_ == 0 && k < g) || (xs_ + xm_ == opt_.nx && k >= xm_ + g));
    if (!ghost_at_end) q_[k] = {u[3 * k], u[3 * k + 1], u[3 * k + 2]};
    if (k >= g && k < xm_ + g) amax = std::max(amax, suite::euler::maxWaveSpeed(q_[k], problem_.gamma));
  }
  PetscCall(VecRestoreArrayRead(Ul, &u));
  PetscCall(DMRestoreLocalVector(da_, &Ul));
  PetscCall(fillGhosts(q_.data()));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &amax, 1, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  try {
    op_->faceFluxes(ctx_.comm(), q_.data(), 1, opt_.nx, xs_, (int)xm_, periodic_, amax * (1.0 + 1e-12),
                    opt_.positivity ? dt_limiter_ / dx_ : 0.0, h_.data());
  } catch (const std::exception& e) { // identical on every rank: the line solve is redundant
    SETERRQ(ctx_.comm(), PETSC_ERR_NOT_CONVERGED,
            "Euler right-hand side failed at step %" PetscInt_FMT ": %s", steps_, e.what());
  }
  PetscCall(VecGetArray(F, &f));
  for (PetscInt k = 0; k < xm_; ++k)
    for (int c = 0; c < 3; ++c) f[3 * k + c] = -(h_[k + 1][c] - h_[k][c]) / dx_;
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::preStep() {
  PetscReal t;
  Vec U;
  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts_, &t));
  PetscCall(TSGetSolution(ts_, &U));
  double dt = opt_.dt;
  if (dt <= 0.0) {
    double amax;
    PetscCall(maxWaveSpeed(U, &amax));
    PetscCheck(std::isfinite(amax) && amax > 0.0, ctx_.comm(), PETSC_ERR_FP,
               "Wave speed is not finite at step %" PetscInt_FMT ", time %g", steps_, t);
    dt = opt_.cfl * dx_ / amax;
  }
  if (t + dt > opt_.t_final) dt = opt_.t_final - t;
  dt_limiter_ = dt;
  PetscCall(TSSetTimeStep(ts_, dt));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::primitiveArrays(Vec U, std::vector<double>* rho, std::vector<double>* u,
                                         std::vector<double>* p) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  rho->resize(xm_);
  u->resize(xm_);
  p->resize(xm_);
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt k = 0; k < xm_; ++k) {
    const Prim w = toPrim({a[3 * k], a[3 * k + 1], a[3 * k + 2]}, problem_.gamma);
    (*rho)[k] = w.rho, (*u)[k] = w.u, (*p)[k] = w.p;
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::checkState(Vec U, PetscInt step, double time) const {
  std::vector<double> rho, u, p;
  PetscFunctionBeginUser;
  PetscCall(primitiveArrays(U, &rho, &u, &p));
  suite::FieldLocation where{"rho", step, time, xs_, xc_.data()};
  PetscCall(suite::checkAbove(ctx_.comm(), rho.data(), xm_, 1, 0, 0.0, where));
  where.field = "u";
  PetscCall(suite::checkFinite(ctx_.comm(), u.data(), xm_, 1, 0, where));
  where.field = "p";
  PetscCall(suite::checkAbove(ctx_.comm(), p.data(), xm_, 1, 0, 0.0, where));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::postStep() {
  PetscReal t;
  Vec U;
  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts_, &t));
  PetscCall(TSGetStepNumber(ts_, &steps_));
  PetscCall(TSGetSolution(ts_, &U));
  time_ = t;
  PetscCall(checkState(U, steps_, t));
  if (opt_.snapshot_every > 0 && steps_ % opt_.snapshot_every == 0 && !opt_.output.empty())
    PetscCall(writeSnapshot(steps_, t));
  if (opt_.spacetime_every > 0 && steps_ % opt_.spacetime_every == 0) {
    const PetscScalar* a;
    PetscCall(VecGetArrayRead(U, &a));
    for (PetscInt k = 0; k < xm_; ++k) spacetime_rho_.push_back(a[3 * k]);
    PetscCall(VecRestoreArrayRead(U, &a));
    spacetime_t_.push_back(t);
  }
  PetscCall(endOfStep(ctx_, ts_, ckpt_, progress_.get(), steps_, t, [this] { return checkpointNow(); }));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::solve() {
  PetscFunctionBeginUser;
  PetscCall(restartIfRequested());
  PetscCall(checkState(U_, steps_, time_));
  if (opt_.spacetime_every > 0) {
    const PetscScalar* a;
    PetscCall(VecGetArrayRead(U_, &a));
    for (PetscInt k = 0; k < xm_; ++k) spacetime_rho_.push_back(a[3 * k]);
    PetscCall(VecRestoreArrayRead(U_, &a));
    spacetime_t_.push_back(0.0);
  }
  if (opt_.snapshot_every > 0 && !opt_.output.empty()) PetscCall(writeSnapshot(0, 0.0));
  PetscCall(suite::logInfo(
      ctx_.comm(), ctx_.quiet(),
      "euler: problem %s, scheme %s, time %s, nx %" PetscInt_FMT ", t_final %g, %d rank(s)",
      opt_.problem.c_str(), opt_.scheme.c_str(), opt_.time.c_str(), opt_.nx, opt_.t_final, ctx_.size()));
  progress_ =
      std::make_unique<suite::Progress>(ctx_.comm(), ctx_.quiet(), ctx_.progressInterval(), opt_.t_final);
  const double w0 = MPI_Wtime(), c0 = cpuSeconds();
  PetscCall(TSSolve(ts_, U_));
  wall_solve_ = MPI_Wtime() - w0;
  cpu_solve_ = cpuSeconds() - c0; // this rank's CPU time: the clock to trust on a loaded machine
  PetscCall(TSGetStepNumber(ts_, &steps_));
  PetscReal t;
  PetscCall(TSGetTime(ts_, &t));
  time_ = t;
  if (ckpt_.enabled() && last_checkpoint_step_ != steps_) PetscCall(checkpointNow()); // final state
  Vec3 tot;
  PetscCall(totals(U_, &tot));
  const char* names[3] = {"mass", "momentum", "energy"};
  for (int c = 0; c < 3; ++c) {
    const double scale = std::max(std::abs(totals0_[c]), 1e-300);
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "conservation %s: initial %.15e final %.15e rel_change %.3e", names[c],
                             totals0_[c], tot[c], std::abs(tot[c] - totals0_[c]) / scale));
  }
  const double cells = (double)opt_.nx * steps_;
  PetscCall(suite::logInfo(
      ctx_.comm(), ctx_.quiet(),
      "euler: %" PetscInt_FMT
      " steps to t = %.6g in %.3f s (%.3e cell-steps/s, %.3e per rank; rank 0 CPU %.3f s); "
      "shock rows %lld, limited faces %lld, line solves %lld (exact fallbacks %lld)",
      steps_, t, wall_solve_, cells / wall_solve_, cells / wall_solve_ / ctx_.size(), cpu_solve_,
      op_->stats().shock_rows, op_->stats().limited_faces, op_->lineSolves(), op_->lineFallbacks()));
  if (opt_.implicit) {
    PetscInt failures, rejections;
    PetscCall(TSGetSNESFailures(ts_, &failures));
    PetscCall(TSGetStepRejections(ts_, &rejections));
    PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                             "implicit: %" PetscInt_FMT " Newton failures, %" PetscInt_FMT
                             " steps retried at half the time step",
                             failures, rejections));
  }
  if (opt_.error) PetscCall(computeErrors());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::totals(Vec U, Vec3* sum) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  double s[3] = {0, 0, 0};
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt k = 0; k < xm_; ++k)
    for (int c = 0; c < 3; ++c) s[c] += a[3 * k + c] * dx_;
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 3, MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  *sum = {s[0], s[1], s[2]};
  PetscFunctionReturn(0);
}

PetscErrorCode runEuler(const suite::RunContext& ctx) {
  PetscInt dim = 1;
  PetscFunctionBeginUser;
  PetscOptionsBegin(ctx.comm(), "", "Euler dimension", "");
  PetscCall(PetscOptionsInt("-dim", "Spatial dimension: 1, 2 or 3 (2/3: -nx -ny -nz, DMDA process grid)", "",
                            dim, &dim, nullptr));
  PetscOptionsEnd();
  PetscCheck(dim >= 1 && dim <= 3, ctx.comm(), PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -dim %" PetscInt_FMT ": 1, 2 or 3", dim);
  if (dim > 1) {
    PetscCall(runEulerND(ctx, (int)dim));
    PetscFunctionReturn(0);
  }
  EulerRun run(ctx);
  PetscCall(run.readOptions());
  if (ctx.helpRequested()) {
    PetscCall(ctx.checkUnusedOptions());
    PetscFunctionReturn(0);
  }
  if (run.spectrumOnly()) {
    PetscCall(ctx.checkUnusedOptions());
    PetscCall(run.schemeSpectrum());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(ctx.checkUnusedOptions());
  PetscCall(run.solve());
  PetscCall(run.writeOutput());
  PetscFunctionReturn(0);
}

} // namespace euler_app
