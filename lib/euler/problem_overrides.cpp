// The user's domain and face conditions for any problem (see problem_overrides.hpp).
#include "euler/problem_overrides.hpp"

#include "core/expression.hpp"
#include "core/named_choice.hpp"
#include "core/option_value.hpp"

#include <array>
#include <cmath>
#include <memory>

namespace suite::euler {

namespace {
const char kAxis[3] = {'x', 'y', 'z'};

const std::vector<suite::Choice> kFaces = {
    {"outflow", "zero-gradient extrapolation"},
    {"wall", "reflecting slip wall"},
    {"symmetry", "symmetry plane (the same mirror as wall)"},
    {"periodic", "periodic (both faces of the direction)"},
    {"inflow", "a prescribed state (-bc_<face>_state rho,u[,v[,w]],p: formulas of x, y, z, t)"},
    {"custom", "the problem's own face (double_mach, jet, a 1D inflow): only as the default"}};

using FaceState = std::array<std::shared_ptr<const suite::Expression>, 5>; // rho, u.. (dim), p
using FaceStates = std::array<std::array<FaceState, 2>, 3>;

// -bc_<face>_state of an inflow face: dim + 2 formulas.
PetscErrorCode readInflowState(PetscOptionItems* PetscOptionsObject, MPI_Comm comm, int dim,
                               const std::string& face, FaceState* state) {
  const std::string option = "-bc_" + face + "_state";
  std::string text;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(suite::optionsString(PetscOptionsObject, option.c_str(),
                                 "Inflow state of the face: rho,u[,v[,w]],p (formulas of x, y, z, t)", &text,
                                 &set));
  PetscCheck(set, comm, PETSC_ERR_ARG_WRONG, "-bc_%s inflow needs %s rho,%s,p (formulas of x, y, z, t)",
             face.c_str(), option.c_str(), dim == 1 ? "u" : (dim == 2 ? "u,v" : "u,v,w"));
  const std::vector<std::string> items = suite::splitTopLevelCommas(text);
  PetscCheck((int)items.size() == dim + 2, comm, PETSC_ERR_ARG_WRONG,
             "%s \"%s\" has %d entries; a %dD state has %d: rho,%s,p", option.c_str(), text.c_str(),
             (int)items.size(), dim, dim + 2, dim == 1 ? "u" : (dim == 2 ? "u,v" : "u,v,w"));
  std::vector<std::string> vars;
  for (int d = 0; d < dim; ++d) vars.push_back(std::string(1, kAxis[d]));
  vars.push_back("t");
  for (int c = 0; c < dim + 2; ++c)
    PetscCall(suite::Expression::create(comm, option + " (entry " + std::to_string(c + 1) + ")", items[c],
                                        vars, {}, &(*state)[c]));
  PetscFunctionReturn(0);
}

// The inflow faces' ghost states, in front of the problem's own ghost function for the other faces.
void installInflowGhosts(ProblemND* pr, const FaceStates& states) {
  const auto previous = pr->ghost;
  const int dim = pr->dim;
  pr->ghost = [previous, states, dim](int d, int side, const double* x, double t, const PrimN& mirror,
                                      const PrimN& edge) {
    const FaceState& s = states[d][side];
    if (!s[0]) return previous(d, side, x, t, mirror, edge);
    double v[4] = {0, 0, 0, 0};
    for (int e = 0; e < dim; ++e) v[e] = x[e];
    v[dim] = t;
    PrimN w{s[0]->operator()(v), {0, 0, 0}, s[dim + 1]->operator()(v)};
    for (int e = 0; e < dim; ++e) w.u[e] = s[1 + e]->operator()(v);
    return w;
  };
}
} // namespace

PetscErrorCode readDomainOptions(MPI_Comm comm, int first_dir, ProblemND* pr) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Domain options", "");
  for (int d = first_dir; d < pr->dim; ++d) {
    const std::string lo = std::string("-") + kAxis[d] + "min", hi = std::string("-") + kAxis[d] + "max";
    double v[2] = {pr->lo[d], pr->hi[d]};
    PetscBool set[2] = {PETSC_FALSE, PETSC_FALSE};
    PetscCall(suite::optionsReal(PetscOptionsObject, lo.c_str(), "Low end of the domain", "", v[0], &v[0],
                                 &set[0]));
    PetscCall(suite::optionsReal(PetscOptionsObject, hi.c_str(), "High end of the domain", "", v[1], &v[1],
                                 &set[1]));
    for (int e = 0; e < 2; ++e)
      PetscCheck(!set[e] || !pr->fixed_extent[d] || v[e] == (e ? pr->hi[d] : pr->lo[d]), comm,
                 PETSC_ERR_ARG_WRONG, "%s %g differs from the extent %g of -initial_state %s",
                 (e ? hi : lo).c_str(), v[e], e ? pr->hi[d] : pr->lo[d], pr->initial_file.c_str());
    PetscCheck(v[1] > v[0], comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid domain: %s %g must exceed %s %g",
               hi.c_str(), v[1], lo.c_str(), v[0]);
    pr->lo[d] = v[0], pr->hi[d] = v[1];
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode readFaceOptions(MPI_Comm comm, ProblemND* pr) {
  FaceStates states{};
  bool any_inflow = false;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Boundary face options", "");
  for (int d = 0; d < pr->dim; ++d)
    for (int side = 0; side < 2; ++side) {
      const std::string face = std::string(1, kAxis[d]) + (side ? "_hi" : "_lo"), option = "-bc_" + face;
      std::string kind = faceLabel(*pr, d, side);
      if (kind == "reflecting") kind = "wall";
      PetscBool set = PETSC_FALSE;
      PetscCall(suite::optionsChoice(PetscOptionsObject, option.c_str(), "Boundary condition of the face",
                                     kFaces, &kind, &set));
      if (!set) continue;
      PetscBool line_name = PETSC_FALSE;
      if (pr->dim == 1)
        PetscCall(PetscOptionsHasName(nullptr, nullptr, side ? "-bc_right" : "-bc_left", &line_name));
      PetscCheck(!line_name, comm, PETSC_ERR_ARG_WRONG, "%s and %s name the same face: give one",
                 option.c_str(), side ? "-bc_right" : "-bc_left");
      PetscCheck(kind != "custom" || pr->bc[d][side] == BcN::Custom, comm, PETSC_ERR_ARG_WRONG,
                 "%s custom: this problem has no face of its own there", option.c_str());
      pr->bc_label[d][side] = kind == "custom" ? "" : kind;
      if (kind == "outflow") pr->bc[d][side] = BcN::Outflow;
      if (kind == "wall" || kind == "symmetry") pr->bc[d][side] = BcN::Reflecting;
      if (kind == "periodic") pr->bc[d][side] = BcN::Periodic;
      if (kind == "inflow") {
        pr->bc[d][side] = BcN::Custom;
        PetscCall(readInflowState(PetscOptionsObject, comm, pr->dim, face, &states[d][side]));
        any_inflow = true;
      }
    }
  PetscOptionsEnd();
  for (int d = 0; d < pr->dim; ++d)
    PetscCheck((pr->bc[d][0] == BcN::Periodic) == (pr->bc[d][1] == BcN::Periodic), comm, PETSC_ERR_ARG_WRONG,
               "Periodic boundaries come in pairs: -bc_%c_lo %s with -bc_%c_hi %s", kAxis[d],
               faceLabel(*pr, d, 0).c_str(), kAxis[d], faceLabel(*pr, d, 1).c_str());
  if (any_inflow) installInflowGhosts(pr, states);
  PetscFunctionReturn(0);
}

} // namespace suite::euler
