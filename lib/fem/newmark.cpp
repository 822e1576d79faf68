// Newmark-beta with Newton iterations on the displacement increment (Hughes, The Finite Element Method 1987,
// sec. 9.1 and 9.3; Wriggers, Nonlinear FEM 2008, sec. 5.2): u_{n+1} = u~ + beta dt^2 a_{n+1},
// v_{n+1} = v~ + gamma dt a_{n+1}, u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, v~ = v_n + dt (1 - gamma) a_n.
#include "fem/newmark.hpp"

#include "fem/cpu_timer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace suite::fem {

namespace {
double now() {
  return threadCpuSeconds();
}
double norm2(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s);
}
} // namespace

NewmarkParams generalizedAlpha(NewmarkParams p, double rho) {
  p.alpha_m = (2 * rho - 1) / (rho + 1);
  p.alpha_f = rho / (rho + 1);
  p.gamma = 0.5 - p.alpha_m + p.alpha_f;
  p.beta = 0.25 * (1 - p.alpha_m + p.alpha_f) * (1 - p.alpha_m + p.alpha_f);
  return p;
}

bool LinearSecondOrderSystem::internalForce(const double* u, double* f, std::vector<double>* K,
                                            double* energy) {
  symMultiply(K_, K_.val, u, f);
  if (K) *K = K_.val;
  if (energy) {
    double e = 0;
    for (int i = 0; i < K_.n; ++i) e += 0.5 * u[i] * f[i];
    *energy = e;
  }
  return true;
}

PetscErrorCode Newmark::sumResidual() {
  PetscFunctionBeginUser;
  if (p_.partial_sums)
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, r_.data(), (int)r_.size(), MPI_DOUBLE, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::allAdmissible(bool* ok) const {
  PetscFunctionBeginUser;
  if (p_.partial_sums) {
    int mine = *ok ? 1 : 0, all = 0;
    PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm_));
    *ok = all == 1;
  }
  PetscFunctionReturn(0);
}

double Newmark::sumScalar(double x) const {
  if (p_.partial_sums) MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return x;
}

PetscErrorCode Newmark::setup(MPI_Comm comm, SecondOrderSystem* sys, LinearSolver* solver,
                              std::vector<double> mass, const NewmarkParams& p,
                              std::function<void(double, double*)> f_ext) {
  PetscFunctionBeginUser;
  comm_ = comm;
  MPI_Comm_rank(comm, &rank_);
  sys_ = sys;
  solver_ = solver;
  p_ = p;
  fext_ = std::move(f_ext);
  M_ = std::move(mass);
  const int n = sys->pattern().n;
  PetscCheck(p.beta > 0 && p.gamma >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Newmark -newmark_beta %g must be > 0 (implicit) and -newmark_gamma %g >= 0", p.beta, p.gamma);
  PetscCheck(p.alpha_m < 1 && p.alpha_f < 1 && p.alpha_f >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "generalized-alpha: alpha_m %g and alpha_f %g must be < 1 (alpha_f >= 0)", p.alpha_m, p.alpha_f);
  PetscCheck(p.newton_max_it >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-newton_max_it %d must be >= 1",
             p.newton_max_it);
  r_.assign(n, 0), du_.assign(n, 0), f_.assign(n, 0), fe_.assign(n, 0), tmp_.assign(n, 0), tmp2_.assign(n, 0);
  std::vector<double> zero(n, 0.0);
  double e;
  sys_->internalForce(zero.data(), f_.data(), &K0_, &e);
  C_.assign(M_.size(), 0.0);
  for (size_t k = 0; k < M_.size(); ++k) C_[k] = p.rayleigh_mass * M_[k] + p.rayleigh_stiffness * K0_[k];
  damped_ = std::any_of(C_.begin(), C_.end(), [](double c) { return c != 0; });
  Keff_ = sys->pattern();
  factored_dt_ = -1;
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::initialize(NewmarkState* s) {
  PetscFunctionBeginUser;
  const int n = Keff_.n;
  s->u.resize(n, 0.0), s->v.resize(n, 0.0), s->a.assign(n, 0.0);
  double e;
  bool adm = sys_->internalForce(s->u.data(), f_.data(), nullptr, &e);
  PetscCall(allAdmissible(&adm));
  PetscCheck(adm, comm_, PETSC_ERR_ARG_WRONG, "initial displacement inverts an element (det F <= 0)");
  fext_(s->t, fe_.data());
  if (p_.partial_sums && rank_ > 0) std::fill(fe_.begin(), fe_.end(), 0.0);
  symMultiply(Keff_, C_, s->v.data(), tmp_.data());
  for (int i = 0; i < n; ++i) r_[i] = fe_[i] - f_[i] - tmp_[i];
  PetscCall(sumResidual());
  Keff_.val = M_;
  bool ok;
  PetscCall(solver_->factor(Keff_, &ok));
  PetscCheck(ok, comm_, PETSC_ERR_MAT_CH_ZRPVT, "mass matrix is not positive definite (check -density)");
  PetscCall(solver_->solve(r_.data(), s->a.data()));
  factored_dt_ = -1;
  keff_current_ = false; // the solver holds the mass matrix now
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::factorEffective(double dt, const std::vector<double>& Kt, StepTimings* tm, bool* ok) {
  PetscFunctionBeginUser;
  // d r / d u_{n+1} with r = M a_{n+1-am} + C v_{n+1-af} + f(u_{n+1-af}) (Newmark: am = af = 0).
  const double c0 = (1 - p_.alpha_m) / (p_.beta * dt * dt), c1 = (1 - p_.alpha_f) * p_.gamma / (p_.beta * dt),
               ck = 1 - p_.alpha_f;
  const double t0 = now();
  for (size_t k = 0; k < M_.size(); ++k) Keff_.val[k] = c0 * M_[k] + c1 * C_[k] + ck * Kt[k];
  PetscCall(solver_->factor(Keff_, ok));
  tm->factor += now() - t0;
  ++tm->factorizations;
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::attempt(NewmarkState* s, double dt, StepTimings* tm, bool* ok) {
  PetscFunctionBeginUser;
  const int n = Keff_.n;
  const double b = p_.beta, g = p_.gamma;
  const double c0 = 1.0 / (b * dt * dt);
  const double am = p_.alpha_m, af = p_.alpha_f;
  const bool alpha = am != 0 || af != 0; // generalized-alpha: evaluate at the intermediate point
  std::vector<double> up(n), vp(n), un(n), an(n), vn(n);
  if (alpha) ua_.resize(n), va_.resize(n), aa_.resize(n);
  for (int i = 0; i < n; ++i) {
    up[i] = s->u[i] + dt * s->v[i] + dt * dt * (0.5 - b) * s->a[i];
    vp[i] = s->v[i] + dt * (1 - g) * s->a[i];
    un[i] = up[i] + b * dt * dt * s->a[i];
  }
  fext_(alpha ? s->t + (1 - af) * dt : s->t + dt, fe_.data());
  if (p_.partial_sums && rank_ > 0) std::fill(fe_.begin(), fe_.end(), 0.0);
  const bool reuse = sys_->isLinear() || p_.initial_jacobian;
  const bool exact_after_one = sys_->isLinear();
  const double* ueval = alpha ? ua_.data() : un.data();
  // Residual r_ at the iterate un, with the tangent Kt_ when asked (same point, same force); admissibility.
  auto residual = [&](bool want_tangent, bool* admissible) -> PetscErrorCode {
    const double t0 = now();
    for (int i = 0; i < n; ++i) an[i] = c0 * (un[i] - up[i]), vn[i] = vp[i] + g * dt * an[i];
    if (alpha)
      for (int i = 0; i < n; ++i) {
        ua_[i] = (1 - af) * un[i] + af * s->u[i];
        va_[i] = (1 - af) * vn[i] + af * s->v[i];
        aa_[i] = (1 - am) * an[i] + am * s->a[i];
      }
    double e;
    *admissible = sys_->internalForce(ueval, f_.data(), want_tangent ? &Kt_ : nullptr, &e);
    PetscCall(allAdmissible(admissible));
    if (*admissible) {
      symMultiply(Keff_, M_, alpha ? aa_.data() : an.data(), tmp_.data());
      if (damped_) {
        symMultiply(Keff_, C_, alpha ? va_.data() : vn.data(), tmp2_.data());
        for (int i = 0; i < n; ++i) r_[i] = tmp_[i] + tmp2_[i] + f_[i] - fe_[i];
      } else {
        for (int i = 0; i < n; ++i) r_[i] = tmp_[i] + f_[i] - fe_[i];
      }
      PetscCall(sumResidual());
    }
    tm->assemble += now() - t0;
    return 0;
  };
  // Tangent predictor: one correction of the predictor with the factorisation the last step left behind.
  bool chord = p_.tangent_predictor && !reuse && p_.newton_max_it > 1 && keff_current_ &&
               s->dt_tangent == dt && static_cast<int>(s->u_tangent.size()) == n;
  double ref = 0;
  bool factored = false; // this attempt refactorised (the state's u_tangent no longer matches the solver)
  *ok = true;
  tm->converged = false;
  if (chord) {
    bool adm;
    PetscCall(residual(false, &adm));
    const double r_pred = adm ? norm2(r_) : 0;
    if (!adm || r_pred <= p_.newton_atol) {
      chord = false; // plain Newton from the predictor (its own rejection and convergence logic below)
      for (int i = 0; i < n; ++i) un[i] = up[i] + b * dt * dt * s->a[i];
    } else {
      const double t0 = now();
      PetscCall(solver_->solve(r_.data(), du_.data()));
      for (int i = 0; i < n; ++i) un[i] -= du_[i];
      tm->solve += now() - t0;
      ref = r_pred;
    }
  }
  for (int it = 0;; ++it) {
    // The tangent is assembled with the force (one element loop) at the iterates where another iteration is
    // expected (the first, and as many as the last accepted step needed); at the others the force comes alone
    // first and the tangent only if another iteration follows. Either way the force and tangent are the same.
    const bool fused = !reuse && (it == 0 || it < last_newton_);
    bool admissible;
    PetscCall(residual(fused, &admissible));
    if (!admissible && it == 0 && chord) { // the correction overshot: start Newton from the predictor
      chord = false;
      for (int i = 0; i < n; ++i) un[i] = up[i] + b * dt * dt * s->a[i];
      PetscCall(residual(fused, &admissible));
    }
    if (!admissible) {
      *ok = false;
      reject_reason_ = "an element inverts (det F <= 0) at Newton iteration " + std::to_string(it);
      if (factored) keff_current_ = false;
      PetscFunctionReturn(0);
    }
    const double rn = norm2(r_);
    tm->residual = rn;
    if (it == 0 && !chord) ref = rn; // with the correction: the predictor's residual, as without it
    if (rn <= p_.newton_atol || (it > 0 && rn <= p_.newton_rtol * ref)) {
      tm->converged = true;
      break;
    }
    if (!std::isfinite(rn) || it >= p_.newton_max_it) {
      // Not converged within newton_max_it solves: reject the step (the caller halves dt), never accept.
      *ok = false;
      char why[256];
      std::snprintf(
          why, sizeof why,
          "Newton did not converge in %d iterations (residual %.3e, tolerance max(%.1e, %.1e * %.3e))", it,
          rn, p_.newton_atol, p_.newton_rtol, ref);
      reject_reason_ = why;
      if (factored) keff_current_ = false;
      PetscFunctionReturn(0);
    }
    bool fok = true;
    if (!reuse && !fused) {
      const double t0 = now();
      double e;
      sys_->internalForce(ueval, tmp2_.data(), &Kt_, &e); // same point: admissible, same force
      tm->assemble += now() - t0;
    }
    if (!reuse || factored_dt_ != dt) {
      PetscCall(factorEffective(dt, reuse ? K0_ : Kt_, tm, &fok));
      factored_dt_ = (reuse && fok) ? dt : -1;
      if (!reuse) {
        factored = true, keff_current_ = false;
        if (p_.tangent_predictor) u_factored_.assign(ueval, ueval + n);
      }
    }
    if (!fok) {
      *ok = false;
      reject_reason_ =
          "the effective tangent is not positive definite at Newton iteration " + std::to_string(it);
      PetscFunctionReturn(0);
    }
    const double t0 = now();
    PetscCall(solver_->solve(r_.data(), du_.data()));
    for (int i = 0; i < n; ++i) un[i] -= du_[i];
    tm->solve += now() - t0;
    ++tm->newton_iterations;
    if ((exact_after_one && it == 0) || p_.newton_max_it == 1) {
      tm->converged = exact_after_one;
      break;
    }
  }
  for (int i = 0; i < n; ++i) an[i] = c0 * (un[i] - up[i]), vn[i] = vp[i] + g * dt * an[i];
  s->u.swap(un), s->v.swap(vn), s->a.swap(an);
  s->t += dt;
  last_newton_ = tm->newton_iterations;
  if (factored && p_.tangent_predictor) { // the factorisation left behind is K_eff at u_factored_, dt
    s->u_tangent = u_factored_;
    s->dt_tangent = dt;
    keff_current_ = true;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::restoreTangent(const NewmarkState& s) {
  PetscFunctionBeginUser;
  keff_current_ = false;
  const bool reuse = sys_->isLinear() || p_.initial_jacobian;
  if (!p_.tangent_predictor || reuse || s.u_tangent.size() != static_cast<size_t>(Keff_.n))
    PetscFunctionReturn(0);
  PetscCheck(s.dt_tangent > 0, comm_, PETSC_ERR_ARG_WRONG, "tangent predictor: stored dt %g must be > 0",
             s.dt_tangent);
  double e;
  bool adm = sys_->internalForce(s.u_tangent.data(), tmp2_.data(), &Kt_, &e);
  PetscCall(allAdmissible(&adm));
  PetscCheck(adm, comm_, PETSC_ERR_ARG_WRONG,
             "tangent predictor: the stored tangent point inverts an element");
  StepTimings tm;
  bool ok;
  PetscCall(factorEffective(s.dt_tangent, Kt_, &tm, &ok));
  factored_dt_ = -1;
  keff_current_ = ok;
  PetscFunctionReturn(0);
}

PetscErrorCode Newmark::step(NewmarkState* s, double dt, StepTimings* tm) {
  PetscFunctionBeginUser;
  PetscCheck(dt > 0, comm_, PETSC_ERR_ARG_OUTOFRANGE, "time step -dt %g must be > 0", dt);
  *tm = StepTimings();
  // Substeps: try dt; on rejection halve and do two halves (recursively, up to max_halvings levels).
  struct Frame {
    double dt;
    int level, remaining;
  };
  std::vector<Frame> stack = {{dt, 0, 1}};
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.remaining == 0) {
      stack.pop_back();
      continue;
    }
    const NewmarkState saved = *s;
    bool ok;
    PetscCall(attempt(s, f.dt, tm, &ok));
    if (ok) {
      --f.remaining;
      continue;
    }
    *s = saved;
    ++tm->rejected;
    PetscCheck(
        f.level < p_.max_halvings, comm_, PETSC_ERR_NOT_CONVERGED,
        "Newmark step at t = %g rejected %d times (-max_halvings %d): %s even with dt = %g; reduce -dt "
        "or the load",
        s->t, tm->rejected, p_.max_halvings, reject_reason_.c_str(), f.dt);
    const double half = 0.5 * f.dt;
    const int level = f.level + 1;
    --f.remaining;
    stack.push_back({half, level, 2});
  }
  PetscFunctionReturn(0);
}

double Newmark::kineticEnergy(const NewmarkState& s) const {
  std::vector<double> mv(s.v.size());
  symMultiply(Keff_, M_, s.v.data(), mv.data());
  double e = 0;
  for (size_t i = 0; i < mv.size(); ++i) e += 0.5 * s.v[i] * mv[i];
  return sumScalar(e);
}

double Newmark::strainEnergy(const NewmarkState& s) {
  double e = 0;
  sys_->internalForce(s.u.data(), f_.data(), nullptr, &e);
  return sumScalar(e);
}

PetscErrorCode solveStatic(MPI_Comm comm, SecondOrderSystem* sys, LinearSolver* solver,
                           const std::vector<double>& f_ext, int nsteps, int newton_max_it, double rtol,
                           std::vector<double>* u, StaticResult* res, bool partial_sums) {
  PetscFunctionBeginUser;
  PetscCheck(nsteps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_steps %d must be >= 1", nsteps);
  int rank = 0;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  SymCsc K = sys->pattern();
  const int n = K.n;
  u->assign(n, 0.0);
  std::vector<double> f(n), r(n), du(n);
  const double fnorm = norm2(f_ext);
  *res = StaticResult();
  const int max_it = sys->isLinear() ? 1 : newton_max_it;
  for (int step = 1; step <= nsteps; ++step) {
    const double lam = static_cast<double>(step) / nsteps;
    for (int it = 0;; ++it) {
      double e;
      int adm = sys->internalForce(u->data(), f.data(), &K.val, &e) ? 1 : 0;
      const double ext = partial_sums && rank > 0 ? 0.0 : lam; // the external force counts once
      for (int i = 0; i < n; ++i) r[i] = f[i] - ext * f_ext[i];
      if (partial_sums) {
        PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &adm, 1, MPI_INT, MPI_MIN, comm));
        PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, r.data(), n, MPI_DOUBLE, MPI_SUM, comm));
        PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &e, 1, MPI_DOUBLE, MPI_SUM, comm));
      }
      PetscCheck(adm, comm, PETSC_ERR_NOT_CONVERGED,
                 "static solve: an element inverts (det F <= 0) at load step %d/%d; increase -load_steps",
                 step, nsteps);
      res->residual = norm2(r);
      res->energy = e;
      if (res->residual <= rtol * std::max(fnorm, 1e-300) || it >= max_it) break;
      bool ok;
      PetscCall(solver->factor(K, &ok));
      PetscCheck(ok, comm, PETSC_ERR_MAT_CH_ZRPVT,
                 "static solve: the tangent stiffness is not positive definite at load step %d/%d (is the "
                 "Dirichlet set empty, i.e. the body free to move rigidly?)",
                 step, nsteps);
      PetscCall(solver->solve(r.data(), du.data()));
      for (int i = 0; i < n; ++i) (*u)[i] -= du[i];
      ++res->newton_iterations;
    }
    res->load_steps = step;
  }
  PetscCheck(sys->isLinear() || res->residual <= rtol * std::max(fnorm, 1e-300) * 10, comm,
             PETSC_ERR_NOT_CONVERGED,
             "static Newton did not converge: residual %g after %d iterations per step "
             "(-newton_max_it %d); increase -load_steps",
             res->residual, newton_max_it, newton_max_it);
  PetscFunctionReturn(0);
}

std::vector<suite::Choice> timeSchemeChoices() {
  return {{"newmark", "Newmark (-newmark_beta, -newmark_gamma)"},
          {"generalized_alpha", "generalized-alpha (-rho_inf: high-frequency damping)"}};
}

std::vector<suite::Choice> jacobianChoices() {
  return {{"tangent", "full Newton: the current tangent"}, {"initial", "K0: factorised once per dt"}};
}

std::vector<suite::Choice> predictorChoices() {
  return {{"constant", "Newmark predictor, a_{n+1} = a_n"},
          {"tangent",
           "plus one correction with the last step's factorised effective tangent (full Newton only)"}};
}

std::vector<suite::Choice> massChoices() {
  return {{"consistent", "consistent mass matrix"}, {"lumped", "lumped mass (HRZ)"}};
}

} // namespace suite::fem
