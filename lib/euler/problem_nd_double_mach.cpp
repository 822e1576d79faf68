// Double Mach reflection of a strong shock (`double_mach`): a Mach 10 shock in air (gamma = 1.4) at rest
// (rho, p) = (1.4, 1) meets a reflecting wall at 60 degrees, starting at x = 1/6 on the bottom of [0, 4] x
// [0, 1]. Post-shock state from the Rankine-Hugoniot relations (Mach M = -mach, pre-shock sound speed 1,
// shock speed S = M): rho = 1.4 (gamma + 1) M^2 / ((gamma - 1) M^2 + 2) = 8, p = (2 gamma M^2 - gamma + 1) /
// (gamma + 1) = 116.5, speed 8.25 normal to the shock: (u, v) = 8.25 (cos 30, -sin 30). The shock line at
// time t is x = 1/6 + (y + 2 S t) / sqrt(3) (x = 1/6 + (1 + 20 t) / sqrt(3) on the top boundary). Boundaries:
// left post-shock inflow (Custom), right outflow, bottom Custom (post-shock state for x < 1/6, reflecting
// wall beyond), top Custom time-dependent (the exact undisturbed flow: post-shock left of the shock line,
// pre-shock right of it, evaluated at the ghost cell centre). t = 0.2, grid 1/120 (480 x 120) by default.
// Reference: Woodward & Colella, J. Comput. Phys. 54 (1984) 115, sec. IVc. In 3D uniform along z.
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createDoubleMachProblemND(MPI_Comm comm, const std::string&, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  double mach = 10.0, gamma = 1.4;
  PetscOptionsBegin(comm, "", "Double Mach reflection options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-mach", "Shock Mach number", "", mach, &mach, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(mach > 1.0 && std::isfinite(mach), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -mach %g: a shock needs Mach number > 1", mach);
  const double rho1 = gamma, p1 = 1.0, S = mach; // pre-shock sound speed sqrt(gamma p1 / rho1) = 1
  const double m2 = mach * mach;
  const double rho2 = rho1 * (gamma + 1.0) * m2 / ((gamma - 1.0) * m2 + 2.0);
  const double p2 = p1 * (2.0 * gamma * m2 - (gamma - 1.0)) / (gamma + 1.0);
  const double un = S * (1.0 - rho1 / rho2); // post-shock speed normal to the shock
  const PrimN pre{rho1, {0.0, 0.0, 0.0}, p1};
  const PrimN post{rho2, {un * std::cos(M_PI / 6.0), -un * std::sin(M_PI / 6.0), 0.0}, p2};
  const double x0 = 1.0 / 6.0, s3 = std::sqrt(3.0);
  pr->gamma = gamma;
  pr->lo[0] = pr->lo[1] = 0.0;
  pr->hi[0] = 4.0;
  pr->hi[1] = 1.0;
  pr->t_final = 0.2;
  pr->default_n[0] = 480;
  pr->default_n[1] = 120;
  pr->bc[0][0] = BcN::Custom;
  pr->bc[0][1] = BcN::Outflow;
  pr->bc[1][0] = pr->bc[1][1] = BcN::Custom;
  extrudeAlongZ(dim, pr);
  // Undisturbed flow: post-shock behind (left of) the shock line x = x0 + (y + 2 S t) / sqrt(3).
  auto undisturbed = [=](const double* x, double t) {
    return x[0] < x0 + (x[1] + 2.0 * S * t) / s3 ? post : pre;
  };
  pr->initial = [undisturbed](const double* x) { return undisturbed(x, 0.0); };
  pr->ghost = [=](int dir, int side, const double* x, double t, const PrimN& mirror, const PrimN&) {
    if (dir == 0) return post;                                    // left inflow (the right face is Outflow)
    if (side == 0) return x[0] < x0 ? post : reflectN(mirror, 1); // bottom
    return undisturbed(x, t);                                     // top
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
