// -error: errors of the final state. 1D: L1, L2 (normalised by the domain length) and Linf of rho, u and p
// against the exact solution (exact Riemann solver, advected profiles) or, with -reference, a finer grid run's
// final state interpolated linearly to this grid's cell centres. 2D/3D: density errors (mean over the cells)
// against the exact solution.
#include "euler_run.hpp"

#include "core/log.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
#include <cmath>

namespace euler_app {

// ref[c] at this rank's cells, c = rho, u, p; scale[c] = max |fine value|.
PetscErrorCode EulerRun::readReference(std::vector<double> ref[3], double scale[3]) const {
  suite::H5Input in;
  const PetscInt nx = opt_.n[0];
  PetscFunctionBeginUser;
  PetscCall(in.open(ctx_.comm(), opt_.reference));
  const char* names[3] = {"/final/rho", "/final/u", "/final/p"};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> fine;
    suite::Dims dims;
    PetscCall(in.readAll(names[c], &fine, &dims));
    const long long nf = (long long)fine.size();
    PetscCheck(nf >= nx && nf % nx == 0, ctx_.comm(), PETSC_ERR_ARG_SIZ,
               "-reference %s has %lld cells: must be a multiple of -nx %" PetscInt_FMT,
               opt_.reference.c_str(), nf, nx);
    const long long r = nf / nx;
    for (PetscInt k = 0; k < m_[0]; ++k) { // linear interpolation of the fine point values at x_j
      const double s = (s_[0] + k + 0.5) * r - 0.5;
      const long long i0 = (long long)std::floor(s);
      const double w = s - i0;
      ref[c][k] = (1.0 - w) * fine[i0] + (w > 0 ? w * fine[std::min(i0 + 1, nf - 1)] : 0.0);
    }
    for (double v : fine) scale[c] = std::max(scale[c], std::abs(v));
  }
  PetscCall(in.close());
  PetscFunctionReturn(0);
}

// ref[c] at this rank's cells, c = rho, u, p: the exact solution at the final time.
void EulerRun::exactLineFields(std::vector<double> ref[3]) const {
  for (PetscInt k = 0; k < m_[0]; ++k) {
    double x[3];
    cellCentre(s_[0] + k, 0, 0, x);
    const suite::euler::PrimN w = problem_.exact(x, time_);
    ref[0][k] = w.rho, ref[1][k] = w.u[0], ref[2][k] = w.p;
  }
}

PetscErrorCode EulerRun::computeLineErrors() {
  std::vector<double> fields[5];
  std::vector<double>* ref = err_.exact;
  double scale[3] = {0, 0, 0}, sums[6] = {0, 0, 0, 0, 0, 0}, maxes[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  const std::vector<double>* num[3] = {&fields[0], &fields[1], &fields[4]};
  for (int c = 0; c < 3; ++c) ref[c].resize(m_[0]);
  if (!opt_.reference.empty())
    PetscCall(readReference(ref, scale));
  else
    exactLineFields(ref);
  for (int c = 0; c < 3; ++c)
    for (PetscInt k = 0; k < m_[0]; ++k) {
      const double e = std::abs((*num[c])[k] - ref[c][k]);
      sums[c] += e * dx_[0];
      sums[3 + c] += e * e * dx_[0];
      maxes[c] = std::isnan(e) ? INFINITY : std::max(maxes[c], e);
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sums, 6, MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, maxes, 3, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  const double L = problem_.hi[0] - problem_.lo[0];
  const char* vn[3] = {"rho", "u", "p"};
  for (int c = 0; c < 3; ++c) {
    err_.l1[c] = sums[c] / L;
    err_.l2[c] = std::sqrt(sums[3 + c] / L);
    err_.linf[c] = maxes[c];
    PetscCall(suite::logInfo(ctx_.comm(), false, "error %s: L1 %.6e L2 %.6e Linf %.6e (against %s)", vn[c],
                             err_.l1[c], err_.l2[c], err_.linf[c],
                             opt_.reference.empty() ? "exact solution" : opt_.reference.c_str()));
  }
  if (!opt_.reference.empty()) {
    double rel = 0;
    for (int c = 0; c < 3; ++c) rel = std::max(rel, err_.linf[c] / std::max(scale[c], 1e-300));
    PetscCall(suite::logInfo(ctx_.comm(), false, "reference max relative difference %.6e", rel));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::computeGridErrors() {
  std::vector<double> fields[5];
  double sums[2] = {0, 0}, linf = 0.0;
  size_t c = 0;
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
    for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
      for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i, ++c) {
        double x[3];
        cellCentre(i, j, k, x);
        const double e = std::abs(fields[0][c] - problem_.exact(x, time_).rho);
        sums[0] += e;
        sums[1] += e * e;
        linf = std::isnan(e) ? INFINITY : std::max(linf, e);
      }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &linf, 1, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  const double ncell = (double)opt_.n[0] * opt_.n[1] * opt_.n[2];
  err_.l1[0] = sums[0] / ncell; // mean over the cells = (1/|domain|) integral
  err_.l2[0] = std::sqrt(sums[1] / ncell);
  err_.linf[0] = linf;
  PetscCall(suite::logInfo(ctx_.comm(), false,
                           "error rho: L1 %.6e L2 %.6e Linf %.6e (against exact solution)", err_.l1[0],
                           err_.l2[0], err_.linf[0]));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::computeErrors() {
  PetscFunctionBeginUser;
  PetscCall(dim() == 1 ? computeLineErrors() : computeGridErrors());
  err_.have = true;
  PetscFunctionReturn(0);
}

} // namespace euler_app
