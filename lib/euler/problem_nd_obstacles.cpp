// Flows past solid obstacles (solid_body.hpp), gamma = 1.4:
// `forward_step`: Woodward & Colella's Mach 3 wind tunnel with a step. Domain [0, 3] x [0, 1], the step
//   x > 0.6, y < 0.2 solid; uniform rho = 1.4, p = 1, u = 3 (Mach 3: c = 1) everywhere at t = 0 and held at
//   the left face (inflow), outflow right, reflecting walls top and bottom; t = 4 (the quasi-steady pattern:
//   bow shock, Mach stem on the step, reflections off the top wall). 240 x 80 cells by default (dx = 1/80, the
//   paper's coarse grid). Woodward and Colella treat the step's corner, a rarefaction singularity, with a fix
//   (an entropy condition near the corner) that is not applied here: the corner's entropy layer along the step's
//   top is the scheme's own. Reference: Woodward & Colella, J. Comput. Phys. 54 (1984) 115, sec. IVb, fig. 4.
// `shock_cylinder` (2D) / `shock_sphere` (3D): a plane shock of Mach 2.8 (-mach) moving along +x into gas
//   at rest (rho = 1.4, p = 1: c = 1) hits a cylinder / sphere of radius 0.2 (-radius) centred at x = 0.6, 0
//   [, 0]; the shock starts at x = 0.3. Post-shock state from the Rankine-Hugoniot relations (Toro, Riemann
//   Solvers and Numerical Methods, 3rd ed., sec. 3.1.3), held at the left face (inflow); outflow elsewhere.
//   Domain [0, 2] x [-0.75, 0.75] (x [-0.75, 0.75]); t = 0.4 (the shock past the body by ~2 diameters: the
//   reflected bow shock, the Mach stems behind it). Default grids 320 x 240 (2D) and 96 x 72 x 72 (3D).
//   Setup in the style of the shock-body interactions of Berger & Colella, J. Comput. Phys. 82 (1989) 64.
// Each refuses -solid / -solid_mask (the obstacle is the problem); -bc_* may still change the faces.
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

namespace {
// The state behind a shock of Mach `mach` moving along +x into `ahead` (at rest).
PrimN postShock(const PrimN& ahead, double mach, double gamma) {
  const double c = std::sqrt(gamma * ahead.p / ahead.rho), m2 = mach * mach;
  const double rho = ahead.rho * (gamma + 1.0) * m2 / ((gamma - 1.0) * m2 + 2.0);
  const double p = ahead.p * (1.0 + 2.0 * gamma / (gamma + 1.0) * (m2 - 1.0));
  return PrimN{rho, {mach * c * (1.0 - ahead.rho / rho), 0.0, 0.0}, p};
}

PetscErrorCode forwardStep(MPI_Comm comm, int dim, ProblemND* pr) {
  PetscFunctionBeginUser;
  PetscCheck(dim == 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "forward_step is a 2D problem (-dim 2)");
  const PrimN in{1.4, {3.0, 0.0, 0.0}, 1.0};
  pr->gamma = 1.4;
  pr->t_final = 4.0;
  pr->lo[0] = 0.0, pr->hi[0] = 3.0, pr->lo[1] = 0.0, pr->hi[1] = 1.0;
  pr->default_n[0] = 240, pr->default_n[1] = 80;
  pr->bc[0][0] = BcN::Custom, pr->bc[0][1] = BcN::Outflow;
  pr->bc[1][0] = pr->bc[1][1] = BcN::Reflecting;
  pr->bc_label[0][0] = "inflow";
  extrudeAlongZ(dim, pr);
  pr->initial = [in](const double*) { return in; };
  pr->ghost = [in](int, int, const double*, double, const PrimN&, const PrimN&) { return in; };
  pr->solid = [](const double* x) { return (x[0] > 0.6 && x[1] < 0.2) ? 1.0 : -1.0; };
  PetscFunctionReturn(0);
}

PetscErrorCode shockBody(MPI_Comm comm, int dim, ProblemND* pr) {
  double mach = 2.8, radius = 0.2;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Shock-obstacle options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-mach", "Shock Mach number", "", mach, &mach, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-radius", "Radius of the body", "", radius, &radius, nullptr));
  PetscOptionsEnd();
  PetscCheck(mach > 1.0 && mach < 1e3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -mach %g: must be in (1, 1000)", mach);
  PetscCheck(radius > 0.0 && radius <= 0.3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -radius %g: must be in (0, 0.3] (the body sits at x = 0.6, the shock starts at 0.3)",
             radius);
  const PrimN ahead{1.4, {0.0, 0.0, 0.0}, 1.0}, behind = postShock(ahead, mach, 1.4);
  pr->gamma = 1.4;
  pr->t_final = 0.4;
  pr->lo[0] = 0.0, pr->hi[0] = 2.0;
  for (int d = 1; d < dim; ++d) pr->lo[d] = -0.75, pr->hi[d] = 0.75;
  pr->default_n[0] = dim == 2 ? 320 : 96;
  for (int d = 1; d < dim; ++d) pr->default_n[d] = dim == 2 ? 240 : 72;
  for (int d = 0; d < dim; ++d) pr->bc[d][0] = pr->bc[d][1] = BcN::Outflow;
  pr->bc[0][0] = BcN::Custom;
  pr->bc_label[0][0] = "inflow";
  if (dim == 2) extrudeAlongZ(dim, pr);
  pr->initial = [ahead, behind](const double* x) { return x[0] < 0.3 ? behind : ahead; };
  pr->ghost = [behind](int, int, const double*, double, const PrimN&, const PrimN&) { return behind; };
  const double r2 = radius * radius;
  pr->solid = [r2, dim](const double* x) {
    double d2 = (x[0] - 0.6) * (x[0] - 0.6);
    for (int d = 1; d < dim; ++d) d2 += x[d] * x[d];
    return r2 - d2;
  };
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode createObstacleProblemND(MPI_Comm comm, const std::string& name, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  if (name == "forward_step") {
    PetscCall(forwardStep(comm, dim, pr));
  } else {
    PetscCheck(name != "shock_cylinder" || dim == 2, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "shock_cylinder is a 2D problem (-dim 2; shock_sphere is its 3D twin)");
    PetscCheck(name != "shock_sphere" || dim == 3, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "shock_sphere is a 3D problem (-dim 3; shock_cylinder is its 2D twin)");
    PetscCall(shockBody(comm, dim, pr));
  }
  PetscFunctionReturn(0);
}

} // namespace suite::euler
