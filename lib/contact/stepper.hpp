// Velocity-level time stepping of rigid bodies with unilateral contacts and dry friction, one LCP / box LCP
// per step solved by lib/lcp: Stewart & Trinkle 1996, Anitescu & Potra 1997, in the box-MLCP and
// operator-splitting forms of Lacoursiere, "Splitting methods for dry frictional contact problems in rigid
// multibody systems" (SIGRAD 2003), with Baumgarte stabilisation of the normal constraints.
//
// Per step (semi-implicit Euler): v* = v + dt g;  impulses lambda solve
//   w = A lambda + b,  A = J M^-1 J^T (+ reg diag(A), a compliance as in SPOOK),  b = J v* + c,   c_n =
//   phi/dt (phi >= 0, a gap closes in one step) or beta phi/dt (phi < 0, penetration), c_t = 0; normal rows:
//   0 <= lambda_n _|_ w_n >= 0;  tangent rows: box bounds -mu nu <= lambda_t <= mu nu;
// then v = v* + M^-1 J^T lambda, x += dt v, q <- exp(dt w / 2) q. Restitution is 0.
// The friction model builds the problem from A and b: friction_formulation.hpp (one file per model).
// Tangent rows with zero bound (mu = 0, or zero estimated normal force) are left out of the problem.
#pragma once

#include "contact/collision.hpp"
#include "contact/delassus.hpp"
#include "contact/joint.hpp"
#include "contact/joint_actuation.hpp"
#include "contact/joint_system.hpp"
#include "contact/phase_times.hpp"
#include "core/named_choice.hpp"
#include "lcp/problem.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace suite::contact {

enum class FrictionModel { None = 0, Box = 1, ScaledBox = 2, Splitting = 3, Polyhedral = 4, Auto = 5 };
const char* frictionName(FrictionModel m);
std::vector<std::string> frictionNames();
bool frictionFromName(const std::string& name, FrictionModel* m);

enum class SplitStart { Zero = 0, Infinite = 1, Previous = 2 };
const char* splitStartName(SplitStart s);
bool splitStartFromName(const std::string& name, SplitStart* s);
std::vector<Choice> splitStartChoices(); // the -splitting_start choices

// -contact_accuracy (contact_accuracy.hpp): exact (every problem solved to the acceptance rule, fallbacks,
// a failed step ends the run) or a per-step budget of PGS sweeps (balanced, fast) after which the step goes
// on with its errors recorded.
enum class ContactAccuracy { Exact = 0, Balanced = 1, Fast = 2 };
const char* accuracyName(ContactAccuracy a);
bool accuracyFromName(const std::string& name, ContactAccuracy* a);
std::vector<Choice> accuracyChoices();

class FrictionFormulation;
class JointSystem;
class AutoFriction;
struct Island;

struct StepperOptions {
  double dt = 0.01;
  Vec3 gravity = Vec3(0, 0, -9.81);
  double mu = 0.5;
  FrictionModel friction = FrictionModel::Splitting;
  // bpp: no failure on the incline/rest/drop problems at any splitting start (lemke, keller, murty,
  // fb_newton, cottle_dantzig, pgs_block failed on some), and the fewest iterations. "auto": the LCP
  // portfolio's chain for the problem's class (lcp::solveWithChain expands it, lcp/portfolio.hpp); the solver
  // that succeeded is StepStats::solver (/steps/solver).
  std::string lcp_solver = "bpp";
  std::vector<std::string> fallback_solvers = {"lemke", "smoothed_newton"};
  // Acceptance: natural-map residual <= lcp_tol (1 + |b|_inf) (m/s): 1e-8 is far below what the time
  // step resolves, and heap problems often end at 1e-10..1e-9 where the library's default 1e-10 rejects them.
  double lcp_tol = 1e-8;
  int lcp_max_iterations = 0; // cap of the primary solver (0: its default); fallbacks use theirs
  double baumgarte = 0.2;     // beta in (0, 1]
  // Compliance added as reg * A_ii to the diagonal: normal rows (makes the load distribution over
  // coplanar contacts unique; velocity error reg * A_nn lambda_n, corrected by Baumgarte) and tangent rows.
  double regularisation = 1e-6;
  double regularisation_t = 1e-8;
  double margin = 1e-3; // contacts are generated for phi < margin
  SplitStart split_start = SplitStart::Previous;
  int splitting_max_it = 50;
  // on max A_nn |delta lambda_n| (m/s), relative to 1 m/s + max A_nn lambda_n; 4e-8 m/s at 1 kg boxes (A_nn 4 to
  // 8 kg^-1) is about 1e-8 N s in impulses: the same passes and cone violations on pile_grid as that rule
  double splitting_tol = 4e-8;
  int polyhedral_directions = 8;
  // Polyhedral: solver chain (Lemke, the accurate reference, first; the Newton methods when round-off in a
  // long pivot sequence ends Lemke on a false secondary ray) and the symmetric diagonal scaling of the LCP
  // (lambda_n, beta rows by 1/sqrt(A_ii), gamma rows by the mean sqrt(A_bb) of their contact) that
  // equilibrates it before pivoting. Every answer is verified on the unscaled problem.
  std::vector<std::string> polyhedral_solvers = {"lemke", "lemke_rf", "smoothed_newton", "fb_newton"};
  bool polyhedral_scaling = true;
  // Compliance eps_i = polyhedral_gamma_reg / mean(A_bb) on the diagonal of the cone rows: w_gamma = mu
  // lambda_n - e^T beta + eps gamma, which makes the LCP matrix strictly copositive (z^T M z = x^T A x + mu
  // gamma^T lambda_n + eps |gamma|^2 > 0 for z >= 0, z != 0), so Lemke cannot end on a secondary ray in exact
  // arithmetic for any q; without it, round-off ended Lemke on false rays on the log heap. It lets the friction
  // exceed the polygon by eps * slip speed (relative cone violation ~ 0.3 eps on the log heap).
  double polyhedral_gamma_reg = 1e-8;
  bool warm_start = true;
  ContactAccuracy accuracy = ContactAccuracy::Exact;
  // balanced / fast: Baumgarte factor of their normal rows (instead of baumgarte). An unconverged answer leaves
  // penetrations of ~1e-3 m whose bias beta phi / dt changes b by up to 0.02 m/s from step to step, more than the
  // sweeps remove; 0.05 keeps that feedback below their error (measured, contact_accuracy.hpp).
  double budget_baumgarte = 0.05;
  int contact_sweeps =
      0; // balanced / fast: PGS sweeps per step (0: the mode's default, contact_accuracy.hpp)
  // exact: problems of more rows than this use the sparse Delassus matrix and the sparse solvers
  // (sparse_box_lcp.hpp) first, the dense chain as their fallback; at most this many rows, the dense path
  // only. Measured (scripts/bench/contact-crossover, ms per step dense / sparse): box_stack 5 (60 rows)
  // 0.068 / 0.088, pyramid 3 (108) 0.23 / 0.15, box_stack 10 (120) 0.25 / 0.20, pyramid 5 (300) 2.2 / 0.56.
  int dense_max_rows = 100;
  // Sleeping (off by default): a dynamic body whose |v| + |w| r stays below sleep_velocity for sleep_steps
  // steps sleeps: it is not integrated and acts as a static body in the contacts of awake bodies; contacts
  // between sleeping (or sleeping and static) bodies are not solved. It wakes when an awake dynamic body
  // touches it.
  bool sleep = false;
  double sleep_velocity = 1e-3;
  int sleep_steps = 20;
  // Islands (islands.hpp): each step's contacts split into independent islands, each solved as its own
  // problem by the same formulation, solver chain and acceptance; off: one problem of the whole scene (the
  // results before islands, bitwise). Off by default: islands change the answer within the LCP tolerance
  // (each island's problem is accepted on its own residual, splitting passes per island), so every existing
  // reference result and checkpoint stays bitwise valid; on (-contact_islands on) spreads them over ranks.
  bool islands = false;
  // -friction auto (friction_auto.hpp): the cone violation each problem's model must meet.
  double target_error = 1e-3;
  // Joints (joint_system.hpp): the position projection ends at max |Phi| <= joint_tol (m; unit-vector dot
  // products for the axis rows) or after joint_max_projections Newton iterations; SHAKE takes at most as many.
  // A projection that ends above kJointFailure joint_tol fails the step (StepStats::retry_smaller_dt: the app
  // retries it at half dt, see docs/contact.md); 0 projections: none, the drift is recorded. 30: the 200-link
  // chain falling from horizontal at dt = 0.01 (tip rotations of order 1 rad per step) needed up to 20 damped
  // Newton iterations (measured), 10 left 1.3e-2 m.
  double joint_tol = 1e-11;
  int joint_max_projections = 30;
  static constexpr double kJointFailure = 1e3;
};

// Runs tasks 0..n-1 (solve(k)) and returns every result at its index; "" or an error message. The default
// runs them in order on the caller; the contact app deals them over MPI ranks (core/task_dealer.hpp).
using TaskSolveFn = std::function<std::vector<double>(int)>;
using TaskRunner =
    std::function<std::string(int n, const TaskSolveFn& solve, std::vector<std::vector<double>>*)>;

// What one step did.
struct StepStats {
  int contacts = 0;
  int rows = 0;                // size of the (last) problem solved
  double force_ratio = 0.0;    // sum over body pairs |sum tangential impulse| / sum normal impulse
  double cone_violation = 0.0; // sum_i max(0, |lambda_t,i| - mu lambda_n,i) / sum lambda_n
  double normal_impulse = 0.0; // sum lambda_n
  std::string solver;          // solver that produced the accepted answer (fallback name if it was needed)
  int fallbacks = 0;           // failed attempts before the accepted one
  int proximal_steps = 0;      // sparse path: proximal steps after a stalled exchange (sparse_box_lcp.hpp)
  int iterations = 0;          // solver iterations (summed over splitting passes)
  long long pivots = 0;
  int refinements = 0;   // active-set refinements of solver answers (contact side, after the solver)
  double residual = 0.0; // natural-map residual (max over passes)
  int splitting_iterations = 0;
  double splitting_error = 0.0;     // last max A_nn |delta lambda_n| (m/s; box_lcp.hpp solveBoxPass)
  std::vector<double> split_errors; // per pass: max A_nn |delta lambda_n| (pass 1: max A_nn lambda_n)
  std::vector<double> split_ratios; // force ratio after each pass
  int sleeping = 0;                 // bodies asleep during this step
  int factorizations = 0;   // sparse active-set solves: each a numeric factorisation of its free set or,
                            // within 16 rows of the last one, a low-rank update (body_space_solve.hpp)
  double penetration = 0.0; // max(0, -phi) over the step's contacts (m)
  bool budget_stop = false; // balanced / fast: the sweeps ended at the budget, not the tolerance
  // Islands (StepperOptions::islands): how many were solved (0: islands off or no contact), the largest one's
  // dynamic bodies and contacts. With islands, rows is the sum over the islands, iterations, pivots,
  // fallbacks, proximal_steps, refinements and factorizations are summed, residual and splitting_error are
  // the largest, split_errors the largest per pass, split_ratios and solver those of the largest island
  // (solver: of the first island that needed a fallback, if any).
  int islands = 0;
  int largest_island_bodies = 0;
  int largest_island_contacts = 0;
  // -friction auto (friction_auto.hpp): the highest ladder rung used (-1: another model or no contact), the
  // rung solves tried, the problems whose best rung missed the target, and per problem (one per island, or
  // the whole scene; islands in order) the rung, its LCP rows, the wall time of all its rung solves (s) and
  // its cone violation.
  int friction_rung = -1;
  int auto_solves = 0;
  int target_missed = 0;
  std::vector<double> problem_rungs, problem_rows, problem_times, problem_violations;
  // Joints: their rows, the SHAKE iterations of the velocities (-1: SHAKE stopped contracting and the step kept
  // the velocity projection alone, joint_system.hpp), the largest |Phi| after the position
  // projection (m, see joint_system.hpp) and its Newton iterations, and the largest |G v| of the step's end
  // velocities at the projected poses (m/s).
  // actuation_solves: the solves of the step's velocities (more than 1: the limits' and motors' active set
  // changed, joint_actuation.hpp).
  int joint_rows = 0;
  int actuation_solves = 0;
  int shake_iterations = 0;
  double joint_error = 0.0;
  int projection_iterations = 0;
  double joint_velocity_error = 0.0;
  bool failed = false;
  bool retry_smaller_dt = false; // failed where a smaller step may succeed: the joints' position projection
  std::string message;           // failure: which solver, status, why
};

class Stepper {
public:
  explicit Stepper(StepperOptions o);
  const StepperOptions& options() const { return o_; }
  // Advances the bodies by one step. On failure (every solver failed, or a non-finite state) the bodies
  // are left unchanged and stats.failed is set; lastProblem() is the problem that failed.
  StepStats step(std::vector<Body>* bodies);
  const std::vector<Contact>& contacts() const { return contacts_; }
  // Impulses of the last step per contact: (normal, t1, t2).
  const std::vector<Vec3>& impulses() const { return impulses_; }
  // The problems of the last step: every one (one per splitting pass) with keepProblems(true), else the
  // last one solved or attempted.
  const std::vector<lcp::Problem>& lastProblems() const { return problems_; }
  void keepProblems(bool on) { keep_problems_ = on; }
  // Everything of the stepper that the next step depends on, for checkpoint/restart (bitwise): per body
  // [still steps, asleep] (nb x 2) and per contact of the last step [a, b, p (3), impulse (3)] (nc x 8),
  // whose impulses warm-start the solvers and give scaled_box / splitting their estimates.
  void exportState(int nbodies, std::vector<double>* body_state, std::vector<double>* contact_state) const;
  // Throws std::runtime_error on inconsistent sizes or body indices.
  void importState(int nbodies, const std::vector<double>& body_state,
                   const std::vector<double>& contact_state);
  // -friction auto's part of that state: the rung of each contact of the last step (nc), then the count of
  // steps (the probe schedule); import throws unless it matches the imported contacts (importState first).
  void exportAutoState(std::vector<double>* state) const;
  void importAutoState(const std::vector<double>& state);
  // Persistent identity of each contact of the last step: the id of the previous step's contact it was
  // matched to (same body pair, nearest point within 0.1 of the smaller bounding radius), else a new one.
  // Not part of the checkpoint (renumbered after a restart; the physics does not depend on them).
  const std::vector<long long>& contactIds() const { return ids_; }
  // The accepted solution z of the last problem solved (lastProblems().back() when the step succeeded).
  // With islands: empty, unless keepProblems(true) (then the last island's).
  const lcp::Vec& lastSolution() const { return solution_; }
  // How the islands of a step are run (default: in order, on this process).
  void setTaskRunner(TaskRunner runner) { runner_ = std::move(runner); }
  // Wall time per phase of the steps so far on this process (phase_times.hpp).
  const PhaseTimes& phaseTimes() const { return phases_; }
  // The time step of the next steps (the app's retry of a failed step at half dt).
  void setDt(double dt);
  // The joints among the bodies (joint.hpp); contacts between two bodies a joint connects are not generated.
  // Throws std::runtime_error for what the joint path does not support (see stepper.cpp).
  void setJoints(std::vector<Joint> joints);
  const std::vector<Joint>& joints() const { return joints_; }
  // Per joint: the force and the torque (about the joint's anchor on a) that the joint exerted on its body a
  // over the last step (impulse / dt; N, N m).
  void jointReaction(int joint, const std::vector<Body>& bodies, Vec3* force, Vec3* torque) const;
  // The motor's power over the last step (W; 0 without a motor): its force (torque) times the rate it drove.
  double motorPower(int joint) const;

private:
  StepStats stepBodies(std::vector<Body>* bodies);
  bool finishJoints(std::vector<Body>* next, const JointSystem& js, StepStats* st);
  bool solveVelocities(const std::vector<Body>& bodies, std::vector<Vec3>* v, std::vector<Vec3>* w,
                       std::vector<Vec3>* lam, StepStats* st, std::unique_ptr<JointSystem>* js,
                       Eigen::VectorXd* jlam);
  void matchPreviousImpulses(const std::vector<Body>& bodies, std::vector<Vec3>* prev,
                             std::vector<bool>* has_prev, std::vector<int>* prev_rung);
  bool solveContacts(const std::vector<Body>& bodies, std::vector<Vec3>* v, std::vector<Vec3>* w,
                     std::vector<Vec3>* lam, StepStats* st);
  // The contacts of one problem with their previous impulses (and -friction auto rungs, -1: none).
  struct ProblemInput {
    const std::vector<Contact>& cs;
    const std::vector<Vec3>& prev;
    const std::vector<bool>& has_prev;
    const std::vector<int>& prev_rung;
    const std::vector<int>* global = nullptr; // an island's problem: the global index of each body
  };
  // The contacts among bodies as one problem: impulses lam, applied to v, w; problems / solution as
  // ChainSolve keeps them (keep_problems_). -friction auto: solveAuto (friction_auto.cpp).
  bool solveProblem(const std::vector<Body>& bodies, const ProblemInput& in, std::vector<Vec3>* v,
                    std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st,
                    std::vector<lcp::Problem>* problems, lcp::Vec* solution) const;
  // ... with one friction formulation and its options.
  lcp::Vec jointCoupling(const DelassusSystem& sys, const lcp::Vec& z, const std::vector<int>* global) const;
  bool solveModel(const FrictionFormulation& form, const StepperOptions& o, const std::vector<Body>& bodies,
                  const ProblemInput& in, std::vector<Vec3>* v, std::vector<Vec3>* w, std::vector<Vec3>* lam,
                  StepStats* st, std::vector<lcp::Problem>* problems, lcp::Vec* solution) const;
  bool solveAuto(const std::vector<Body>& bodies, const ProblemInput& in, std::vector<Vec3>* v,
                 std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st,
                 std::vector<lcp::Problem>* problems, lcp::Vec* solution) const;
  // The same per island (stepper_islands.cpp), the islands run by runner_.
  struct IslandInput {
    const std::vector<Vec3>& prev;
    const std::vector<bool>& has_prev;
    const std::vector<int>& prev_rung;
    const std::vector<Vec3>& v;
    const std::vector<Vec3>& w;
  };
  std::vector<double> solveIsland(const std::vector<Body>& bodies, const Island& isl, const IslandInput& in,
                                  std::vector<lcp::Problem>* problems, lcp::Vec* solution) const;
  void failedIsland(const std::vector<Body>& bodies, const std::vector<Island>& islands,
                    const IslandInput& in, int k, const std::vector<double>& result, StepStats* st);
  bool solveIslands(const std::vector<Body>& bodies, const std::vector<Vec3>& prev,
                    const std::vector<bool>& has_prev, const std::vector<int>& prev_rung,
                    std::vector<Vec3>* v, std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st);
  TaskRunner runner_;
  PhaseTimes phases_;
  StepperOptions o_;
  std::shared_ptr<const FrictionFormulation> form_;
  std::shared_ptr<const AutoFriction> auto_; // -friction auto (form_ is null then)
  std::vector<int> rungs_, prev_rungs_;      // -friction auto: the rung of each contact (this / last step)
  long long steps_done_ = 0;                 // successful steps (auto's probe schedule)
  std::vector<int> still_;
  std::vector<char> asleep_;
  std::vector<Contact> contacts_;
  std::vector<Vec3> impulses_;
  std::vector<Contact> prev_contacts_;
  std::vector<Vec3> prev_impulses_;
  std::vector<long long> ids_, prev_ids_; // persistent contact identities (contactIds())
  long long next_id_ = 0;
  std::vector<lcp::Problem> problems_;
  std::vector<Joint> joints_;
  std::vector<std::pair<int, int>> joined_;             // the body pairs a joint connects (sorted)
  std::vector<JRow> joint_rows_;                        // the last step's joint rows (at its start) ...
  std::vector<int> joint_first_;                        // ... the first row of each joint ...
  Eigen::VectorXd joint_impulse_;                       // ... and their impulses
  const JointSystem* joint_sys_ = nullptr;              // during a step: its joint block
  JointActuation actuation_;                            // the joints' limits and motors
  JointFactorization joint_factor_, projection_factor_; // their symbolic analyses kept from step to step
  lcp::Vec solution_;
  bool keep_problems_ = false;
};

// Total mechanical energy sum(0.5 m v^2 + 0.5 w^T I w - m g.x) of the dynamic bodies.
double mechanicalEnergy(const std::vector<Body>& bodies, const Vec3& gravity);
// Sum over body pairs of |sum of tangential impulse vectors| / sum of normal impulses (ratio), the cone
// violation sum_i max(0, |lambda_t,i| - mu lambda_n,i) / sum lambda_n, and sum lambda_n (normal).
void forceMeasures(const std::vector<Contact>& cs, const std::vector<Vec3>& lam, double mu, double* ratio,
                   double* violation, double* normal);
// The model simplifications a run with these options makes on these bodies (one line, for output and log).
std::string simplifications(const StepperOptions& o, const std::vector<Body>& bodies);

} // namespace suite::contact
