// Woodward-Colella interacting blast waves: rho = 1, u = 0, p = 1000 / 0.01 / 100 on [0, 0.1] / [0.1, 0.9] /
// [0.9, 1], reflecting walls, t = 0.038. Reference: Woodward & Colella, J. Comput. Phys. 54 (1984) 115, sec.
// IVa.
#include "core/option_value.hpp"
#include "euler/problem.hpp"

namespace suite::euler {

PetscErrorCode createBlastProblem(MPI_Comm comm, const std::string&, Problem* pr) {
  PetscFunctionBeginUser;
  double p_l = 1000.0, p_m = 0.01, p_r = 100.0, rho = 1.0, gamma = 1.4;
  PetscOptionsBegin(comm, "", "Blast wave options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_l", "Left pressure", "", p_l, &p_l, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_m", "Middle pressure", "", p_m, &p_m, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-p_r", "Right pressure", "", p_r, &p_r, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-rho0", "Density", "", rho, &rho, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCall(checkState(comm, {rho, 0.0, p_l}, "-rho0", "-p_l"));
  PetscCall(checkState(comm, {rho, 0.0, p_m}, "-rho0", "-p_m"));
  PetscCall(checkState(comm, {rho, 0.0, p_r}, "-rho0", "-p_r"));
  pr->gamma = gamma;
  pr->xmin = 0.0;
  pr->xmax = 1.0;
  pr->t_final = 0.038;
  pr->default_nx = 400;
  pr->bc_left = pr->bc_right = Bc::Reflecting;
  pr->initial = [=](double x) { return Prim{rho, 0.0, x < 0.1 ? p_l : (x < 0.9 ? p_m : p_r)}; };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
