// Newmark-beta with Newton iterations on the displacement increment (Hughes, The Finite Element Method 1987,
// sec. 9.1 and 9.3; Wriggers, Nonlinear FEM 2008, sec. 5.2): u_{n+1} = u~ + beta dt^2 a_{n+1},
// v_{n+1} = v~ + gamma dt a_{n+1}, u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, v~ = v_n + dt (1 - gamma) a_n.
#include "fem/newmark.hpp"

#include "core/clocks.hpp"

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

// One attempt of a step: the predictor u~, v~ (up, vp), the iterate u_{n+1} (un) with its a, v (an, vn).
struct Newmark::Attempt {
  NewmarkState* s = nullptr;
  StepTimings* tm = nullptr;
  double dt = 0, c0 = 0;
  bool alpha = false;           // generalized-alpha: evaluate at the intermediate point (ua_, va_, aa_)
  bool reuse = false;           // K_eff factorised once per dt (linear system or modified Newton)
  bool exact_after_one = false; // linear system: one Newton solve is exact
  std::vector<double> up, vp, un, an, vn;
  const double* ueval = nullptr; // where the force is evaluated: un, or ua_
  bool chord = false;            // the tangent predictor's correction applies
  bool factored = false;    // this attempt refactorised (the state's u_tangent no longer matches the solver)
  double ref = 0;           // the residual the relative Newton test refers to
  bool lagged = false;      // -jacobian lagged: refactorise only when the refresh rule asks
  int lag_its = 0;          // lagged: corrections with the factorisation held now, in this attempt
  int corrections = 0;      // corrections applied in this attempt (the work cap)
  double r_last = 0, q = 0; // |r| of the last iterate and its contraction |r_k| / |r_{k-1}| (0 at k = 0)
  double tol = 0;           // the Newton test's bound max(atol, rtol ref)
};

PetscErrorCode Newmark::attempt(NewmarkState* s, double dt, StepTimings* tm, bool* ok) {
  PetscFunctionBeginUser;
  Attempt a;
  a.s = s, a.tm = tm, a.dt = dt, a.c0 = 1.0 / (p_.beta * dt * dt);
  a.alpha = p_.alpha_m != 0 || p_.alpha_f != 0;
  a.reuse = sys_->isLinear() || p_.initial_jacobian;
  a.exact_after_one = sys_->isLinear();
  a.lagged = p_.lagged && !a.reuse;
  predict(a);
  *ok = true;
  tm->converged = false;
  if (a.chord) PetscCall(correctPredictor(a));
  for (int it = 0;; ++it) {
    // The tangent is assembled with the force (one element loop) at the iterates where another iteration is
    // expected (the first, and as many as the last accepted step needed); at the others the force comes alone
    // first and the tangent only if another iteration follows. Either way the force and tangent are the same.
    // Lagged: the tangent comes with the force only where a refresh is certain (no factorisation for this dt).
    const bool fused = a.lagged ? it == 0 && refreshDue(a) : !a.reuse && (it == 0 || it < last_newton_);
    Verdict v;
    PetscCall(testIterate(a, it, fused, &v));
    if (v == Verdict::iterate) PetscCall(refactorize(a, it, fused, &v));
    if (v == Verdict::converged) break;
    if (v == Verdict::rejected) {
      *ok = false;
      PetscFunctionReturn(0);
    }
    PetscCall(applyCorrection(a));
    ++tm->newton_iterations;
    if (p_.max_corrections > 0 && ++a.corrections >= p_.max_corrections) {
      PetscCall(acceptCapped(a, ok));
      if (!*ok) PetscFunctionReturn(0);
      break;
    }
    if ((a.exact_after_one && it == 0) || p_.newton_max_it == 1) {
      tm->converged = a.exact_after_one;
      break;
    }
  }
  accept(a);
  PetscFunctionReturn(0);
}

// The Newmark predictor (constant acceleration) as the first iterate, the external force at the evaluation
// time, and whether the tangent predictor's correction applies (the solver holds K_eff of the last step, dt).
void Newmark::predict(Attempt& a) {
  const int n = Keff_.n;
  const double b = p_.beta, g = p_.gamma, dt = a.dt, af = p_.alpha_f;
  const NewmarkState* s = a.s;
  a.up.resize(n), a.vp.resize(n), a.un.resize(n), a.an.resize(n), a.vn.resize(n);
  if (a.alpha) ua_.resize(n), va_.resize(n), aa_.resize(n);
  for (int i = 0; i < n; ++i) {
    a.up[i] = s->u[i] + dt * s->v[i] + dt * dt * (0.5 - b) * s->a[i];
    a.vp[i] = s->v[i] + dt * (1 - g) * s->a[i];
    a.un[i] = a.up[i] + b * dt * dt * s->a[i];
  }
  fext_(a.alpha ? s->t + (1 - af) * dt : s->t + dt, fe_.data());
  if (p_.partial_sums && rank_ > 0) std::fill(fe_.begin(), fe_.end(), 0.0);
  a.ueval = a.alpha ? ua_.data() : a.un.data();
  a.chord = p_.tangent_predictor && !a.reuse && !a.lagged && p_.newton_max_it > 1 && keff_current_ &&
            s->dt_tangent == dt && static_cast<int>(s->u_tangent.size()) == n;
}

// Back to the predictor as the iterate (plain Newton without the tangent predictor's correction).
void Newmark::restartFromPredictor(Attempt& a) {
  const int n = Keff_.n;
  const double b = p_.beta, dt = a.dt;
  for (int i = 0; i < n; ++i) a.un[i] = a.up[i] + b * dt * dt * a.s->a[i];
}

// a_{n+1} and v_{n+1} of the iterate.
void Newmark::ratesAt(Attempt& a) {
  const int n = Keff_.n;
  const double g = p_.gamma, dt = a.dt;
  for (int i = 0; i < n; ++i) a.an[i] = a.c0 * (a.un[i] - a.up[i]), a.vn[i] = a.vp[i] + g * dt * a.an[i];
}

// Residual r_ at the iterate un, with the tangent Kt_ when asked (same point, same force); admissibility.
PetscErrorCode Newmark::residualAt(Attempt& a, bool want_tangent, bool* admissible) {
  PetscFunctionBeginUser;
  const int n = Keff_.n;
  const double am = p_.alpha_m, af = p_.alpha_f;
  const NewmarkState* s = a.s;
  const double t0 = now();
  ratesAt(a);
  if (a.alpha)
    for (int i = 0; i < n; ++i) {
      ua_[i] = (1 - af) * a.un[i] + af * s->u[i];
      va_[i] = (1 - af) * a.vn[i] + af * s->v[i];
      aa_[i] = (1 - am) * a.an[i] + am * s->a[i];
    }
  double e;
  *admissible = sys_->internalForce(a.ueval, f_.data(), want_tangent ? &Kt_ : nullptr, &e);
  PetscCall(allAdmissible(admissible));
  if (*admissible) {
    symMultiply(Keff_, M_, a.alpha ? aa_.data() : a.an.data(), tmp_.data());
    if (damped_) {
      symMultiply(Keff_, C_, a.alpha ? va_.data() : a.vn.data(), tmp2_.data());
      for (int i = 0; i < n; ++i) r_[i] = tmp_[i] + tmp2_[i] + f_[i] - fe_[i];
    } else {
      for (int i = 0; i < n; ++i) r_[i] = tmp_[i] + f_[i] - fe_[i];
    }
    PetscCall(sumResidual());
  }
  a.tm->assemble += now() - t0;
  PetscFunctionReturn(0);
}

// Tangent predictor: one correction of the predictor with the factorisation the last step left behind.
PetscErrorCode Newmark::correctPredictor(Attempt& a) {
  PetscFunctionBeginUser;
  bool adm;
  PetscCall(residualAt(a, false, &adm));
  const double r_pred = adm ? norm2(r_) : 0;
  if (!adm || r_pred <= p_.newton_atol) {
    a.chord = false; // plain Newton from the predictor (its own rejection and convergence logic below)
    restartFromPredictor(a);
  } else {
    PetscCall(applyCorrection(a));
    a.ref = r_pred;
  }
  PetscFunctionReturn(0);
}

// The residual at the iterate it (with the tangent when fused); rejected when an element inverts.
PetscErrorCode Newmark::testIterate(Attempt& a, int it, bool fused, Verdict* v) {
  PetscFunctionBeginUser;
  bool admissible;
  PetscCall(residualAt(a, fused, &admissible));
  if (!admissible && it == 0 && a.chord) { // the correction overshot: start Newton from the predictor
    a.chord = false;
    restartFromPredictor(a);
    PetscCall(residualAt(a, fused, &admissible));
  }
  if (!admissible) {
    reject(a, "an element inverts (det F <= 0) at Newton iteration " + std::to_string(it));
    *v = Verdict::rejected;
    PetscFunctionReturn(0);
  }
  *v = convergence(a, it);
  PetscFunctionReturn(0);
}

// The Newton test on the residual r_ of the iterate it: converged, another iteration, or rejected.
Newmark::Verdict Newmark::convergence(Attempt& a, int it) {
  const double rn = norm2(r_);
  a.tm->residual = rn;
  a.q = it > 0 && a.r_last > 0 ? rn / a.r_last : 0;
  a.r_last = rn;
  if (it == 0 && !a.chord) a.ref = rn; // with the correction: the predictor's residual, as without it
  a.tol = std::max(p_.newton_atol, p_.newton_rtol * a.ref);
  if (rn <= p_.newton_atol || (it > 0 && rn <= p_.newton_rtol * a.ref)) {
    a.tm->converged = true;
    return Verdict::converged;
  }
  if (!std::isfinite(rn) || it >= p_.newton_max_it) {
    // Not converged within newton_max_it solves: reject the step (the caller halves dt), never accept.
    char why[256];
    std::snprintf(
        why, sizeof why,
        "Newton did not converge in %d iterations (residual %.3e, tolerance max(%.1e, %.1e * %.3e))", it, rn,
        p_.newton_atol, p_.newton_rtol, a.ref);
    reject(a, why);
    return Verdict::rejected;
  }
  return Verdict::iterate;
}

// K_eff factorised for the correction of iterate it: at every iteration with the tangent at the iterate
// (assembled here when it did not come with the force), once per dt with K0; rejected if not positive
// definite.
PetscErrorCode Newmark::refactorize(Attempt& a, int it, bool fused, Verdict* v) {
  PetscFunctionBeginUser;
  bool ok = true;
  if (a.lagged && !refreshDue(a)) { // the factorisation held serves this correction
    ++a.lag_its;
    PetscFunctionReturn(0);
  }
  if (!a.reuse && !fused) {
    const double t0 = now();
    double e;
    sys_->internalForce(a.ueval, tmp2_.data(), &Kt_, &e); // same point: admissible, same force
    a.tm->assemble += now() - t0;
  }
  if (!a.reuse || factored_dt_ != a.dt) {
    PetscCall(factorEffective(a.dt, a.reuse ? K0_ : Kt_, a.tm, &ok));
    factored_dt_ = (a.reuse && ok) ? a.dt : -1;
    if (!a.reuse) {
      a.factored = true, keff_current_ = false, a.lag_its = 1, refresh_next_ = false;
      if (p_.tangent_predictor || p_.lagged) u_factored_.assign(a.ueval, a.ueval + Keff_.n);
    }
  }
  if (!ok) {
    reject(a, "the effective tangent is not positive definite at Newton iteration " + std::to_string(it));
    *v = Verdict::rejected;
  }
  PetscFunctionReturn(0);
}

// The Newton correction un -= K_eff^{-1} r_ with the factorisation the solver holds.
PetscErrorCode Newmark::applyCorrection(Attempt& a) {
  PetscFunctionBeginUser;
  const int n = Keff_.n;
  const double t0 = now();
  PetscCall(solver_->solve(r_.data(), du_.data()));
  for (int i = 0; i < n; ++i) a.un[i] -= du_[i];
  a.tm->solve += now() - t0;
  PetscFunctionReturn(0);
}

// Lagged: refactorise before this correction? When the solver holds no K_eff for this dt (none yet, or the dt
// changed); after the first correction with the factorisation held, when the last iterate contracted the
// residual by less than refresh_contraction (q = |r_k| / |r_{k-1}|), or when the corrections made with it
// plus those the contraction predicts to reach the Newton test, log(tol / |r_k|) / log(q) (a linearly
// converging chord iteration; Hairer & Wanner, Solving ODEs II, 1996, sec. IV.8), exceed refresh_iterations.
bool Newmark::refreshDue(const Attempt& a) const {
  const bool held = a.factored || (keff_current_ && a.s->dt_tangent == a.dt);
  if (!held || (refresh_next_ && !a.factored)) return true;
  if (a.lag_its == 0) return false;
  if (a.q > p_.refresh_contraction || a.lag_its >= p_.refresh_iterations) return true;
  const double predicted = std::log(a.tol / a.r_last) / std::log(a.q);
  return a.lag_its + predicted > p_.refresh_iterations;
}

// The work cap reached: the residual at the last iterate (one force evaluation) is recorded and the step is
// accepted whether or not it passes the Newton test; rejected only if that iterate inverts an element.
PetscErrorCode Newmark::acceptCapped(Attempt& a, bool* ok) {
  PetscFunctionBeginUser;
  bool admissible;
  PetscCall(residualAt(a, false, &admissible));
  if (!admissible) {
    reject(a, "an element inverts (det F <= 0) at the work cap's last iterate");
    *ok = false;
    PetscFunctionReturn(0);
  }
  const double rn = norm2(r_);
  a.tm->residual = rn;
  a.tm->converged = rn <= p_.newton_atol || rn <= p_.newton_rtol * a.ref;
  a.tm->capped = !a.tm->converged;
  refresh_next_ = a.lagged && a.tm->capped; // the next step starts from a fresh factorisation
  PetscFunctionReturn(0);
}

// A rejected attempt: why, and the solver no longer holds the last step's K_eff if this attempt refactorised.
void Newmark::reject(const Attempt& a, const std::string& why) {
  reject_reason_ = why;
  if (a.factored) keff_current_ = false;
}

// The accepted iterate becomes the state (its a, v from the Newmark relations); the factorisation left behind
// is K_eff at u_factored_, dt for the next step's tangent predictor.
void Newmark::accept(Attempt& a) {
  NewmarkState* s = a.s;
  ratesAt(a);
  s->u.swap(a.un), s->v.swap(a.vn), s->a.swap(a.an);
  s->t += a.dt;
  last_newton_ = a.tm->newton_iterations;
  if (a.factored && (p_.tangent_predictor || p_.lagged)) {
    s->u_tangent = u_factored_;
    s->dt_tangent = a.dt;
    keff_current_ = true;
  }
}

PetscErrorCode Newmark::restoreTangent(const NewmarkState& s) {
  PetscFunctionBeginUser;
  keff_current_ = false;
  const bool reuse = sys_->isLinear() || p_.initial_jacobian;
  if (!(p_.tangent_predictor || p_.lagged) || reuse || s.u_tangent.size() != static_cast<size_t>(Keff_.n))
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

PetscErrorCode Newmark::lowPass(LinearSolver* filter, double wc, const double* e, double* x) {
  PetscFunctionBeginUser;
  if (wc != filter_wc_) {
    SymCsc F = Keff_;
    for (size_t k = 0; k < M_.size(); ++k) F.val[k] = M_[k] + K0_[k] / (wc * wc);
    bool ok;
    PetscCall(filter->factor(F, &ok)); // partial sums: this rank's part (the solver adds)
    PetscCheck(ok, comm_, PETSC_ERR_MAT_CH_ZRPVT, "low-pass filter M + K0 / wc^2 is not positive definite");
    filter_wc_ = wc;
  }
  symMultiply(Keff_, M_, e, r_.data());
  PetscCall(sumResidual()); // partial sums: M is this rank's part
  PetscCall(filter->solve(r_.data(), x));
  PetscFunctionReturn(0);
}

double Newmark::massNorm(const double* x) const {
  std::vector<double> mx(Keff_.n);
  symMultiply(Keff_, M_, x, mx.data());
  double e = 0;
  for (int i = 0; i < Keff_.n; ++i) e += x[i] * mx[i];
  return std::sqrt(std::max(0.0, sumScalar(e)));
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
  return {{"tangent", "full Newton: the current tangent"},
          {"initial", "K0: factorised once per dt"},
          {"lagged", "modified Newton: the last factorised tangent, refreshed by -lagged_refresh_contraction "
                     "and -lagged_refresh_iterations"}};
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
