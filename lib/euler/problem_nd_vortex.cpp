// Isentropic vortex advected by a uniform flow (`isentropic_vortex`): the standard smooth accuracy test of
// the 2D Euler equations. Mean flow (rho, u, v, p) = (1, u0, v0, 1) on [0, 10]^2, periodic, vortex centred at
// (5, 5) with strength beta: with (xb, yb) = x - (5, 5) - (u0, v0) t and r^2 = xb^2 + yb^2,
//   (du, dv) = beta / (2 pi) e^{(1 - r^2) / 2} (-yb, xb),
//   T = p / rho = 1 - (gamma - 1) beta^2 / (8 gamma pi^2) e^{1 - r^2},  rho = T^{1 / (gamma - 1)},
//   p = rho^gamma.
// The flow is an exact steady vortex translated with the mean flow, so the exact solution at time t is the
// initial field moved by (u0, v0) t. On a periodic domain a single vortex is not periodic: its velocity at the
// domain edge is ~beta e^{-12} ~ 1e-5 and jumps there, which stalls high-order convergence near 1e-7 in
// density. Both the initial and the exact field therefore sum the perturbations (du, dv, dT) over the 5 x 5
// nearest periodic images: the field is smooth and periodic, and it solves the Euler equations up to the
// products of overlapping images (~beta^2 e^{-24} ~ 1e-9 at the edge, 1e-10 in the density error measured at
// 128^2). One period with (u0, v0) = (1, 1): t = 10.
// -vortex_domain L: domain [0, L]^2, vortex at (L/2, L/2), t = L.
// References: Shu, ICASE report 97-65 (NASA/CR-97-206253, 1997), the 2D vortex evolution example; Yee,
// Sandham & Djomehri, J. Comput. Phys. 150 (1999) 199 (isentropic vortex convection). In 3D the vortex is
// uniform along z (w = 0).
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

namespace {
// Nearest periodic image of d on a period L: in [-L/2, L/2).
double nearestImage(double d, double L) {
  return d - L * std::floor(d / L + 0.5);
}
} // namespace

PetscErrorCode createVortexProblemND(MPI_Comm comm, const std::string&, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  double beta = 5.0, u0 = 1.0, v0 = 1.0, gamma = 1.4, L = 10.0;
  PetscOptionsBegin(comm, "", "Isentropic vortex options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-vortex_strength", "Vortex strength beta", "", beta,
                               &beta, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-vortex_u", "Mean flow velocity along x", "", u0, &u0,
                               nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-vortex_v", "Mean flow velocity along y", "", v0, &v0,
                               nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-vortex_domain",
                               "Side L of the periodic domain [0, L]^2 (vortex at its centre)", "", L, &L,
                               nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(L >= 4.0 && std::isfinite(L), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -vortex_domain %g: must be >= 4 (the vortex has a radius of a few units)", L);
  PetscCheck(std::isfinite(u0) && std::isfinite(v0), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid mean flow (-vortex_u %g, -vortex_v %g): must be finite", u0, v0);
  const double dT = (gamma - 1.0) * beta * beta / (8.0 * gamma * M_PI * M_PI); // temperature dip / e
  PetscCheck(
      std::isfinite(beta) && 1.0 - dT * std::exp(1.0) > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
      "Invalid -vortex_strength %g: the vortex core temperature 1 - (gamma-1) beta^2 e / (8 gamma pi^2) "
      "must stay > 0 (|beta| < %.4g for gamma = %g)",
      beta, std::sqrt(8.0 * gamma * M_PI * M_PI / ((gamma - 1.0) * std::exp(1.0))), gamma);
  pr->gamma = gamma;
  pr->lo[0] = pr->lo[1] = 0.0;
  pr->hi[0] = pr->hi[1] = L;
  pr->t_final = L; // one period with (u0, v0) = (1, 1)
  pr->default_n[0] = pr->default_n[1] = 64;
  for (int d = 0; d < 2; ++d) pr->bc[d][0] = pr->bc[d][1] = BcN::Periodic;
  extrudeAlongZ(dim, pr);
  const double xc = 0.5 * L, yc = 0.5 * L;
  pr->exact = [=](const double* x, double t) {
    const double x0 = nearestImage(x[0] - xc - u0 * t, L), y0 = nearestImage(x[1] - yc - v0 * t, L);
    double du = 0.0, dv = 0.0, dTe = 0.0;
    for (int a = -2; a <= 2; ++a)
      for (int b = -2; b <= 2; ++b) {
        const double xb = x0 + a * L, yb = y0 + b * L, r2 = xb * xb + yb * yb;
        const double s = beta / (2.0 * M_PI) * std::exp(0.5 * (1.0 - r2));
        du -= s * yb;
        dv += s * xb;
        dTe += std::exp(1.0 - r2);
      }
    const double T = 1.0 - dT * dTe, rho = std::pow(T, 1.0 / (gamma - 1.0));
    return PrimN{rho, {u0 + du, v0 + dv, 0.0}, rho * T};
  };
  auto exact = pr->exact;
  pr->initial = [exact](const double* x) { return exact(x, 0.0); };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
