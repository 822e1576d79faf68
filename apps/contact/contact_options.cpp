// Options of the contact app (see contact_options.hpp).
#include "contact_options.hpp"

#include "contact/friction_formulation.hpp"
#include "contact/lemke_rf.hpp"
#include "core/named_choice.hpp"
#include "lcp/solver.hpp"

#include <cmath>
#include <sstream>

namespace contact_app {

namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> v;
  std::stringstream ss(s);
  std::string tok;
  while (std::getline(ss, tok, ','))
    if (!tok.empty() && tok != "none") v.push_back(tok);
  return v;
}

std::string joinList(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// An int option through PetscInt.
PetscErrorCode optionInt(PetscOptionItems* PetscOptionsObject, const char* name, const char* text, int* v) {
  PetscInt x = *v;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt(name, text, nullptr, x, &x, nullptr));
  *v = (int)x;
  PetscFunctionReturn(0);
}

// A string option through a buffer.
PetscErrorCode optionString(PetscOptionItems* PetscOptionsObject, const char* name, const char* text,
                            std::string* v) {
  char buf[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buf, v->c_str(), sizeof buf));
  PetscCall(PetscOptionsString(name, text, nullptr, buf, buf, sizeof buf, nullptr));
  *v = buf;
  PetscFunctionReturn(0);
}

PetscErrorCode sceneOptions(PetscOptionItems* PetscOptionsObject, SceneParams* s) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-scene", "Scene", sceneChoices(), &s->scene));
  PetscCall(optionString(PetscOptionsObject, "-scene_file",
                         "Scene file for -scene file (format: lib/contact/scenes.hpp)", &s->file));
  PetscCall(
      PetscOptionsReal("-theta", "Incline angle (degrees)", nullptr, s->theta_deg, &s->theta_deg, nullptr));
  PetscCall(PetscOptionsReal("-size", "Box edge / sphere diameter (m)", nullptr, s->size, &s->size, nullptr));
  PetscCall(PetscOptionsReal("-density", "Density (kg/m^3)", nullptr, s->density, &s->density, nullptr));
  PetscCall(PetscOptionsReal("-mass", "Mass of the incline/drop body (kg, 0: from density)", nullptr, s->mass,
                             &s->mass, nullptr));
  PetscCall(PetscOptionsReal("-v0", "Initial speed (incline: downhill, drop: along x)", nullptr, s->v0,
                             &s->v0, nullptr));
  PetscCall(PetscOptionsReal("-height", "Drop: initial gap (m)", nullptr, s->height, &s->height, nullptr));
  PetscCall(PetscOptionsReal("-tilt", "Drop: initial rotation about x (degrees)", nullptr, s->tilt_deg,
                             &s->tilt_deg, nullptr));
  PetscCall(PetscOptionsReal("-spin", "Drop: initial angular velocity about y (rad/s)", nullptr, s->spin,
                             &s->spin, nullptr));
  PetscCall(
      optionString(PetscOptionsObject, "-drop_body", "Drop: sphere, box, capsule, cylinder", &s->drop_body));
  PetscCall(optionInt(PetscOptionsObject, "-stack_height", "box_stack: number of boxes", &s->stack_height));
  PetscCall(
      optionInt(PetscOptionsObject, "-pyramid_base", "pyramid: boxes in the bottom row", &s->pyramid_base));
  PetscCall(optionInt(PetscOptionsObject, "-n_logs", "log_heap: number of logs", &s->n_logs));
  PetscCall(PetscOptionsReal("-log_radius", "log_heap: log radius (m)", nullptr, s->log_radius,
                             &s->log_radius, nullptr));
  PetscCall(PetscOptionsReal("-log_length", "log_heap: log length (m)", nullptr, s->log_length,
                             &s->log_length, nullptr));
  PetscInt seed = (PetscInt)s->seed;
  PetscCall(PetscOptionsInt("-seed", "log_heap: random seed", nullptr, seed, &seed, nullptr));
  s->seed = (unsigned)seed;
  PetscFunctionReturn(0);
}

// Friction model and the LCP solvers.
PetscErrorCode frictionOptions(PetscOptionItems* PetscOptionsObject, MPI_Comm comm, StepperOptions* t) {
  std::string friction = frictionName(t->friction), fallback = joinList(t->fallback_solvers),
              poly = joinList(t->polyhedral_solvers);
  PetscFunctionBeginUser;
  PetscCall(
      suite::optionsChoice(PetscOptionsObject, "-friction", "Friction model", frictionChoices(), &friction));
  PetscCheck(frictionFromName(friction, &t->friction), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-friction %s: unknown friction model", friction.c_str());
  PetscCall(PetscOptionsReal("-mu", "Friction coefficient", nullptr, t->mu, &t->mu, nullptr));
  PetscCall(optionString(PetscOptionsObject, "-lcp_solver", "LCP solver (lib/lcp registry)", &t->lcp_solver));
  PetscCall(optionString(PetscOptionsObject, "-fallback_solvers",
                         "Comma list tried when the solver fails ('none': stop)", &fallback));
  PetscCall(PetscOptionsReal("-lcp_tol", "Acceptance: natural-map residual <= tol (1 + |q|_inf)", nullptr,
                             t->lcp_tol, &t->lcp_tol, nullptr));
  PetscCall(optionInt(PetscOptionsObject, "-lcp_max_iterations",
                      "Iteration cap of the primary LCP solver (0: its default)", &t->lcp_max_iterations));
  t->fallback_solvers = splitList(fallback);
  PetscCall(optionString(PetscOptionsObject, "-polyhedral_solvers",
                         "Polyhedral: solver chain, first the reference (each answer verified)", &poly));
  t->polyhedral_solvers = splitList(poly);
  PetscFunctionReturn(0);
}

// Integration, stabilisation, splitting, polyhedral cone and sleeping.
PetscErrorCode stepperOptions(PetscOptionItems* PetscOptionsObject, MPI_Comm comm, StepperOptions* t) {
  std::string start = splitStartName(t->split_start);
  PetscReal g = 9.81;
  PetscBool poly_scaling = t->polyhedral_scaling ? PETSC_TRUE : PETSC_FALSE,
            sleep = t->sleep ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-dt", "Time step (s)", nullptr, t->dt, &t->dt, nullptr));
  PetscCall(PetscOptionsReal("-gravity", "Gravity (m/s^2, along -z)", nullptr, g, &g, nullptr));
  t->gravity = Vec3(0, 0, -g);
  PetscCall(PetscOptionsReal("-baumgarte", "Baumgarte factor for penetration (0, 1]", nullptr, t->baumgarte,
                             &t->baumgarte, nullptr));
  PetscCall(PetscOptionsReal("-regularisation", "Relative compliance of the normal rows", nullptr,
                             t->regularisation, &t->regularisation, nullptr));
  PetscCall(PetscOptionsReal("-regularisation_t", "Relative compliance of the tangent rows", nullptr,
                             t->regularisation_t, &t->regularisation_t, nullptr));
  PetscCall(PetscOptionsReal("-margin", "Contact margin (m)", nullptr, t->margin, &t->margin, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-splitting_start",
                                 "Splitting: first estimate of the normal impulse", splitStartChoices(),
                                 &start));
  PetscCheck(splitStartFromName(start, &t->split_start), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-splitting_start %s: unknown", start.c_str());
  PetscCall(optionInt(PetscOptionsObject, "-splitting_max_it", "Splitting: pass cap", &t->splitting_max_it));
  PetscCall(PetscOptionsReal("-splitting_tol", "Splitting: relative tolerance on max|delta lambda_n|",
                             nullptr, t->splitting_tol, &t->splitting_tol, nullptr));
  PetscCall(optionInt(PetscOptionsObject, "-polyhedral_directions",
                      "Polyhedral: friction directions per contact", &t->polyhedral_directions));
  PetscCall(PetscOptionsReal("-polyhedral_gamma_reg", "Polyhedral: compliance of the cone rows (x 1/A_tt)",
                             nullptr, t->polyhedral_gamma_reg, &t->polyhedral_gamma_reg, nullptr));
  PetscCall(PetscOptionsBool("-polyhedral_scaling", "Polyhedral: equilibrate the LCP before solving", nullptr,
                             poly_scaling, &poly_scaling, nullptr));
  t->polyhedral_scaling = poly_scaling;
  PetscCall(PetscOptionsBool("-sleep",
                             "Put bodies at rest to sleep (not integrated, their contacts not solved)",
                             nullptr, sleep, &sleep, nullptr));
  t->sleep = sleep;
  PetscCall(PetscOptionsReal("-sleep_velocity",
                             "Sleep: speed |v| + |w| r below which a body is at rest (m/s)", nullptr,
                             t->sleep_velocity, &t->sleep_velocity, nullptr));
  PetscCall(
      optionInt(PetscOptionsObject, "-sleep_steps", "Sleep: steps at rest before sleeping", &t->sleep_steps));
  PetscFunctionReturn(0);
}

PetscErrorCode runOptions(PetscOptionItems* PetscOptionsObject, AppOptions* o) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt("-steps", "Number of steps", nullptr, o->steps, &o->steps, nullptr));
  PetscCall(PetscOptionsReal("-overlap_tol", "Largest allowed overlap of static bodies (m)", nullptr,
                             o->overlap_tol, &o->overlap_tol, nullptr));
  PetscCall(PetscOptionsInt("-output_every", "Frame interval in steps", nullptr, o->output_every,
                            &o->output_every, nullptr));
  PetscCall(PetscOptionsString("-output", "HDF5 output file", nullptr, o->output, o->output, sizeof o->output,
                               nullptr));
  PetscCall(PetscOptionsString("-dump_problems", "Prefix: every contact problem -> PREFIX_step<N>_pass<K>.h5",
                               nullptr, o->dump, o->dump, sizeof o->dump, nullptr));
  PetscCall(
      PetscOptionsInt("-dump_max", "Most problems dumped", nullptr, o->dump_max, &o->dump_max, nullptr));
  PetscFunctionReturn(0);
}

// Every solver name known (lib/lcp's registry or the contact library's own).
PetscErrorCode checkSolvers(MPI_Comm comm, const StepperOptions& t) {
  std::string names;
  PetscFunctionBeginUser;
  for (auto& n : suite::lcp::solverNames()) names += (names.empty() ? "" : ", ") + n;
  PetscCheck(makeContactSolver(t.lcp_solver) != nullptr, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-lcp_solver %s: unknown solver (%s)", t.lcp_solver.c_str(), names.c_str());
  PetscCheck(!t.polyhedral_solvers.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-polyhedral_solvers: needs at least one solver");
  for (const auto& n : t.polyhedral_solvers)
    PetscCheck(makeContactSolver(n) != nullptr, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-polyhedral_solvers: unknown solver %s (%s, lemke_rf)", n.c_str(), names.c_str());
  for (const auto& n : t.fallback_solvers)
    PetscCheck(makeContactSolver(n) != nullptr, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-fallback_solvers: unknown solver %s (%s)", n.c_str(), names.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode checkRanges(MPI_Comm comm, const AppOptions& o) {
  const StepperOptions& t = o.step;
  PetscFunctionBeginUser;
  PetscCheck(t.lcp_tol > 0 && t.lcp_tol < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-lcp_tol %g: must be in (0, 1)",
             (double)t.lcp_tol);
  PetscCheck(t.mu >= 0 && std::isfinite(t.mu), comm, PETSC_ERR_ARG_OUTOFRANGE, "-mu %g: must be >= 0",
             (double)t.mu);
  PetscCheck(t.dt > 0 && std::isfinite(t.dt), comm, PETSC_ERR_ARG_OUTOFRANGE, "-dt %g: must be > 0",
             (double)t.dt);
  PetscCheck(o.steps >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-steps %d: must be >= 0", (int)o.steps);
  const double g = -t.gravity.z();
  PetscCheck(g >= 0 && std::isfinite(g), comm, PETSC_ERR_ARG_OUTOFRANGE, "-gravity %g: must be >= 0", g);
  PetscCheck(t.baumgarte > 0 && t.baumgarte <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-baumgarte %g: must be in (0, 1]", (double)t.baumgarte);
  PetscCheck(t.regularisation >= 0 && t.regularisation_t >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-regularisation %g / -regularisation_t %g: must be >= 0", (double)t.regularisation,
             (double)t.regularisation_t);
  PetscCheck(t.margin >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-margin %g: must be >= 0", (double)t.margin);
  PetscCheck(t.splitting_max_it >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-splitting_max_it %d: must be >= 1",
             t.splitting_max_it);
  PetscCheck(t.splitting_tol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-splitting_tol %g: must be > 0",
             (double)t.splitting_tol);
  PetscCheck(t.polyhedral_directions >= 3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-polyhedral_directions %d: must be >= 3", t.polyhedral_directions);
  PetscCheck(o.output_every >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_every %d: must be >= 1",
             (int)o.output_every);
  PetscCheck(t.sleep_velocity > 0 && t.sleep_steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sleep_velocity %g / -sleep_steps %d: must be > 0 / >= 1", (double)t.sleep_velocity,
             t.sleep_steps);
  PetscCheck(o.overlap_tol >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-overlap_tol %g: must be >= 0",
             (double)o.overlap_tol);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readOptions(MPI_Comm comm, AppOptions* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Contact app options", nullptr);
  PetscCall(sceneOptions(PetscOptionsObject, &o->scene));
  PetscCall(frictionOptions(PetscOptionsObject, comm, &o->step));
  PetscCall(stepperOptions(PetscOptionsObject, comm, &o->step));
  PetscCall(runOptions(PetscOptionsObject, o));
  PetscOptionsEnd();
  PetscCall(checkSolvers(comm, o->step));
  PetscCall(checkRanges(comm, *o));
  PetscFunctionReturn(0);
}

std::string simplifications(const AppOptions& o, const std::vector<Body>& bodies) {
  std::string s;
  if (o.step.mu == 0 || o.step.friction == FrictionModel::None)
    s += "no friction rows (plain LCP); ";
  else if (o.step.friction != FrictionModel::Polyhedral)
    s += "box friction (per-direction bounds, not a cone); ";
  bool cyl = false;
  for (const Body& b : bodies) cyl = cyl || b.shape.type == ShapeType::Cylinder;
  if (cyl) s += "cylinders act as capsules except against planes; ";
  s += "zero-bound tangent rows left out; ";
  s += o.step.sleep ? "sleeping on (bodies at rest are frozen, contacts among them not solved)"
                    : "sleeping off (every contact is solved each step)";
  return s;
}

} // namespace contact_app
