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

// One-line option declarations inside the PetscOptionsBegin/End block (each documented by -help).
struct Reader {
  PetscOptionItems* po;
  PetscErrorCode real(const char* name, const char* text, double* v) const {
    return PetscOptionsReal_Private(po, name, text, nullptr, *v, v, nullptr);
  }
  template <class I> PetscErrorCode integer(const char* name, const char* text, I* v) const {
    PetscInt x = (PetscInt)*v;
    PetscFunctionBeginUser;
    PetscCall(PetscOptionsInt_Private(po, name, text, nullptr, x, &x, nullptr, PETSC_MIN_INT, PETSC_MAX_INT));
    *v = (I)x;
    PetscFunctionReturn(0);
  }
  PetscErrorCode boolean(const char* name, const char* text, bool* v) const {
    PetscBool x = *v ? PETSC_TRUE : PETSC_FALSE;
    PetscFunctionBeginUser;
    PetscCall(PetscOptionsBool_Private(po, name, text, nullptr, x, &x, nullptr));
    *v = x;
    PetscFunctionReturn(0);
  }
  PetscErrorCode string(const char* name, const char* text, std::string* v) const {
    char buf[PETSC_MAX_PATH_LEN];
    PetscFunctionBeginUser;
    PetscCall(PetscStrncpy(buf, v->c_str(), sizeof buf));
    PetscCall(PetscOptionsString_Private(po, name, text, nullptr, buf, buf, sizeof buf, nullptr));
    *v = buf;
    PetscFunctionReturn(0);
  }
};

PetscErrorCode sceneOptions(const Reader& r, SceneParams* s) {
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(r.po, "-scene", "Scene", sceneChoices(), &s->scene));
  PetscCall(r.string("-scene_file", "Scene file for -scene file (format: lib/contact/scenes.hpp)", &s->file));
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
  PetscCall(r.integer("-pyramid_base", "pyramid: boxes in the bottom row", &s->pyramid_base));
  PetscCall(r.integer("-n_logs", "log_heap: number of logs", &s->n_logs));
  PetscCall(r.real("-log_radius", "log_heap: log radius (m)", &s->log_radius));
  PetscCall(r.real("-log_length", "log_heap: log length (m)", &s->log_length));
  PetscCall(r.integer("-seed", "log_heap: random seed", &s->seed));
  PetscFunctionReturn(0);
}

// Friction model and the LCP solvers.
PetscErrorCode frictionOptions(const Reader& r, MPI_Comm comm, StepperOptions* t) {
  std::string friction = frictionName(t->friction), fallback = joinList(t->fallback_solvers),
              poly = joinList(t->polyhedral_solvers);
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(r.po, "-friction", "Friction model", frictionChoices(), &friction));
  PetscCheck(frictionFromName(friction, &t->friction), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-friction %s: unknown friction model", friction.c_str());
  PetscCall(r.real("-mu", "Friction coefficient", &t->mu));
  PetscCall(r.string("-lcp_solver", "LCP solver (lib/lcp registry)", &t->lcp_solver));
  PetscCall(
      r.string("-fallback_solvers", "Comma list tried when the solver fails ('none': stop)", &fallback));
  PetscCall(r.real("-lcp_tol", "Acceptance: natural-map residual <= tol (1 + |q|_inf)", &t->lcp_tol));
  PetscCall(r.integer("-lcp_max_iterations", "Iteration cap of the primary LCP solver (0: its default)",
                      &t->lcp_max_iterations));
  PetscCall(r.string("-polyhedral_solvers",
                     "Polyhedral: solver chain, first the reference (each answer verified)", &poly));
  t->fallback_solvers = splitList(fallback);
  t->polyhedral_solvers = splitList(poly);
  PetscFunctionReturn(0);
}

// Integration, stabilisation, splitting, polyhedral cone and sleeping.
PetscErrorCode stepperOptions(const Reader& r, MPI_Comm comm, StepperOptions* t) {
  std::string start = splitStartName(t->split_start);
  double g = 9.81;
  PetscFunctionBeginUser;
  PetscCall(r.real("-dt", "Time step (s)", &t->dt));
  PetscCall(r.real("-gravity", "Gravity (m/s^2, along -z)", &g));
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
  PetscCall(
      r.real("-splitting_tol", "Splitting: relative tolerance on max|delta lambda_n|", &t->splitting_tol));
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
  PetscFunctionReturn(0);
}

PetscErrorCode runOptions(const Reader& r, AppOptions* o) {
  PetscFunctionBeginUser;
  PetscCall(r.integer("-steps", "Number of steps", &o->steps));
  PetscCall(r.real("-overlap_tol", "Largest allowed overlap of static bodies (m)", &o->overlap_tol));
  PetscCall(r.integer("-output_every", "Frame interval in steps", &o->output_every));
  PetscCall(PetscOptionsString_Private(r.po, "-output", "HDF5 output file", nullptr, o->output, o->output,
                                       sizeof o->output, nullptr));
  PetscCall(PetscOptionsString_Private(r.po, "-dump_problems",
                                       "Prefix: every contact problem -> PREFIX_step<N>_pass<K>.h5", nullptr,
                                       o->dump, o->dump, sizeof o->dump, nullptr));
  PetscCall(r.integer("-dump_max", "Most problems dumped", &o->dump_max));
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
  const Reader r{PetscOptionsObject};
  PetscCall(sceneOptions(r, &o->scene));
  PetscCall(frictionOptions(r, comm, &o->step));
  PetscCall(stepperOptions(r, comm, &o->step));
  PetscCall(runOptions(r, o));
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
