// High Mach number astrophysical jet (`jet`, 2D; uniform along z in 3D): ambient gas rho = 0.5 (-rho_ambient),
// p = 0.4127 (-p_ambient), at rest, on [0, 1] x [-0.25, 0.25], gamma = 5/3. A jet rho = 5 (-jet_rho), u = 800
// (-jet_u), p = 0.4127 (-jet_p) enters through the part |y| < 0.05 (-jet_halfwidth) of the left face (an inflow
// boundary on part of a face: a Custom face whose ghost cells hold the jet state where the ghost cell centre
// lies in the jet, the zero-gradient outflow state elsewhere); outflow on every other face; t = 0.001. The jet's
// Mach number with respect to its own sound speed sqrt(gamma p / rho) = 0.371 is about 2156 ("Mach 2000").
// Densities and pressures span several orders of magnitude behind the bow shock: a positivity test.
// Start: as Zhang & Shu, the domain holds ambient gas only (-jet_x0 L fills x < L, |y| < halfwidth with the jet
// state at t = 0 instead). The CFL time step counts the inflow ghost states (apps/euler/euler_step.cpp), so the
// first step is stable although the jet has not entered yet.
// Reference: Zhang & Shu, J. Comput. Phys. 229 (2010) 8918, sec. 4 (high Mach number astrophysical jets).
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createJetProblemND(MPI_Comm comm, const std::string&, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  double gamma = 5.0 / 3.0, halfwidth = 0.05, x0 = 0.0;
  PrimN jet{5.0, {800.0, 0.0, 0.0}, 0.4127}, ambient{0.5, {0.0, 0.0, 0.0}, 0.4127};
  PetscOptionsBegin(comm, "", "Astrophysical jet options", "");
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-jet_rho", "Jet density", "", jet.rho, &jet.rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-jet_u", "Jet velocity along x", "", jet.u[0], &jet.u[0],
                               nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-jet_p", "Jet pressure", "", jet.p, &jet.p, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-jet_halfwidth",
                               "Jet half-width (inflow where |y| < it on the left face)", "", halfwidth,
                               &halfwidth, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-jet_x0", "Length of jet already in the domain at t = 0",
                               "", x0, &x0, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-rho_ambient", "Ambient density", "", ambient.rho,
                               &ambient.rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_ambient", "Ambient pressure", "", ambient.p,
                               &ambient.p, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCall(checkStateN(comm, jet, "-jet_rho", "-jet_p"));
  PetscCall(checkStateN(comm, ambient, "-rho_ambient", "-p_ambient"));
  PetscCheck(halfwidth > 0.0 && halfwidth < 0.25, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -jet_halfwidth %g: must lie in (0, 0.25) (the domain is [-0.25, 0.25] in y)",
             halfwidth);
  PetscCheck(x0 >= 0.0 && x0 < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -jet_x0 %g: must lie in [0, 1) (the domain is [0, 1] in x)", x0);
  pr->gamma = gamma;
  pr->lo[0] = 0.0, pr->hi[0] = 1.0;
  pr->lo[1] = -0.25, pr->hi[1] = 0.25;
  pr->t_final = 0.001;
  pr->default_n[0] = 200;
  pr->default_n[1] = 100;
  pr->bc[0][0] = BcN::Custom;
  pr->bc[0][1] = pr->bc[1][0] = pr->bc[1][1] = BcN::Outflow;
  extrudeAlongZ(dim, pr);
  pr->initial = [=](const double* x) { return x[0] < x0 && std::abs(x[1]) < halfwidth ? jet : ambient; };
  // Only the left face is Custom: jet where the ghost cell centre lies in the jet, zero-gradient outflow elsewhere.
  pr->ghost = [jet, halfwidth](int, int, const double* x, double, const PrimN&, const PrimN& edge) {
    return std::abs(x[1]) < halfwidth ? jet : edge;
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
