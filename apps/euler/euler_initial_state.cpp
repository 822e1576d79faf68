// The Euler run's initial conserved state (see euler_run.hpp): from the problem's initial function at the cell
// centres (or, -ic_average, its cell averages of the conservative state by Gauss-Legendre points), or from an
// HDF5 file (lib/euler/initial_state_file.hpp); a user's formula that is not a physical state somewhere is one
// error naming the formula and the cell. -output_initial writes the result to /initial.
#include "euler_run.hpp"

#include "core/error_handler.hpp"
#include "euler/initial_state_file.hpp"
#include "euler_state.hpp"

#include <cmath>
#include <cstdio>

namespace euler_app {

using namespace suite::euler;

namespace {
// Where a user's formulas give no physical state at x: "" when they do.
std::string unphysical(const PrimN& w, int dim, const double* x, const PetscInt idx[3]) {
  static const char* const kOption[5] = {"-ic_rho", "-ic_u", "-ic_v", "-ic_w", "-ic_p"};
  const double v[5] = {w.rho, w.u[0], w.u[1], w.u[2], w.p};
  for (int f = 0; f < 5; ++f) {
    if ((f == 2 && dim < 2) || (f == 3 && dim < 3)) continue;
    const bool bad = !std::isfinite(v[f]) || ((f == 0 || f == 4) && v[f] <= 0.0);
    if (!bad) continue;
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s evaluates to %g at cell (%d, %d, %d), x = (%g, %g, %g)%s", kOption[f],
                  v[f], (int)idx[0], (int)idx[1], (int)idx[2], x[0], x[1], x[2],
                  f == 0 ? ": density must be > 0" : (f == 4 ? ": pressure must be > 0" : ": not finite"));
    return buf;
  }
  return "";
}
} // namespace

PetscErrorCode EulerRun::initialFromProblem(double* u) {
  // 3-point Gauss-Legendre on [-1/2, 1/2] (exact for quintics)
  static const double kNode[3] = {-0.5 * std::sqrt(0.6), 0.0, 0.5 * std::sqrt(0.6)};
  static const double kWeight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  const int nq = problem_.initial_quadrature;
  std::string bad;
  PetscFunctionBeginUser;
  size_t idx = 0;
  for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
    for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
      for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i, idx += nv()) {
        const PetscInt cell[3] = {i, j, k};
        double x[3];
        cellCentre(i, j, k, x);
        if (nq == 0) {
          const PrimN w = problem_.initial(x);
          if (problem_.user_defined && bad.empty()) bad = unphysical(w, dim(), x, cell);
          conservative(w, dim(), problem_.gamma, u + idx);
          continue;
        }
        double sum[5] = {0, 0, 0, 0, 0};
        const int na = nq, nb = dim() >= 2 ? nq : 1, nc = dim() == 3 ? nq : 1;
        for (int c = 0; c < nc; ++c)
          for (int b = 0; b < nb; ++b)
            for (int a = 0; a < na; ++a) {
              const int pt[3] = {a, b, c};
              double xq[3], wq = 1.0, q[5];
              for (int d = 0; d < 3; ++d) {
                xq[d] = x[d];
                if (d >= dim()) continue;
                xq[d] += kNode[pt[d]] * dx_[d];
                wq *= kWeight[pt[d]];
              }
              const PrimN w = problem_.initial(xq);
              if (problem_.user_defined && bad.empty()) bad = unphysical(w, dim(), xq, cell);
              conservative(w, dim(), problem_.gamma, q);
              for (int v = 0; v < nv(); ++v) sum[v] += wq * q[v];
            }
        for (int v = 0; v < nv(); ++v) u[idx + v] = sum[v];
      }
  PetscCall(suite::agreeOnFailure(ctx_.comm(), &bad));
  PetscCheck(bad.empty(), ctx_.comm(), PETSC_ERR_ARG_WRONG, "-problem formula: %s", bad.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::initialFromFile(double* u) {
  const InitialStateFile& f = *problem_.initial_state; // inspected with the options
  std::vector<double> values;
  PetscFunctionBeginUser;
  PetscCall(readInitialStateBlock(ctx_.comm(), f, dim(), problem_.gamma, s_, m_, &values));
  for (PetscInt c = 0; c < localCells(); ++c) {
    const double* v = &values[(size_t)c * nv()];
    if (f.conservative) {
      for (int q = 0; q < nv(); ++q) u[c * nv() + q] = v[q];
      continue;
    }
    PrimN w{v[0], {0, 0, 0}, v[nv() - 1]};
    for (int d = 0; d < dim(); ++d) w.u[d] = v[1 + d];
    conservative(w, dim(), problem_.gamma, u + c * nv());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::setInitialState() {
  PetscScalar* u;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(da_, &U_));
  PetscCall(VecGetArray(U_, &u));
  PetscErrorCode ierr = problem_.initial_file.empty() ? initialFromProblem(u) : initialFromFile(u);
  PetscCall(VecRestoreArray(U_, &u));
  PetscCall(ierr);
  PetscCall(totals(U_, &totals0_));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeInitial() {
  static const char* const kNames[3][5] = {
      {"rho", "mom_x", "E"}, {"rho", "mom_x", "mom_y", "E"}, {"rho", "mom_x", "mom_y", "mom_z", "E"}};
  const PetscScalar* a;
  suite::Dims dims, start, count;
  std::vector<double> field(localCells());
  PetscFunctionBeginUser;
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  blockDims(&dims, &start, &count);
  PetscCall(VecGetArrayRead(U_, &a));
  for (int v = 0; v < nv(); ++v) {
    for (PetscInt c = 0; c < localCells(); ++c) field[c] = a[c * nv() + v];
    PetscCall(out_.writeDistributed(std::string("/initial/") + kNames[dim() - 1][v], field.data(), dims,
                                    start, count, ""));
  }
  PetscCall(VecRestoreArrayRead(U_, &a));
  PetscFunctionReturn(0);
}

} // namespace euler_app
