// `-problem formula`: the initial state as formulas of the cell centre, for -dim 1|2|3:
//   -ic_rho "..." -ic_p "..." (required), -ic_u -ic_v -ic_w (default 0; v from -dim 2, w in -dim 3),
//   -ic_param a=1,b=2 (named constants), -gamma (1.4), -ic_average (cell averages, below).
// Variables: x (1D), x y (2D), x y z (3D). Piecewise states with comparisons and c ? a : b; the syntax is
// muParser's (core/expression.hpp). Domain [0, 1]^dim unless -xmin -xmax ... (problem_overrides.hpp), outflow
// faces unless -bc_* says otherwise; -t_final and -nx [-ny -nz] are required (the problem has no scale of its
// own).
// Point values or cell averages: the schemes are finite-difference schemes on point values at the cell
// centres (Shu, ICASE report 97-65, sec. 2.3: the flux is reconstructed so that its differences are the flux
// derivative at the centres), so the default evaluates the formulas at the centres, which keeps a smooth
// problem's order. -ic_average gives the cell averages of the conservative state by 3 x 3 (x 3) Gauss points
// (exact for quintics): it places a discontinuity at its sub-cell position (curved interfaces without the
// staircase) but differs from the point values by dx^2/24 of the second derivative on smooth data. Against the
// exact cell averages a linear flow keeps the scheme's order (the averages of a translated density wave are
// themselves a translated wave: measured order 6.0, tests/euler/euler_user_check.py average); a nonlinear one does
// not in general (the average of a solution is not a solution: an O(dx^2) defect of the fluxes).
#include "core/expression.hpp"
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>
#include <memory>

namespace suite::euler {

PetscErrorCode createFormulaProblem(MPI_Comm comm, int dim, ProblemND* pr) {
  static const char* const kNames[5] = {"-ic_rho", "-ic_u", "-ic_v", "-ic_w", "-ic_p"};
  static const char* const kHelp[5] = {"Initial density: a formula of x[, y[, z]]", "Initial x velocity",
                                       "Initial y velocity (-dim 2|3)", "Initial z velocity (-dim 3)",
                                       "Initial pressure: a formula of x[, y[, z]]"};
  std::string text[5] = {"", "0", "0", "0", ""}, params;
  PetscBool set[5] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
  PetscBool average = PETSC_FALSE;
  double gamma = 1.4;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Formula problem options", "");
  for (int f = 0; f < 5; ++f) {
    if ((f == 2 && dim < 2) || (f == 3 && dim < 3)) continue; // not read: given anyway, an unused option
    PetscCall(suite::optionsString(PetscOptionsObject, kNames[f], kHelp[f], &text[f], &set[f]));
  }
  PetscCall(suite::optionsString(PetscOptionsObject, "-ic_param",
                                 "Named constants of the formulas: name=value,name=value", &params, nullptr));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-ic_average",
                               "Cell averages by Gauss quadrature instead of point values at the centres", "",
                               average, &average, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  PetscCheck(
      set[0] && set[4], comm, PETSC_ERR_ARG_WRONG,
      "-problem formula needs -ic_rho and -ic_p (formulas of the cell centre%s; velocities default to 0)",
      dim == 1 ? " x" : (dim == 2 ? " x, y" : " x, y, z"));
  const std::vector<std::string> vars = dim == 1   ? std::vector<std::string>{"x"}
                                        : dim == 2 ? std::vector<std::string>{"x", "y"}
                                                   : std::vector<std::string>{"x", "y", "z"};
  suite::NamedValues constants;
  PetscCall(suite::parseNamedValues(comm, "-ic_param", params, vars, &constants));
  std::shared_ptr<const suite::Expression> e[5];
  for (int f = 0; f < 5; ++f)
    PetscCall(suite::Expression::create(comm, kNames[f], text[f], vars, constants, &e[f]));
  pr->gamma = gamma;
  pr->initial_quadrature = average ? 3 : 0;
  pr->initial = [e](const double* x) {
    PrimN w{(*e[0])(x), {(*e[1])(x), (*e[2])(x), (*e[3])(x)}, (*e[4])(x)};
    return w;
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
