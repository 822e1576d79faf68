// Contact sizes (see contact_size_check.hpp). The step's problem is dense: the Delassus matrix A of r rows
// (r = 3 per contact for box friction and splitting, 1 + d for polyhedral, 1 without friction) and the LCP of
// m unknowns (polyhedral: (2 + d) per contact) with its solvers' workspace (fallback chain, Lemke's tableau,
// LU factors): about 8 (r^2 + 12 m^2) bytes (measured peak RSS over an incline run: 145 MB at 1200 rows,
// pyramid base 10). Contacts per moving body: a box 8 (up to 4 points per pair, a pyramid's box rests on two;
// pyramid base 10: 55 boxes, 400 contacts measured), a capsule or cylinder 4, a sphere 2 (resting in a heap).
#include "contact_size_check.hpp"

#include "core/resource_checks.hpp"

#include <cstdio>
#include <string>

namespace contact_app {

namespace {
constexpr double kBase = 5e7; // libraries, PETSc, HDF5

// Delassus rows and LCP unknowns per contact of the friction model.
void rowsPerContact(const StepperOptions& t, double* delassus, double* lcp) {
  const double d = t.friction == FrictionModel::Auto ? 8.0 : t.polyhedral_directions; // auto: its top rung
  switch (t.friction) {
  case FrictionModel::None:
    *delassus = *lcp = 1.0;
    break;
  case FrictionModel::Auto:
  case FrictionModel::Polyhedral:
    *delassus = 1.0 + d;
    *lcp = 2.0 + d;
    break;
  default:
    *delassus = *lcp = 3.0;
  }
}

// The options that set the number of bodies, for messages.
std::string sizeOptions(const SceneParams& s) {
  if (s.scene == "box_stack") return "-stack_height " + std::to_string(s.stack_height);
  if (s.scene == "pyramid") return "-pyramid_base " + std::to_string(s.pyramid_base);
  if (s.scene == "pile_grid")
    return "-piles " + std::to_string(s.piles) + " -pyramid_base " + std::to_string(s.pyramid_base);
  if (s.scene == "log_heap") return "-n_logs " + std::to_string(s.n_logs);
  if (s.scene == "file" || s.scene == "mjcf") return "-scene_file " + s.file;
  if (s.scene == "chain") return "-links " + std::to_string(s.links);
  return "-scene " + s.scene;
}
} // namespace

SceneSize sceneSize(const SceneParams& s) {
  if (s.scene == "box_stack") return {1.0 + s.stack_height, 8.0 * s.stack_height};
  const double boxes = 0.5 * s.pyramid_base * (s.pyramid_base + 1.0); // one pyramid
  if (s.scene == "pyramid") return {1.0 + boxes, 8.0 * boxes};
  if (s.scene == "pile_grid") return {1.0 + s.piles * boxes, 8.0 * s.piles * boxes, 8.0 * boxes};
  if (s.scene == "log_heap") return {5.0 + s.n_logs, 4.0 * s.n_logs};
  if (s.scene == "file" || s.scene == "mjcf") return {-1.0, -1.0};
  if (s.scene == "chain") return {s.links + 1.0, 8.0 * (s.links + 1.0)};
  return {2.0, 8.0}; // incline, drop: one body on a plane
}

SceneSize sceneSize(const std::vector<Body>& bodies) {
  SceneSize z{(double)bodies.size(), 0.0};
  for (const Body& b : bodies) {
    if (b.is_static) continue;
    const ShapeType t = b.shape.type;
    z.contacts += t == ShapeType::Box ? 8.0 : t == ShapeType::Sphere ? 2.0 : 4.0;
  }
  return z;
}

PetscErrorCode checkIntegerOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  for (const char* name :
       {"-stack_height", "-pyramid_base", "-piles", "-n_logs", "-steps", "-output_every", "-dump_max",
        "-lcp_max_iterations", "-splitting_max_it", "-polyhedral_directions", "-sleep_steps"})
    PetscCall(suite::checkIntOptionRange(comm, name, 0));
  PetscCall(suite::checkIntOptionRange(comm, "-seed", 0)); // unsigned in the scene; PetscInt on the way
  PetscFunctionReturn(0);
}

PetscErrorCode checkContactSizes(MPI_Comm comm, const AppOptions& o, const SceneSize& size) {
  double delassus = 0, lcp = 0;
  rowsPerContact(o.step, &delassus, &lcp);
  // with islands, the largest dense problem is the largest island's (a known one: pile_grid's pile)
  const double contacts = o.step.islands && size.island_contacts > 0 ? size.island_contacts : size.contacts;
  const double bodies = size.bodies, r = delassus * contacts, m = lcp * contacts;
  const double frames = 2.0 + (double)o.steps / (double)(o.output_every > 0 ? o.output_every : 1);
  const double record = frames * bodies * 14.0 * 8.0 + (double)o.steps * 200.0; // frames, step records
  const std::string what = sizeOptions(o.scene) + (o.step.friction == FrictionModel::Polyhedral
                                                       ? " -friction polyhedral -polyhedral_directions " +
                                                             std::to_string(o.step.polyhedral_directions)
                                                       : "");
  char memory_what[400];
  std::snprintf(memory_what, sizeof memory_what,
                "%s (%.3g bodies, about %.3g contacts: a dense %.3g-row contact problem) with -steps %lld "
                "-output_every %lld",
                what.c_str(), bodies, contacts, m, (long long)o.steps, (long long)o.output_every);
  PetscFunctionBeginUser;
  PetscCall(suite::checkIndexCount(comm, bodies, "bodies", what.c_str()));
  PetscCall(suite::checkIndexCount(comm, m, "contact problem rows (estimate)", what.c_str()));
  PetscCall(suite::checkMemoryEstimate(comm, kBase + 8.0 * (r * r + 12.0 * m * m) + 2000.0 * bodies + record,
                                       memory_what));
  PetscFunctionReturn(0);
}

} // namespace contact_app
