// Options of the contact app (see contact_options.hpp).
#include "contact_options.hpp"
#include "contact_size_check.hpp"

#include "contact/friction_formulation.hpp"
#include "contact/lemke_rf.hpp"
#include "core/named_choice.hpp"
#include "core/option_value.hpp"

#include <algorithm>
#include <cmath>

namespace contact_app {

namespace {

// One-line option declarations inside the PetscOptionsBegin/End block (each documented by -help).
struct Reader {
  PetscOptionItems* po;
  PetscErrorCode real(const char* name, const char* text, double* v, bool* given = nullptr) const {
    PetscBool set = PETSC_FALSE;
    PetscFunctionBeginUser;
    PetscCall(suite::optionsReal(po, name, text, nullptr, *v, v, &set));
    if (given) *given = set;
    PetscFunctionReturn(0);
  }
  template <class I> PetscErrorCode integer(const char* name, const char* text, I* v) const {
    PetscInt x = (PetscInt)*v;
    PetscFunctionBeginUser;
    PetscCall(suite::optionsInt(po, name, text, nullptr, x, &x, nullptr));
    *v = (I)x;
    PetscFunctionReturn(0);
  }
  PetscErrorCode boolean(const char* name, const char* text, bool* v) const {
    PetscBool x = *v ? PETSC_TRUE : PETSC_FALSE;
    PetscFunctionBeginUser;
    PetscCall(suite::optionsBool(po, name, text, nullptr, x, &x, nullptr));
    *v = x;
    PetscFunctionReturn(0);
  }
  PetscErrorCode string(const char* name, const char* text, std::string* v) const {
    return suite::optionsString(po, name, text, v);
  }
  // A list of solvers (contactSolverChoices); 'none' entries are dropped ('none' alone: the empty list).
  PetscErrorCode solvers(const char* name, const char* text, bool none, std::vector<std::string>* v) const {
    std::vector<suite::Choice> choices = contactSolverChoices();
    PetscFunctionBeginUser;
    if (none) choices.push_back({"none", "no solver (alone: the empty list)"});
    PetscCall(suite::optionsChoiceList(po, name, text, choices, v));
    v->erase(std::remove(v->begin(), v->end(), "none"), v->end());
    PetscFunctionReturn(0);
  }
};

PetscErrorCode sceneOptions(const Reader& r, SceneParams* s) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(r.po, "-scene", "Scene", sceneChoices(), &s->scene));
  PetscCall(r.string("-scene_file",
                     "Scene file for -scene file (format: docs/contact.md#scene-file-format) or -scene mjcf "
                     "(an MJCF model, docs/contact.md#mjcf-models)",
                     &s->file));
  PetscCall(r.real("-theta", "Incline angle (degrees)", &s->theta_deg));
  PetscCall(r.real("-size", "Box edge / sphere diameter (m)", &s->size));
  PetscCall(r.real("-density", "Density (kg/m^3)", &s->density));
  PetscCall(r.real("-mass", "Mass of the incline/drop body (kg, 0: from density)", &s->mass));
  PetscCall(r.real("-v0", "Initial speed (incline: downhill, drop: along x)", &s->v0));
  PetscCall(r.real("-height", "Drop: initial gap (m)", &s->height));
  PetscCall(r.real("-tilt", "Drop: initial rotation about x (degrees)", &s->tilt_deg));
  PetscCall(r.real("-spin", "Drop: initial angular velocity about y (rad/s)", &s->spin));
  PetscCall(r.string("-drop_body", "Drop: sphere, box, capsule, cylinder", &s->drop_body));
  PetscCall(r.integer("-stack_height", "box_stack: number of boxes", &s->stack_height));
  PetscCall(r.integer("-pyramid_base", "pyramid, pile_grid: boxes in the bottom row", &s->pyramid_base));
  PetscCall(r.integer("-piles", "pile_grid: number of pyramids", &s->piles));
  PetscCall(r.integer("-n_logs", "log_heap: number of logs", &s->n_logs));
  PetscCall(r.real("-log_radius", "log_heap: log radius (m)", &s->log_radius));
  PetscCall(r.real("-log_length", "log_heap: log length (m)", &s->log_length));
  PetscCall(r.integer("-seed", "log_heap: random seed", &s->seed));
  PetscCall(r.integer("-links", "chain: number of links", &s->links));
  PetscCall(suite::optionsChoice(r.po, "-joint_type", "chain: joint between links",
                                 {{"hinge", "about y (planar motion)"}, {"ball", "spherical"}},
                                 &s->joint_type));
  PetscCall(r.real("-angle",
                   "pendulum, double_pendulum, chain, motor_limit: release angle from the downward vertical "
                   "(degrees)",
                   &s->angle_deg));
  PetscCall(r.real("-end_mass_ratio", "chain: end sphere's mass / a link's mass (0: no end sphere)",
                   &s->end_mass_ratio));
  PetscCall(r.real("-link_length", "pendulum, double_pendulum, chain: joint spacing (m)", &s->link_length));
  PetscCall(r.real("-link_radius",
                   "pendulum, double_pendulum, chain, four_bar, slider_crank: capsule radius (m)",
                   &s->link_radius));
  PetscCall(r.real("-link_mass", "pendulum, double_pendulum, chain, four_bar, slider_crank: link mass (kg)",
                   &s->link_mass));
  PetscCall(r.real("-crank_length", "four_bar, slider_crank: crank length (m)", &s->crank_length));
  PetscCall(r.real("-coupler_length", "four_bar: coupler length; slider_crank: rod length (m)",
                   &s->coupler_length));
  PetscCall(r.real("-rocker_length", "four_bar: rocker length (m)", &s->rocker_length));
  PetscCall(r.real("-ground_length", "four_bar: distance between the ground pivots (m)", &s->ground_length));
  PetscCall(r.real("-crank_angle", "four_bar, slider_crank: initial crank angle from +x towards +z (degrees)",
                   &s->crank_angle_deg));
  PetscCall(r.real("-crank_speed", "four_bar, slider_crank: initial crank speed (rad/s)", &s->crank_speed));
  PetscCall(r.integer("-bridge_boxes", "rope_bridge: boxes dropped onto the bridge", &s->bridge_boxes));
  PetscCall(r.real("-ball_radius", "wrecking_ball: the end sphere's radius and the cubes' edge (m)",
                   &s->ball_radius));
  PetscCall(r.real("-sag_angle", "rope_bridge: the planks' angle from the horizontal (degrees)",
                   &s->sag_angle_deg));
  PetscCall(r.real("-limit_angle", "motor_limit: the hinge's limits about the start pose (+-, degrees)",
                   &s->limit_angle_deg));
  PetscCall(r.real("-motor_speed", "motor_limit: the motor's target speed (rad/s, > 0 raises the link)",
                   &s->motor_speed));
  PetscCall(r.real("-motor_torque", "motor_limit: the motor's torque bound (N m)", &s->motor_torque));
  PetscFunctionReturn(0);
}

// Friction model and the LCP solvers.
PetscErrorCode frictionOptions(const Reader& r, MPI_Comm comm, StepperOptions* t, ModelOverrides* given) {
  std::string friction = frictionName(t->friction);
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(r.po, "-friction", "Friction model", frictionChoices(), &friction));
  PetscCheck(frictionFromName(friction, &t->friction), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-friction %s: unknown friction model", friction.c_str());
  PetscCall(r.real("-mu", "Friction coefficient (-scene mjcf: overrides the file's geom friction)", &t->mu,
                   &given->mu));
  PetscBool target_set = PETSC_FALSE;
  PetscCall(suite::optionsReal(r.po, "-target_error",
                               "-friction auto: largest cone violation sum max(0, |l_t| - mu l_n) / sum l_n "
                               "of each problem",
                               nullptr, t->target_error, &t->target_error, &target_set));
  PetscCheck(!target_set || t->friction == FrictionModel::Auto, comm, PETSC_ERR_ARG_WRONG,
             "-target_error: needs -friction auto (given with -friction %s)", friction.c_str());
  std::vector<suite::Choice> primary = contactSolverChoices();
  primary.push_back({"auto",
                     "the portfolio (lib/lcp/portfolio): the measured chain of the problem's class, each "
                     "answer verified, then -fallback_solvers"});
  PetscCall(suite::optionsChoice(r.po, "-lcp_solver", "LCP solver", primary, &t->lcp_solver));
  PetscCall(
      r.solvers("-fallback_solvers", "Solvers tried when the solver fails", true, &t->fallback_solvers));
  PetscCall(r.real("-lcp_tol", "Acceptance: natural-map residual <= tol (1 + |q|_inf)", &t->lcp_tol));
  PetscCall(r.integer("-lcp_max_iterations", "Iteration cap of the primary LCP solver (0: its default)",
                      &t->lcp_max_iterations));
  PetscCall(r.solvers("-polyhedral_solvers",
                      "Polyhedral: solver chain, first the reference (each answer verified)", false,
                      &t->polyhedral_solvers));
  PetscCheck(!t->polyhedral_solvers.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-polyhedral_solvers: needs at least one solver");
  PetscFunctionReturn(0);
}

// The speed/accuracy trade (contact_accuracy.hpp) and the dense/sparse crossover.
PetscErrorCode accuracyOptions(const Reader& r, MPI_Comm comm, StepperOptions* t) {
  std::string acc = accuracyName(t->accuracy);
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(r.po, "-contact_accuracy", "Contact accuracy (speed/accuracy trade)",
                                 accuracyChoices(), &acc));
  PetscCheck(accuracyFromName(acc, &t->accuracy), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-contact_accuracy %s: unknown", acc.c_str());
  PetscCall(
      r.integer("-contact_sweeps",
                "balanced/fast: PGS sweeps per step (0: the mode's default, growing with the pile height)",
                &t->contact_sweeps));
  PetscCall(r.real("-contact_budget_baumgarte", "balanced/fast: Baumgarte factor (0, 1] of their normal rows",
                   &t->budget_baumgarte));
  PetscCall(r.integer("-contact_dense_max_rows",
                      "exact: dense contact problems up to this many rows, sparse above",
                      &t->dense_max_rows));
  std::string islands = t->islands ? "on" : "off";
  PetscCall(suite::optionsChoice(
      r.po, "-contact_islands", "Solve each island of contacts as its own problem, islands dealt over ranks",
      {{"on", "one problem per island (lib/contact/islands.hpp), dealt over ranks"},
       {"off", "one problem of the whole scene, on every rank"}},
      &islands));
  t->islands = islands == "on";
  const bool cone = t->friction == FrictionModel::Polyhedral || t->friction == FrictionModel::Auto;
  PetscCheck(t->accuracy == ContactAccuracy::Exact || !cone, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-contact_accuracy %s: needs -friction none, box, scaled_box or splitting", acc.c_str());
  PetscFunctionReturn(0);
}

// Integration, stabilisation, splitting, polyhedral cone and sleeping.
PetscErrorCode stepperOptions(const Reader& r, MPI_Comm comm, StepperOptions* t, ModelOverrides* given) {
  std::string start = splitStartName(t->split_start);
  double g = 9.81;
  PetscFunctionBeginUser;
  PetscCall(
      r.real("-dt", "Time step (s; -scene mjcf: overrides the file's option timestep)", &t->dt, &given->dt));
  PetscCall(r.real("-gravity", "Gravity (m/s^2, along -z; -scene mjcf: overrides the file's option gravity)",
                   &g, &given->gravity));
  t->gravity = Vec3(0, 0, -g);
  PetscCall(r.real("-baumgarte", "Baumgarte factor for penetration (0, 1]", &t->baumgarte));
  PetscCall(r.real("-regularisation", "Relative compliance of the normal rows", &t->regularisation));
  PetscCall(r.real("-regularisation_t", "Relative compliance of the tangent rows", &t->regularisation_t));
  PetscCall(r.real("-margin", "Contact margin (m)", &t->margin));
  PetscCall(suite::optionsChoice(r.po, "-splitting_start", "Splitting: first estimate of the normal impulse",
                                 splitStartChoices(), &start));
  PetscCheck(splitStartFromName(start, &t->split_start), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-splitting_start %s: unknown", start.c_str());
  PetscCall(r.integer("-splitting_max_it", "Splitting: pass cap", &t->splitting_max_it));
  PetscCall(r.real("-splitting_tol",
                   "Splitting: tolerance on the normal velocity change max A_nn |delta lambda_n|, relative "
                   "to 1 m/s + max A_nn lambda_n",
                   &t->splitting_tol));
  PetscCall(r.integer("-polyhedral_directions", "Polyhedral: friction directions per contact",
                      &t->polyhedral_directions));
  PetscCall(r.real("-polyhedral_gamma_reg", "Polyhedral: compliance of the cone rows (x 1/A_tt)",
                   &t->polyhedral_gamma_reg));
  PetscCall(r.boolean("-polyhedral_scaling", "Polyhedral: equilibrate the LCP before solving",
                      &t->polyhedral_scaling));
  PetscCall(r.boolean("-sleep", "Put bodies at rest to sleep (not integrated, their contacts not solved)",
                      &t->sleep));
  PetscCall(r.real("-sleep_velocity", "Sleep: speed |v| + |w| r below which a body is at rest (m/s)",
                   &t->sleep_velocity));
  PetscCall(r.integer("-sleep_steps", "Sleep: steps at rest before sleeping", &t->sleep_steps));
  PetscCall(r.real("-joint_tol", "Joints: position projection until max |Phi| <= tol (m)", &t->joint_tol));
  PetscCall(r.integer("-joint_max_projections", "Joints: most Newton iterations of the position projection",
                      &t->joint_max_projections));
  PetscFunctionReturn(0);
}

PetscErrorCode runOptions(const Reader& r, AppOptions* o) {
  PetscFunctionBeginUser;
  PetscCall(r.integer("-steps", "Number of steps", &o->steps));
  PetscCall(r.real("-overlap_tol", "Largest allowed overlap of static bodies (m)", &o->overlap_tol));
  PetscCall(r.integer("-output_every", "Frame interval in steps", &o->output_every));
  PetscCall(r.string("-output", "HDF5 output file", &o->output));
  PetscCall(r.string("-write_mjcf",
                     "Write the scene (with the run's -dt, -gravity, -mu) as an MJCF model to this file and "
                     "exit without stepping (MuJoCo loads it; docs/contact.md#mjcf-models)",
                     &o->write_mjcf));
  PetscCall(
      r.string("-dump_problems", "Prefix: every contact problem -> PREFIX_step<N>_pass<K>.h5", &o->dump));
  PetscCall(r.integer("-dump_max", "Most problems dumped", &o->dump_max));
  PetscCall(r.boolean("-contact_phase_times", "Print each rank's wall time per step phase at the end",
                      &o->phase_times));
  PetscFunctionReturn(0);
}

// A numeric option's range check: lo < (or <=) value < (or <=) hi; hi = inf reads "must be > lo" (">= lo"), and
// an open infinite bound rejects inf. NaN fails every range.
struct Range {
  const char* option;
  double value;
  char lo_bracket; // '(' open, '[' closed
  double lo, hi;
  char hi_bracket; // ')' open, ']' closed
  bool integer = false;
};

PetscErrorCode checkRange(MPI_Comm comm, const Range& c) {
  const bool ok = (c.lo_bracket == '(' ? c.value > c.lo : c.value >= c.lo) &&
                  (c.hi_bracket == ')' ? c.value < c.hi : c.value <= c.hi);
  char value[64], rule[64];
  std::snprintf(value, sizeof value, c.integer ? "%.0f" : "%g", c.value);
  if (std::isinf(c.hi))
    std::snprintf(rule, sizeof rule, c.lo_bracket == '(' ? "> %g" : ">= %g", c.lo);
  else
    std::snprintf(rule, sizeof rule, "in %c%g, %g%c", c.lo_bracket, c.lo, c.hi, c.hi_bracket);
  PetscFunctionBeginUser;
  PetscCheck(ok, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: must be %s", c.option, value, rule);
  PetscFunctionReturn(0);
}

PetscErrorCode checkRanges(MPI_Comm comm, const AppOptions& o) {
  const StepperOptions& t = o.step;
  const double inf = INFINITY;
  const Range ranges[] = {
      {"-lcp_tol", t.lcp_tol, '(', 0, 1, ')'},
      {"-mu", t.mu, '[', 0, inf, ')'},
      {"-target_error", t.target_error, '(', 0, inf, ')'},
      {"-dt", t.dt, '(', 0, inf, ')'},
      {"-steps", (double)o.steps, '[', 0, inf, ']', true},
      {"-gravity", -t.gravity.z(), '[', 0, inf, ')'},
      {"-baumgarte", t.baumgarte, '(', 0, 1, ']'},
      {"-regularisation", t.regularisation, '[', 0, inf, ']'},
      {"-regularisation_t", t.regularisation_t, '[', 0, inf, ']'},
      {"-margin", t.margin, '[', 0, inf, ']'},
      {"-splitting_max_it", (double)t.splitting_max_it, '[', 1, inf, ']', true},
      {"-splitting_tol", t.splitting_tol, '(', 0, inf, ']'},
      {"-polyhedral_directions", (double)t.polyhedral_directions, '[', 3, inf, ']', true},
      {"-output_every", (double)o.output_every, '[', 1, inf, ']', true},
      {"-sleep_velocity", t.sleep_velocity, '(', 0, inf, ']'},
      {"-sleep_steps", (double)t.sleep_steps, '[', 1, inf, ']', true},
      {"-overlap_tol", o.overlap_tol, '[', 0, inf, ']'},
      {"-contact_sweeps", (double)t.contact_sweeps, '[', 0, inf, ']', true},
      {"-contact_budget_baumgarte", t.budget_baumgarte, '(', 0, 1, ']'},
      {"-contact_dense_max_rows", (double)t.dense_max_rows, '[', 0, inf, ']', true},
      {"-joint_tol", t.joint_tol, '(', 0, inf, ')'},
      {"-joint_max_projections", (double)t.joint_max_projections, '[', 0, inf, ']', true},
  };
  PetscFunctionBeginUser;
  for (const Range& c : ranges) PetscCall(checkRange(comm, c));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readOptions(MPI_Comm comm, AppOptions* o) {
  PetscFunctionBeginUser;
  PetscCall(checkIntegerOptions(comm));
  PetscOptionsBegin(comm, nullptr, "Contact app options", nullptr);
  const Reader r{PetscOptionsObject};
  PetscCall(sceneOptions(r, &o->scene));
  PetscCall(frictionOptions(r, comm, &o->step, &o->given));
  PetscCall(stepperOptions(r, comm, &o->step, &o->given));
  PetscCall(accuracyOptions(r, comm, &o->step));
  PetscCall(runOptions(r, o));
  PetscOptionsEnd();
  PetscCall(checkRanges(comm, *o));
  PetscFunctionReturn(0);
}

} // namespace contact_app
