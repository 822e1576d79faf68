// Riemann problems (`riemann` with any states, presets `sod`, `lax`, `toro123`, `modified_sod`) and their
// exact solution. References: Sod, J. Comput. Phys. 27 (1978) 1; Lax, Comm. Pure Appl. Math. 7 (1954) 159
// (data as in Harten 1983); Toro (2009) sec. 4.3.3, tests 1 (modified Sod, x0 = 0.3) and 2 (123 problem).
#include "core/option_value.hpp"
#include "euler/exact_riemann.hpp"
#include "euler/problem.hpp"

#include <memory>

namespace suite::euler {

PetscErrorCode createRiemannProblem(MPI_Comm comm, const std::string& name, Problem* pr) {
  PetscFunctionBeginUser;
  Prim L{1.0, 0.0, 1.0}, R{0.125, 0.0, 0.1};
  double x0 = 0.5;
  pr->xmin = 0.0;
  pr->xmax = 1.0;
  pr->t_final = 0.2;
  if (name == "lax") {
    L = {0.445, 0.698, 3.528};
    R = {0.5, 0.0, 0.571};
    pr->t_final = 0.14;
  } else if (name == "toro123") {
    L = {1.0, -2.0, 0.4};
    R = {1.0, 2.0, 0.4};
    pr->t_final = 0.15;
  } else if (name == "modified_sod") {
    L = {1.0, 0.75, 1.0};
    R = {0.125, 0.0, 0.1};
    x0 = 0.3;
  }
  double gamma = 1.4;
  PetscOptionsBegin(comm, "", "Riemann problem options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-rho_l", "Left density", "", L.rho, &L.rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-u_l", "Left velocity", "", L.u, &L.u, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_l", "Left pressure", "", L.p, &L.p, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-rho_r", "Right density", "", R.rho, &R.rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-u_r", "Right velocity", "", R.u, &R.u, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_r", "Right pressure", "", R.p, &R.p, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-x0", "Initial discontinuity position", "", x0, &x0, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCall(checkState(comm, L, "-rho_l", "-p_l"));
  PetscCall(checkState(comm, R, "-rho_r", "-p_r"));
  pr->gamma = gamma;
  pr->bc_left = pr->bc_right = Bc::Outflow;
  pr->inflow_left = L;
  pr->inflow_right = R;
  pr->initial = [L, R, x0](double x) { return x < x0 ? L : R; };
  auto exact = std::make_shared<ExactRiemann>(L, R, gamma);
  pr->exact = [exact, L, R, x0](double x, double t) {
    if (t <= 0.0) return x < x0 ? L : R;
    return exact->sample((x - x0) / t);
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
