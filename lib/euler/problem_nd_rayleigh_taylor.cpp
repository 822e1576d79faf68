// Rayleigh-Taylor instability (`rayleigh_taylor`) on [0, 1/4] x [0, 1], gamma = 5/3: heavy fluid (rho = 2)
// for y < 1/2, light fluid (rho = 1) above, u = 0, hydrostatic pressure p = 2y + 1 (y < 1/2) and p = y + 3/2
// (y >= 1/2), interface perturbed by v = -0.025 c cos(8 pi x) with c = sqrt(gamma p / rho) the local sound
// speed (-amplitude). Shi, Zhang & Shu add the source rho to the y-momentum equation and rho v to the energy
// equation, i.e. the gravity vector g = (0, +1): it points from the heavy fluid towards the light one, which
// is the Rayleigh-Taylor-unstable arrangement, and dp/dy = rho g holds in both fluids (the app adds
// (0, rho g, rho u.g)). Boundaries: reflecting left and right; bottom and top Custom with the paper's fixed
// states (rho, u, v, p) = (2, 0, 0, 1) and (1, 0, 0, 2.5). t = 1.95, 64 x 256 cells by default.
// Reference: Shi, Zhang & Shu, J. Comput. Phys. 186 (2003) 690, sec. 4 (Rayleigh-Taylor instability). In 3D
// uniform along z.
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createRayleighTaylorProblemND(MPI_Comm comm, const std::string&, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  double amp = 0.025, gamma = 5.0 / 3.0, g = 1.0;
  PetscOptionsBegin(comm, "", "Rayleigh-Taylor options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-amplitude",
                               "Interface perturbation amplitude (times the sound speed)", "", amp, &amp,
                               nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(std::isfinite(amp) && std::abs(amp) < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -amplitude %g: must satisfy |amplitude| < 1 (a fraction of the sound speed)", amp);
  pr->gamma = gamma;
  pr->lo[0] = pr->lo[1] = 0.0;
  pr->hi[0] = 0.25;
  pr->hi[1] = 1.0;
  pr->t_final = 1.95;
  pr->default_n[0] = 64;
  pr->default_n[1] = 256;
  pr->bc[0][0] = pr->bc[0][1] = BcN::Reflecting;
  pr->bc[1][0] = pr->bc[1][1] = BcN::Custom;
  pr->gravity[1] = g;
  extrudeAlongZ(dim, pr);
  pr->initial = [=](const double* x) {
    const double y = x[1];
    const double rho = y < 0.5 ? 2.0 : 1.0, p = y < 0.5 ? 2.0 * y + 1.0 : y + 1.5;
    const double c = std::sqrt(gamma * p / rho);
    return PrimN{rho, {0.0, -amp * c * std::cos(8.0 * M_PI * x[0]), 0.0}, p};
  };
  const PrimN bottom{2.0, {0.0, 0.0, 0.0}, 1.0}, top{1.0, {0.0, 0.0, 0.0}, 2.5};
  pr->ghost = [=](int, int side, const double*, double, const PrimN&, const PrimN&) {
    return side == 0 ? bottom : top;
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
