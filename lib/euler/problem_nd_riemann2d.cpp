// Four-quadrant 2D Riemann problems (`riemann2d`: any four states; presets `lax_liu_4`, `lax_liu_6`,
// `liska_wendroff_3`) on [0, 1]^2 with outflow boundaries. Quadrants around the split point (x0, y0) =
// (0.5, 0.5): ne = {x > x0, y > y0} (Lax & Liu's region 1), nw = 2, sw = 3, se = 4; each state is
// (rho, u, v, p), gamma = 1.4.
//   Configuration 3 (four shocks; the `riemann2d` default and `liska_wendroff_3`), t = 0.3:
//     ne (1.5, 0, 0, 1.5)      nw (0.5323, 1.206, 0, 0.3)
//     sw (0.138, 1.206, 1.206, 0.029)   se (0.5323, 0, 1.206, 0.3)
//   Configuration 4 (four shocks, `lax_liu_4`), t = 0.25:
//     ne (1.1, 0, 0, 1.1)      nw (0.5065, 0.8939, 0, 0.35)
//     sw (1.1, 0.8939, 0.8939, 1.1)     se (0.5065, 0, 0.8939, 0.35)
//   Configuration 6 (four slip lines, `lax_liu_6`), t = 0.3:
//     ne (1, 0.75, -0.5, 1)    nw (2, 0.75, 0.5, 1)
//     sw (1, -0.75, 0.5, 1)             se (3, -0.75, -0.5, 1)
// References: Lax & Liu, SIAM J. Sci. Comput. 19 (1998) 319 (configurations 3, 4, 6); Kurganov & Tadmor,
// Numer. Methods Partial Differential Equations 18 (2002) 584 (same data and end times); Liska & Wendroff,
// SIAM J. Sci. Comput. 25 (2003) 995 (2D Riemann problem case 3 = Lax-Liu configuration 3, t = 0.3). The
// four-digit states are the published ones (the shocks of configurations 3 and 4 satisfy the Rankine-Hugoniot
// relations to those digits; tests/unit/euler_nd checks it). In 3D the data are uniform along z.
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

namespace suite::euler {

PetscErrorCode createRiemann2dProblemND(MPI_Comm comm, const std::string& name, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  // order: ne, nw, sw, se
  PrimN q[4] = {{1.5, {0.0, 0.0, 0.0}, 1.5},
                {0.5323, {1.206, 0.0, 0.0}, 0.3},
                {0.138, {1.206, 1.206, 0.0}, 0.029},
                {0.5323, {0.0, 1.206, 0.0}, 0.3}};
  double t_final = 0.3;
  if (name == "lax_liu_4") {
    q[0] = {1.1, {0.0, 0.0, 0.0}, 1.1};
    q[1] = {0.5065, {0.8939, 0.0, 0.0}, 0.35};
    q[2] = {1.1, {0.8939, 0.8939, 0.0}, 1.1};
    q[3] = {0.5065, {0.0, 0.8939, 0.0}, 0.35};
    t_final = 0.25;
  } else if (name == "lax_liu_6") {
    q[0] = {1.0, {0.75, -0.5, 0.0}, 1.0};
    q[1] = {2.0, {0.75, 0.5, 0.0}, 1.0};
    q[2] = {1.0, {-0.75, 0.5, 0.0}, 1.0};
    q[3] = {3.0, {-0.75, -0.5, 0.0}, 1.0};
    t_final = 0.3;
  }
  double x0 = 0.5, y0 = 0.5, gamma = 1.4;
  static const char* const tag[4] = {"ne", "nw", "sw", "se"};
  std::string opt[4][4];
  for (int k = 0; k < 4; ++k) {
    opt[k][0] = std::string("-rho_") + tag[k];
    opt[k][1] = std::string("-u_") + tag[k];
    opt[k][2] = std::string("-v_") + tag[k];
    opt[k][3] = std::string("-p_") + tag[k];
  }
  PetscOptionsBegin(comm, "", "2D Riemann problem options", "");
  for (int k = 0; k < 4; ++k) {
    PetscCall(suite::optionsReal(PetscOptionsObject, opt[k][0].c_str(), "Quadrant density", "", q[k].rho,
                                 &q[k].rho, nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, opt[k][1].c_str(), "Quadrant x velocity", "", q[k].u[0],
                                 &q[k].u[0], nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, opt[k][2].c_str(), "Quadrant y velocity", "", q[k].u[1],
                                 &q[k].u[1], nullptr));
    PetscCall(suite::optionsReal(PetscOptionsObject, opt[k][3].c_str(), "Quadrant pressure", "", q[k].p,
                                 &q[k].p, nullptr));
  }
  PetscCall(suite::optionsReal(PetscOptionsObject, "-x0", "Split point x", "", x0, &x0, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-y0", "Split point y", "", y0, &y0, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  for (int k = 0; k < 4; ++k) PetscCall(checkStateN(comm, q[k], opt[k][0].c_str(), opt[k][3].c_str()));
  PetscCheck(x0 > 0.0 && x0 < 1.0 && y0 > 0.0 && y0 < 1.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid split point (-x0 %g, -y0 %g): must lie inside the domain (0, 1)^2", x0, y0);
  pr->gamma = gamma;
  pr->t_final = t_final;
  pr->default_n[0] = pr->default_n[1] = 200;
  for (int d = 0; d < 2; ++d) pr->bc[d][0] = pr->bc[d][1] = BcN::Outflow;
  extrudeAlongZ(dim, pr);
  const PrimN ne = q[0], nw = q[1], sw = q[2], se = q[3];
  pr->initial = [=](const double* x) {
    if (x[1] > y0) return x[0] > x0 ? ne : nw;
    return x[0] > x0 ? se : sw;
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
