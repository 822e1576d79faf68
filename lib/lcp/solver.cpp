// Verified solve (acceptance rule, active-set refinement), the chain of solvers with a fallback, and the
// helpers shared by the LCP solvers.
#include "lcp/solver.hpp"

#include "lcp/portfolio.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>

namespace suite::lcp {

const char* statusName(Status s) {
  switch (s) {
  case Status::Solved:
    return "solved";
  case Status::MaxIterations:
    return "max_iterations";
  case Status::RayTermination:
    return "ray_termination";
  case Status::Breakdown:
    return "breakdown";
  case Status::Unsupported:
    return "unsupported";
  case Status::NotAccepted:
    return "not_accepted";
  case Status::InvalidInput:
    return "invalid_input";
  case Status::NumericalError:
    return "numerical_error";
  }
  return "?";
}

double signTolerance(const Problem& p) {
  return 1e-13 * (1.0 + p.q.lpNorm<Eigen::Infinity>());
}

void evaluate(const Problem& p, Result* r) {
  if (r->z.size() != p.size()) {
    r->z = Vec::Zero(p.size());
    r->w = p.q;
    r->residual = kInf;
    r->complementarity = kInf;
    return;
  }
  r->w = slack(p, r->z);
  r->residual = naturalResidual(p, r->z, r->w);
  r->complementarity = complementarity(p, r->z, r->w);
}

std::vector<State> initialStates(const Problem& p, const Vec* warm) {
  const int n = p.size();
  std::vector<State> st(n, State::Free);
  for (int i = 0; i < n; ++i) {
    const bool lf = std::isfinite(p.l[i]), uf = std::isfinite(p.u[i]);
    if (warm && warm->size() == n) {
      const double z = (*warm)[i];
      if (lf && z <= p.l[i])
        st[i] = State::Lower;
      else if (uf && z >= p.u[i])
        st[i] = State::Upper;
      else
        st[i] = State::Free;
    } else {
      st[i] = lf ? State::Lower : (uf ? State::Upper : State::Free);
    }
  }
  return st;
}

bool isSymmetric(const Mat& M) {
  // 16 x 16 tiles: the transposed accesses stay in cache (a plain double loop strides over whole columns).
  const int n = static_cast<int>(M.rows());
  if (M.cols() != n) return false;
  constexpr int T = 16;
  for (int jb = 0; jb < n; jb += T)
    for (int ib = jb; ib < n; ib += T) {
      const int je = std::min(n, jb + T), ie = std::min(n, ib + T);
      for (int j = jb; j < je; ++j)
        for (int i = std::max(ib, j + 1); i < ie; ++i)
          if (M(i, j) != M(j, i)) return false;
    }
  return true;
}

bool solveStates(const Problem& p, const std::vector<State>& st, Vec* z, bool symmetric) {
  const int n = p.size();
  z->resize(n);
  std::vector<int> F, N;
  F.reserve(n);
  N.reserve(n);
  for (int i = 0; i < n; ++i) {
    if (st[i] == State::Free) {
      F.push_back(i);
    } else {
      N.push_back(i);
      (*z)[i] = st[i] == State::Lower ? p.l[i] : p.u[i];
    }
  }
  if (F.empty()) return true;
  const int k = static_cast<int>(F.size());
  const Mat A = p.M(F, F);
  Vec b;
  if (N.empty()) {
    b = -p.q(F);
  } else { // t = q + M z_N (z_F = 0): one contiguous matrix-vector product instead of gathering M_FN
    Vec zn = Vec::Zero(n);
    for (int j : N) zn[j] = (*z)[j];
    const Vec t = p.M * zn + p.q;
    b = -t(F);
  }
  Vec x;
  bool done = false;
  if (symmetric) {
    Eigen::LLT<Mat> llt(A);
    if (llt.info() == Eigen::Success) {
      const auto d = llt.matrixLLT().diagonal();
      if (d.minCoeff() > 1e-7 * d.maxCoeff()) { // cond(A) = (max/min)^2 <~ 1e14
        x = llt.solve(b);
        x += llt.solve(b - A * x);
        done = true;
      }
    }
  }
  if (!done) {
    Eigen::PartialPivLU<Mat> lu(A);
    const double rc = lu.rcond();
    if (!(rc > 1e-14)) return false;
    x = lu.solve(b);
    x += lu.solve(b - A * x); // one step of iterative refinement
  }
  if (!x.allFinite()) return false;
  for (int a = 0; a < k; ++a) (*z)[F[a]] = x[a];
  return true;
}

bool isSymmetric(const Problem& p) {
  return p.symmetric >= 0 ? p.symmetric == 1 : isSymmetric(p.M);
}

std::vector<State> statesFromSolution(const Problem& p, const Vec& z, const Vec& w) {
  const int n = p.size();
  std::vector<State> st(n);
  for (int i = 0; i < n; ++i) {
    const double t = z[i] - w[i];
    if (t <= p.l[i])
      st[i] = State::Lower;
    else if (t >= p.u[i])
      st[i] = State::Upper;
    else
      st[i] = State::Free;
  }
  return st;
}

Result solve(const Solver& s, const Problem& p, const SolverOptions& opt) {
  const double t0 = opt.timed ? MPI_Wtime() : 0.0;
  timespec c0{}, c1{};
  if (opt.timed) clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
  Result r;
  try {
    r = s.run(p, opt);
  } catch (const std::exception& e) {
    r = Result{};
    r.status = Status::NumericalError;
    r.message = e.what();
  }
  evaluate(p, &r);
  const double tol = acceptanceTolerance(p, opt.rel_tol);
  if (r.status == Status::Solved && !(r.residual <= tol) && opt.refine && std::isfinite(r.residual)) {
    // Active-set refinement: the method found (approximately) the right index sets; solve exactly on them.
    for (int k = 0; k < 3 && !(r.residual <= tol); ++k) {
      Vec z;
      if (!solveStates(p, statesFromSolution(p, r.z, r.w), &z)) break;
      Result t = r;
      t.z = z;
      evaluate(p, &t);
      ++r.refinements;
      if (!(t.residual < r.residual)) break;
      t.refinements = r.refinements;
      r = t;
    }
  }
  if (r.status == Status::Solved && !(r.residual <= tol)) {
    r.status = Status::NotAccepted;
    if (r.message.empty()) r.message = "residual above the acceptance tolerance";
  }
  if (r.status == Status::Solved && !r.z.allFinite()) r.status = Status::NumericalError;
  if (!opt.timed) return r;
  r.time = MPI_Wtime() - t0;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
  r.cpu_time =
      static_cast<double>(c1.tv_sec - c0.tv_sec) + 1e-9 * static_cast<double>(c1.tv_nsec - c0.tv_nsec);
  return r;
}

namespace {

// diag(s) M diag(s), diag(s) q, [l, u] / s: the problem in z' = z / s.
Problem scaledProblem(const Problem& p, const Vec& s) {
  Problem ps = p;
  ps.M = s.asDiagonal() * p.M * s.asDiagonal();
  ps.q = s.cwiseProduct(p.q);
  ps.l = p.l.cwiseQuotient(s);
  ps.u = p.u.cwiseQuotient(s);
  return ps;
}

// At most max exact solves on the index sets read off r (each kept only if it lowers the residual on p):
// they repair the round-off a long pivot sequence leaves. Returns how many were kept.
int refineOnStates(const Problem& p, double tol, int max, Result* r) {
  int kept = 0;
  for (int k = 0; k < max && !(r->residual <= tol); ++k) {
    Result t = *r;
    if (!solveStates(p, statesFromSolution(p, r->z, r->w), &t.z)) break;
    evaluate(p, &t);
    if (!(t.residual < r->residual)) break;
    *r = t;
    ++kept;
  }
  return kept;
}

// One solver on `solved` (p itself, or its scaled form when sc is given), its answer mapped back to p,
// refined and verified there.
Result attempt(const Solver& s, const Problem& p, const Problem& solved, const Vec* sc, bool first,
               const ChainOptions& o, double tol, Attempt* a) {
  SolverOptions so;
  so.rel_tol = sc ? o.scaled_tol_factor * o.rel_tol : o.rel_tol;
  so.timed = o.timed;
  if (first) so.max_iterations = o.first_max_iterations;
  Vec warm;
  if (o.warm_start && o.warm_start->size() == p.size() && o.warm_start->allFinite()) {
    warm = sc ? Vec(o.warm_start->cwiseQuotient(*sc)) : *o.warm_start;
    so.warm_start = &warm;
  }
  Result r = solve(s, solved, so);
  if (sc && r.z.size() == p.size() && r.z.allFinite()) { // back to the original problem
    r.z = sc->cwiseProduct(r.z);
    evaluate(p, &r);
  }
  finishAttempt(p, o, tol, &r, a);
  return r;
}

} // namespace

void finishAttempt(const Problem& p, const ChainOptions& o, double tol, Result* r, Attempt* a) {
  a->status = r->status;
  a->iterations = r->iterations;
  a->pivots = r->pivots;
  const bool finite = r->z.size() == p.size() && r->z.allFinite();
  if (finite) a->refinements = refineOnStates(p, tol, o.refinements, r);
  a->residual = r->residual;
  a->message = r->message;
  a->accepted = finite && r->residual <= tol;
}

Result attemptOn(const Solver& s, const Problem& p, bool first, const ChainOptions& o, double tol,
                 Attempt* a) {
  return attempt(s, p, p, nullptr, first, o, tol, a);
}

// The chain with each "auto" replaced by the built-in portfolio's chain of p's class and its completion of the
// solver families (portfolio.hpp), solvers already named left out.
static std::vector<std::string> expandAuto(const Problem& p, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    const std::vector<std::string> one{n};
    for (const std::string& s :
         n == "auto" ? completeFamilies(builtinPortfolio().chainFor(classify(p).class_index)) : one)
      if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  }
  return out;
}

Result solveWithChain(const Problem& p, const std::vector<std::string>& chain, const ChainOptions& o,
                      std::vector<Attempt>* attempts) {
  const bool has_auto = std::any_of(chain.begin(), chain.end(),
                                    [](const std::string& s) { return s.size() == 4 && s == "auto"; });
  const std::vector<std::string> expanded = has_auto ? expandAuto(p, chain) : std::vector<std::string>();
  const std::vector<std::string>& names = has_auto ? expanded : chain; // no copy without "auto"
  std::vector<Attempt> local;
  std::vector<Attempt>& att = attempts ? *attempts : local;
  const int forms = o.scale ? 2 : 1;
  att.clear();
  att.reserve(names.size() * forms);
  const Problem ps = o.scale ? scaledProblem(p, *o.scale) : Problem();
  const double tol = acceptanceTolerance(p, o.rel_tol);
  Result r;
  for (size_t k = 0; k < names.size(); ++k) {
    const std::unique_ptr<Solver> made = o.make ? o.make(names[k]) : nullptr;
    const Solver* s = o.make ? made.get() : registeredSolver(names[k]);
    for (int f = 0; f < forms; ++f) {
      att.emplace_back();
      Attempt& a = att.back();
      a.solver = names[k];
      a.form = !o.scale ? Form::Plain : f == 0 ? Form::Scaled : Form::Unscaled;
      a.known = s != nullptr;
      if (s) r = attempt(*s, p, f == 0 && o.scale ? ps : p, f == 0 ? o.scale : nullptr, k == 0, o, tol, &a);
      if (a.accepted) {
        r.status = Status::Solved;
        return r;
      }
    }
  }
  if (r.status == Status::Solved) r.status = Status::NotAccepted;
  return r;
}

std::string describeAttempts(const std::vector<Attempt>& attempts) {
  std::ostringstream why;
  for (const Attempt& a : attempts) {
    if (a.accepted) continue;
    why << a.solver;
    if (!a.known) {
      why << ": unknown solver; ";
      continue;
    }
    why << (a.form == Form::Scaled     ? " (scaled)"
            : a.form == Form::Unscaled ? " (unscaled)"
                                       : "")
        << ": " << statusName(a.status) << " (residual " << a.residual
        << (a.message.empty() ? "" : ", " + a.message) << "); ";
  }
  return why.str();
}

} // namespace suite::lcp
