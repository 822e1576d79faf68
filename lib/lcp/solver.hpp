// Solver interface and registry of the LCP library: every solver returns z, w, a status, iteration and
// pivot counts and the natural-map residual; solve() verifies the answer (acceptance rule of problem.hpp)
// so that a solver can never report a wrong answer as solved; solveWithChain() tries a chain of solvers (the
// next one when an answer fails the acceptance rule on the original problem).
//
// Adding a solver: one file in lib/lcp/solvers/ defining `std::unique_ptr<Solver> makeXxx()`, plus one
// line in registry.cpp.
#pragma once

#include "lcp/problem.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace suite::lcp {

enum class Status : int {
  Solved = 0,
  MaxIterations = 1,  // iteration / pivot cap reached
  RayTermination = 2, // Lemke / Cottle-Dantzig: secondary ray (no solution found, e.g. infeasible LCP)
  Breakdown = 3,      // zero or tiny pivot, singular block, cycling guard: the method cannot handle it
  Unsupported = 4,    // problem class outside the method's domain (e.g. M_ii <= 0 for PGS)
  NotAccepted = 5,    // the method stopped but the verified residual is above the acceptance tolerance
  InvalidInput = 6,   // the problem failed validation (recorded by the batch driver)
  NumericalError = 7, // NaN/Inf during the iteration
};
const char* statusName(Status s);

struct SolverOptions {
  int max_iterations = 0;          // 0: the solver's default cap
  double rel_tol = 1e-10;          // acceptance: residual <= rel_tol (1 + ||q||_inf)
  const Vec* warm_start = nullptr; // initial z (ignored by methods without warm start, e.g. Lemke)
  double omega = 1.0;              // PGS relaxation
  int block_size = 3;              // block PGS
  bool refine = true;              // final active-set refinement of a claimed solution (see solve())
  // Fill Result::time / cpu_time. The thread CPU clock costs ~1 us a call (a system call), as much as a whole
  // solve of a small problem: callers that time a sequence of solves themselves (solveAuto) turn it off.
  bool timed = true;
};

struct Result {
  Vec z, w;
  Status status = Status::NumericalError;
  int iterations = 0;     // major iterations (Newton steps, block iterations, sweeps, pivots for pivoting)
  long long pivots = 0;   // basis / index-set changes (0 for Newton and splitting methods)
  int refinements = 0;    // exact active-set solves added by solve()
  double residual = kInf; // natural-map residual of the returned z
  double complementarity = kInf;
  double time = 0.0;     // wall seconds (filled by solve())
  double cpu_time = 0.0; // CPU seconds of the calling thread (filled by solve(); robust on a loaded machine)
  std::string message;   // reason of a failure
  bool ok() const { return status == Status::Solved; }
};

class Solver {
public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;
  // The raw method: fills z (and optionally w), status, iterations, pivots. Called through solve().
  virtual Result run(const Problem& p, const SolverOptions& opt) const = 0;
};

// Registry by name (registry.cpp).
std::vector<std::string> solverNames();
// Every registered solver with its one-line description (for -help), in registry order.
struct SolverInfo {
  std::string name, description;
};
std::vector<SolverInfo> solverRegistry();
// nullptr if the name is unknown.
std::unique_ptr<Solver> makeSolver(const std::string& name);
// The registry's shared instance of a solver (the solvers hold no state: run() is const), nullptr if the name
// is unknown; solveWithChain uses it to create no solver per attempt.
const Solver* registeredSolver(const std::string& name);

// Runs the solver, recomputes w = Mz + q, residual and complementarity, optionally refines a claimed
// solution by exact solves on its active set (at most 3, counted in Result::refinements), and accepts
// only when residual <= tolerance; a claimed solution above the tolerance becomes NotAccepted.
Result solve(const Solver& s, const Problem& p, const SolverOptions& opt = {});

// ---- a chain of solvers: each answer verified on the original problem, the next solver on failure ----
// How an attempt saw the problem: as given (no scaling in the chain), scaled, or unscaled after the scaled one.
enum class Form { Plain, Scaled, Unscaled };

// One attempt of solveWithChain.
struct Attempt {
  std::string solver;
  Form form = Form::Plain;
  bool known = true;                      // false: no such solver (not tried, not a fallback)
  bool accepted = false;                  // its answer met the acceptance rule on the original problem
  Status status = Status::NumericalError; // the method's own status (from solve())
  double residual =
      kInf; // natural-map residual on the original problem (of the solved form if z is not finite)
  std::string message;
  int iterations = 0;
  long long pivots = 0;
  int refinements = 0; // active-set refinements on the original problem after the method
};

struct ChainOptions {
  double rel_tol = 1e-10;       // acceptance on the ORIGINAL problem: residual <= rel_tol (1 + ||q||_inf)
  int first_max_iterations = 0; // iteration cap of the chain's first solver (0: its default); others: theirs
  const Vec* warm_start = nullptr; // initial z of every solver (left out if its size or values are unusable)
  // Scaling s (z = diag(s) z'): each solver first on diag(s) M diag(s), diag(s) q, [l, u] / s, solved to
  // rel_tol * scaled_tol_factor (the natural-map residual is not scale invariant), then on the original.
  const Vec* scale = nullptr;
  double scaled_tol_factor = 1e-3;
  int refinements = 2; // active-set refinements of a finite answer on the original problem (kept if better)
  bool timed = true;   // SolverOptions::timed of every attempt
  std::function<std::unique_ptr<Solver>(const std::string&)> make; // solver factory (empty: makeSolver)
};

// Tries the named solvers in turn with solve() and returns the first answer whose natural-map residual on p
// meets the acceptance rule, with status Solved even when the method reported another one (seen: Lemke
// 'ray_termination' with residual 1e-14); when none does, the last attempt's result, never Solved.
// A name "auto" stands for the built-in portfolio's chain of p's class (portfolio.hpp; the entry point of the
// portfolio for the chain's users, e.g. the contact app's solver chains).
// attempts (optional): every attempt in order.
Result solveWithChain(const Problem& p, const std::vector<std::string>& names, const ChainOptions& o,
                      std::vector<Attempt>* attempts = nullptr);
// One attempt of a chain on p as given (no scaling; o.scale is not read): solve() with o's options (the
// iteration cap o.first_max_iterations when first), refinement on p, acceptance when residual <= tol; fills
// a but a->solver. solveWithChain's step, for callers running their own chain (solveAuto).
Result attemptOn(const Solver& s, const Problem& p, bool first, const ChainOptions& o, double tol,
                 Attempt* a);
// The rest of such an attempt once solve() has returned r (the answer on p): the method's status and counts
// into a, refinement on p (at most o.refinements exact solves, each kept only if it lowers the residual),
// acceptance when r's residual <= tol; fills a but a->solver. solveAuto calls it only when solve() did not
// accept the first solver's answer itself (solve() accepts by the same rule, without the refinements).
void finishAttempt(const Problem& p, const ChainOptions& o, double tol, Result* r, Attempt* a);
// The failed attempts in one line: "name[ (scaled| (unscaled)]: status (residual r[, message]); " each.
std::string describeAttempts(const std::vector<Attempt>& attempts);

// ---- helpers shared by the solvers ----
// Index states of the active-set methods: z at lower bound, at upper bound, or free (w = 0).
enum class State : signed char { Lower = 0, Upper = 1, Free = 2 };
// Initial states: from a warm start (free if strictly inside, else at the nearer bound) or, without one,
// at l if finite, else at u if finite, else free.
std::vector<State> initialStates(const Problem& p, const Vec* warm);
// z for the given states: z_L = l, z_U = u, z_F solving M_FF z_F = -(q_F + M_FN z_N) by LU.
// Returns false if M_FF is singular (rcond below 1e-14 or non-finite result). symmetric: M is symmetric, try
// a Cholesky factorisation first (half the flops of LU), LU if M_FF is not positive definite.
bool solveStates(const Problem& p, const std::vector<State>& st, Vec* z, bool symmetric = false);
// M == M^T exactly?
bool isSymmetric(const Mat& M);
// p.symmetric when known, else isSymmetric(p.M).
bool isSymmetric(const Problem& p);
// States read off an approximate solution: t = z - w <= l -> Lower, >= u -> Upper, else Free.
std::vector<State> statesFromSolution(const Problem& p, const Vec& z, const Vec& w);
// Fills w, residual, complementarity of r.z.
void evaluate(const Problem& p, Result* r);
// Default tolerance for sign tests of the pivoting methods: 1e-13 (1 + ||q||_inf).
double signTolerance(const Problem& p);

} // namespace suite::lcp
