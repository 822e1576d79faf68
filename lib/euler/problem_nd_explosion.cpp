// Explosion problems on [-1, 1]^dim with outflow boundaries, gamma = 1.4.
// `explosion`: inside the sphere (3D) or circle (2D, cylindrical explosion) r < 0.4 (-radius) rho = 1, p = 1
//   (-rho_in, -p_in), outside rho = 0.125, p = 0.1 (-rho_out, -p_out), u = 0; t = 0.25. Reference: Toro,
//   Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed. (2009), sec. 17.1 (explosion tests in
//   2D and 3D; Toro centres the charge in a box of side 2, which is [-1, 1]^dim here). A spherical explosion
//   is cell-centred at the origin, so the grid is symmetric under the octahedral group.
// `sedov`: point explosion in a cold uniform gas rho = 1 (-rho0), p = 1e-5 (-p_ambient): energy E = 1
//   (-energy; per unit length in 2D) deposited as uniform pressure p = (gamma - 1) E / V in the ball r < r0 =
//   0.0625 (-radius, 2 cells of the default 64-cell 3D grid; V = 4/3 pi r0^3 in 3D, pi r0^2 in 2D). Cells are
//   classified by their centre, so the discrete energy differs from E by the staircase error of the ball (use
//   r0 of a few cells). t = 0.4: the blast radius xi0 (E t^2 / rho)^{1/(dim+2)} (xi0 ~ 1.15 in 3D, ~ 1.0 in
//   2D for gamma = 1.4) is then about 0.8 (3D) and 0.63 (2D), inside the box. Reference: Sedov, Similarity
//   and Dimensional Methods in Mechanics (1959); setup in the style of Fryxell et al., Astrophys. J. Suppl.
//   131 (2000) 273 (FLASH Sedov test: rho 1, p 1e-5, E 1).
// Boundaries: outflow, or reflecting walls on every face with -closed_box (a closed box: total mass and energy are
// conserved to round-off, and the solution is the same until a wave reaches a wall).
// No exact solution is provided for either (compare with a fine-grid or 1D radial reference).
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createExplosionProblemND(MPI_Comm comm, const std::string& name, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  const bool sedov = name == "sedov";
  double gamma = 1.4, radius = sedov ? 0.0625 : 0.4;
  PrimN in{1.0, {0.0, 0.0, 0.0}, 1.0}, out{0.125, {0.0, 0.0, 0.0}, 0.1};
  double energy = 1.0;
  PetscBool closed = PETSC_FALSE;
  if (sedov) out = {1.0, {0.0, 0.0, 0.0}, 1e-5};
  PetscOptionsBegin(comm, "", sedov ? "Sedov blast options" : "Explosion options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-radius", "Radius of the initial charge", "", radius,
                               &radius, nullptr));
  if (sedov) {
    PetscCall(
        suite::optionsReal(PetscOptionsObject, "-rho0", "Ambient density", "", out.rho, &out.rho, nullptr));
    PetscCall(
        suite::optionsReal(PetscOptionsObject, "-p_ambient", "Ambient pressure", "", out.p, &out.p, nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, "-energy", "Deposited energy (per unit length in 2D)",
                                 "", energy, &energy, nullptr));
  } else {
    PetscCall(
        suite::optionsReal(PetscOptionsObject, "-rho_in", "Density inside", "", in.rho, &in.rho, nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, "-p_in", "Pressure inside", "", in.p, &in.p, nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, "-rho_out", "Density outside", "", out.rho, &out.rho,
                                 nullptr));
    PetscCall(
        suite::optionsReal(PetscOptionsObject, "-p_out", "Pressure outside", "", out.p, &out.p, nullptr));
  }
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-closed_box",
                               "Reflecting walls on every face instead of outflow", "", closed, &closed,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(radius > 0.0 && radius < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -radius %g: must lie in (0, 1) (the domain is [-1, 1]^%d)", radius, dim);
  if (sedov) {
    PetscCheck(energy > 0.0 && std::isfinite(energy), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "Invalid -energy %g: must be > 0", energy);
    PetscCall(checkStateN(comm, out, "-rho0", "-p_ambient"));
    const double volume = dim == 3 ? 4.0 / 3.0 * M_PI * radius * radius * radius : M_PI * radius * radius;
    in = {out.rho, {0.0, 0.0, 0.0}, (gamma - 1.0) * energy / volume};
  } else {
    PetscCall(checkStateN(comm, in, "-rho_in", "-p_in"));
    PetscCall(checkStateN(comm, out, "-rho_out", "-p_out"));
  }
  pr->gamma = gamma;
  pr->t_final = sedov ? 0.4 : 0.25;
  for (int d = 0; d < dim; ++d) {
    pr->lo[d] = -1.0;
    pr->hi[d] = 1.0;
    pr->bc[d][0] = pr->bc[d][1] = closed ? BcN::Reflecting : BcN::Outflow;
    pr->default_n[d] = dim == 3 ? 64 : 200;
  }
  if (dim == 2) extrudeAlongZ(dim, pr);
  const double r2max = radius * radius;
  pr->initial = [=](const double* x) {
    double r2 = 0.0;
    for (int d = 0; d < dim; ++d) r2 += x[d] * x[d];
    return r2 < r2max ? in : out;
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
