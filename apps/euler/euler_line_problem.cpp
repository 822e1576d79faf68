// A 1D problem (problem.hpp) described as a problem of a 1-D grid (ProblemND with dim 1): the domain, end time,
// boundary conditions and the initial and exact states along x; an Inflow boundary becomes a Custom face whose
// ghost state is the problem's inflow state. The other directions are unused (one periodic cell).
#include "euler_options.hpp"

namespace euler_app {

using namespace suite::euler;

namespace {
PrimN alongX(const Prim& w) {
  return PrimN{w.rho, {w.u, 0.0, 0.0}, w.p};
}
} // namespace

void lineProblemAsGrid(const Problem& line, ProblemND* pr) {
  *pr = ProblemND{};
  pr->name = line.name;
  pr->dim = 1;
  pr->gamma = line.gamma;
  pr->t_final = line.t_final;
  pr->lo[0] = line.xmin;
  pr->hi[0] = line.xmax;
  pr->default_n[0] = line.default_nx;
  pr->default_n[1] = pr->default_n[2] = 1;
  pr->bc[0][0] = gridBc(line.bc_left);
  pr->bc[0][1] = gridBc(line.bc_right);
  pr->default_max_steps = line.default_max_steps;
  pr->default_dt = line.default_dt;
  const auto initial = line.initial;
  pr->initial = [initial](const double* x) { return alongX(initial(x[0])); };
  if (line.exact) {
    const auto exact = line.exact;
    pr->exact = [exact](const double* x, double t) { return alongX(exact(x[0], t)); };
  }
  const Prim in[2] = {line.inflow_left, line.inflow_right};
  pr->ghost = [in](int, int side, const double*, double, const PrimN&, const PrimN&) {
    return alongX(in[side]);
  };
}
} // namespace euler_app
