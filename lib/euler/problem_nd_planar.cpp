// Planar problems: any 1D problem of problem.hpp (sod, lax, shu_osher, density_wave, pulse, ...) placed along
// axis `axis` (-axis x|y|z) of a dim-D grid. Along the axis: the 1D domain, end time, boundary conditions and
// default cell count; velocity along the axis, zero across it. The other directions are [0, 1], periodic,
// 6 cells by default (the app's minimum, its stencil width; 1 for the unused z of a 2D grid), so the solution
// is the 1D one, constant across the axis; the exact solution (where the 1D problem has one) maps the same
// way. 1D Inflow boundaries become Custom faces whose ghost state is the 1D inflow state (velocity along the
// axis).
// The same references as the 1D problems apply (see problem_riemann.cpp, problem_shock_entropy.cpp, ...).
#include "euler/problem_nd.hpp"

namespace suite::euler {

namespace {
PrimN alongAxis(const Prim& w, int axis) {
  PrimN q{w.rho, {0.0, 0.0, 0.0}, w.p};
  q.u[axis] = w.u;
  return q;
}
} // namespace

BcN gridBc(Bc bc) {
  switch (bc) {
  case Bc::Periodic:
    return BcN::Periodic;
  case Bc::Outflow:
    return BcN::Outflow;
  case Bc::Reflecting:
    return BcN::Reflecting;
  case Bc::Inflow:
    return BcN::Custom;
  }
  return BcN::Outflow;
}

PetscErrorCode createPlanarProblemND(MPI_Comm comm, const std::string& name, int dim, int axis,
                                     ProblemND* pr) {
  PetscFunctionBeginUser;
  PetscCheck(axis >= 0 && axis < dim, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -axis %c for the planar problem '%s': a %d-D grid has axes x%s",
             axis >= 0 && axis < 3 ? "xyz"[axis] : '?', name.c_str(), dim, dim == 3 ? ", y, z" : ", y");
  Problem p1;
  p1.name = name;
  PetscCall(createProblem(comm, name, &p1));
  pr->gamma = p1.gamma;
  pr->t_final = p1.t_final;
  pr->default_max_steps = p1.default_max_steps;
  pr->default_dt = p1.default_dt;
  for (int d = 0; d < 3; ++d) {
    pr->lo[d] = 0.0;
    pr->hi[d] = 1.0;
    pr->bc[d][0] = pr->bc[d][1] = BcN::Periodic;
    pr->default_n[d] = d < dim ? 6 : 1;
  }
  pr->lo[axis] = p1.xmin;
  pr->hi[axis] = p1.xmax;
  pr->default_n[axis] = p1.default_nx;
  pr->bc[axis][0] = gridBc(p1.bc_left);
  pr->bc[axis][1] = gridBc(p1.bc_right);
  const auto init1 = p1.initial;
  pr->initial = [init1, axis](const double* x) { return alongAxis(init1(x[axis]), axis); };
  if (p1.exact) {
    const auto exact1 = p1.exact;
    pr->exact = [exact1, axis](const double* x, double t) { return alongAxis(exact1(x[axis], t), axis); };
  }
  if (p1.bc_left == Bc::Inflow || p1.bc_right == Bc::Inflow) {
    const PrimN left = alongAxis(p1.inflow_left, axis), right = alongAxis(p1.inflow_right, axis);
    pr->ghost = [left, right](int, int side, const double*, double, const PrimN&, const PrimN&) {
      return side == 0 ? left : right;
    };
  }
  PetscFunctionReturn(0);
}

} // namespace suite::euler
