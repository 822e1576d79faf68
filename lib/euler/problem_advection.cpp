// Pure advection problems (uniform u and p, so rho(x, t) = rho0(x - u t) exactly, periodic):
// `density_wave` rho = 1 + A sin(pi x) on [-1, 1] (Jiang & Shu 1996 sec. 4.1-style accuracy test);
// `pulse`: a rectangular density block moving left at high speed (u = -3, Mach 2.5 in the ambient gas)
// through a uniform medium with sine-shaped oscillations ahead of it, 560 cells and 2000 fixed steps by
// default (a reconstruction of the original ENO-Pade code's pulse case; the exact solution is known, so -error
// works).
#include "core/option_value.hpp"
#include "euler/problem.hpp"

#include <cmath>

namespace suite::euler {

namespace {
double wrap(double x, double a, double b) {
  const double L = b - a;
  double y = std::fmod(x - a, L);
  if (y < 0) y += L;
  return a + y;
}
} // namespace

PetscErrorCode createAdvectionProblem(MPI_Comm comm, const std::string& name, Problem* pr) {
  PetscFunctionBeginUser;
  const bool pulse = name == "pulse";
  double amp = pulse ? 0.3 : 0.2, u = pulse ? -3.0 : 1.0, p = 1.0, gamma = 1.4, block = 4.0;
  PetscOptionsBegin(comm, "", "Advection problem options", "");
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-amplitude", "Density wave amplitude", "", amp, &amp, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-velocity", "Advection velocity", "", u, &u, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-pressure", "Uniform pressure", "", p, &p, nullptr));
  if (pulse)
    PetscCall(suite::optionsReal(PetscOptionsObject, "-block_density", "Density of the moving block", "",
                                 block, &block, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(p > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial pressure %g (option -pressure): must be > 0", p);
  PetscCheck(std::abs(amp) < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -amplitude %g: density 1 + amplitude sin(...) must stay > 0", amp);
  PetscCheck(block > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid initial density %g (option -block_density): density must be > 0", block);
  pr->gamma = gamma;
  pr->bc_left = pr->bc_right = Bc::Periodic;
  std::function<double(double)> rho0;
  if (pulse) {
    pr->xmin = 0.0;
    pr->xmax = 1.0;
    pr->t_final = 0.25;
    pr->default_nx = 560;
    pr->default_max_steps = 2000;
    pr->default_dt = 0.25 / 2000;
    pr->default_spacetime_every = 10;
    rho0 = [amp, block](double x) {
      if (x >= 0.8 && x < 0.95) return block;
      if (x >= 0.1 && x < 0.7) return 1.0 + amp * std::sin(16.0 * M_PI * x);
      return 1.0;
    };
  } else {
    pr->xmin = -1.0;
    pr->xmax = 1.0;
    pr->t_final = 2.0;
    pr->default_nx = 80;
    rho0 = [amp](double x) { return 1.0 + amp * std::sin(M_PI * x); };
  }
  const double a = pr->xmin, b = pr->xmax;
  pr->initial = [rho0, u, p](double x) { return Prim{rho0(x), u, p}; };
  pr->exact = [rho0, u, p, a, b](double x, double t) { return Prim{rho0(wrap(x - u * t, a, b)), u, p}; };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
