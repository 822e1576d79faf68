// Shock / entropy-wave interaction problems: `shu_osher` (Shu & Osher, J. Comput. Phys. 83 (1989) 32, example
// 8: Mach 3 shock into rho = 1 + 0.2 sin(5x) on [-5, 5], t = 1.8) and `titarev_toro` (Titarev & Toro, J.
// Comput. Phys. 201 (2004) 238, sec. 7: rho = 1 + 0.1 sin(20 pi x), shock at x = -4.5, t = 5). No exact
// solution: compare with a fine-grid run (-reference).
#include "core/option_value.hpp"
#include "euler/problem.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createShockEntropyProblem(MPI_Comm comm, const std::string& name, Problem* pr) {
  PetscFunctionBeginUser;
  const bool so = name == "shu_osher";
  Prim L = so ? Prim{3.857143, 2.629369, 10.33333} : Prim{1.515695, 0.523346, 1.805};
  double x0 = so ? -4.0 : -4.5, amp = so ? 0.2 : 0.1, wavenumber = so ? 5.0 : 20.0 * M_PI, gamma = 1.4;
  PetscOptionsBegin(comm, "", "Shock/entropy-wave problem options", "");
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-rho_l", "Post-shock density", "", L.rho, &L.rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-u_l", "Post-shock velocity", "", L.u, &L.u, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_l", "Post-shock pressure", "", L.p, &L.p, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-x0", "Initial shock position", "", x0, &x0, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-amplitude", "Density wave amplitude", "", amp, &amp, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-wavenumber", "Density wave number", "", wavenumber,
                               &wavenumber, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCall(checkState(comm, L, "-rho_l", "-p_l"));
  PetscCheck(amp < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -amplitude %g: the pre-shock density 1 + amplitude sin(kx) must stay > 0", amp);
  pr->gamma = gamma;
  pr->xmin = -5.0;
  pr->xmax = 5.0;
  pr->t_final = so ? 1.8 : 5.0;
  pr->default_nx = so ? 400 : 1000;
  pr->bc_left = Bc::Inflow;
  pr->bc_right = Bc::Outflow;
  pr->inflow_left = L;
  pr->inflow_right = {1.0, 0.0, 1.0};
  pr->initial = [L, x0, amp, wavenumber](double x) {
    return x < x0 ? L : Prim{1.0 + amp * std::sin(wavenumber * x), 0.0, 1.0};
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
