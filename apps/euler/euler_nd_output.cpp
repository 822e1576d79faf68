// 2D/3D Euler output: final fields and snapshots in (z, y, x) array order written collectively, cell centres,
// density errors against the exact solution, kinetic-energy spectrum E(k) (FFTW-MPI), XDMF sidecar.
#include "euler_nd_run.hpp"

#include "core/log.hpp"
#include "fft/energy_spectrum.hpp"
#include "io/xdmf.hpp"

#include <cmath>

namespace euler_app {

using namespace suite::euler;

void EulerRunND::blockDims(suite::Dims* dims, suite::Dims* start, suite::Dims* count) const {
  dims->clear(), start->clear(), count->clear();
  for (int d = opt_.dim - 1; d >= 0; --d) { // slowest first: (z,) y, x
    dims->push_back((unsigned long long)opt_.n[d]);
    start->push_back((unsigned long long)s_[d]);
    count->push_back((unsigned long long)m_[d]);
  }
}

PetscErrorCode EulerRunND::primitiveFields(Vec U, std::vector<double> fields[5]) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  const PetscInt ncell = m_[0] * m_[1] * m_[2];
  for (int f = 0; f < 5; ++f) fields[f].resize(ncell);
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < ncell; ++c) {
    const double* q = a + c * nv();
    double ke = 0.0;
    fields[0][c] = q[0];
    for (int d = 0; d < 3; ++d) {
      const double u = d < opt_.dim ? q[1 + d] / q[0] : 0.0;
      fields[1 + d][c] = u;
      if (d < opt_.dim) ke += 0.5 * q[1 + d] * u;
    }
    fields[4][c] = (problem_.gamma - 1.0) * (q[nv() - 1] - ke);
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::writeFields(const std::string& group, Vec U) {
  std::vector<double> fields[5];
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U, fields));
  suite::Dims dims, start, count;
  blockDims(&dims, &start, &count);
  const char* names[5] = {"rho", "u", "v", "w", "p"};
  for (int f = 0; f < 5; ++f)
    PetscCall(out_.writeDistributed(group + "/" + names[f], fields[f].data(), dims, start, count, ""));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::writeSnapshot(PetscInt step, double time) {
  PetscFunctionBeginUser;
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  char group[64];
  PetscCall(PetscSNPrintf(group, sizeof(group), "/snapshots/%06" PetscInt_FMT, step));
  PetscCall(writeFields(group, U_));
  if (opt_.spectrum) PetscCall(writeSpectrum(std::string(group) + "/spectrum"));
  PetscCall(out_.writeAttribute(group, "time", time));
  PetscCall(out_.writeAttribute(group, "step", (long long)step));
  snapshots_.push_back({step, time});
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::computeErrors() {
  std::vector<double> fields[5];
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  double sums[2] = {0, 0}, linf = 0.0;
  size_t c = 0;
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
  err_l1_ = sums[0] / ncell; // mean over the cells = (1/|domain|) integral
  err_l2_ = std::sqrt(sums[1] / ncell);
  err_linf_ = linf;
  have_errors_ = true;
  PetscCall(suite::logInfo(ctx_.comm(), false,
                           "error rho: L1 %.6e L2 %.6e Linf %.6e (against exact solution)", err_l1_, err_l2_,
                           err_linf_));
  PetscFunctionReturn(0);
}

// E(k) of sqrt(rho) u (so that sum_k E(k) is the mean kinetic energy), in box wavenumbers, into group/k, group/E.
PetscErrorCode EulerRunND::writeSpectrum(const std::string& group) {
  std::vector<double> fields[5];
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  std::vector<double> comp[3];
  std::vector<const double*> ptrs;
  for (int d = 0; d < opt_.dim; ++d) {
    comp[d].resize(fields[0].size());
    for (size_t c = 0; c < fields[0].size(); ++c) comp[d][c] = std::sqrt(fields[0][c]) * fields[1 + d][c];
    ptrs.push_back(comp[d].data());
  }
  suite::fft::Block block;
  suite::Dims dims, start, count;
  blockDims(&dims, &start, &count);
  for (size_t e = 0; e < dims.size(); ++e) {
    block.dims.push_back((long long)dims[e]);
    block.start.push_back((long long)start[e]);
    block.count.push_back((long long)count[e]);
  }
  std::vector<double> E;
  PetscCall(suite::fft::energySpectrum(ctx_.comm(), block, ptrs, &E));
  std::vector<double> k(E.size());
  double total = 0.0;
  for (size_t i = 0; i < E.size(); ++i) k[i] = (double)i, total += E[i];
  PetscCall(out_.writeReplicated(group + "/k", k.data(), {(unsigned long long)k.size()}, ""));
  PetscCall(out_.writeReplicated(group + "/E", E.data(), {(unsigned long long)E.size()}, ""));
  PetscCall(out_.writeAttribute(group, "field", "sqrt(rho) u"));
  PetscCall(out_.writeAttribute(group, "sum_E", total));
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(), "spectrum %s: %zu shells, sum E(k) = %.12e",
                           group.c_str(), E.size(), total));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::writeXdmf() {
  PetscFunctionBeginUser;
  const char* names[5] = {"rho", "u", "v", "w", "p"};
  std::vector<suite::XdmfStep> steps;
  auto step = [&](double t, const std::string& g) {
    suite::XdmfStep s{t, {}};
    for (int f = 0; f < 5; ++f)
      if (f < 1 + opt_.dim || f == 4) s.attributes.push_back({names[f], g + "/" + names[f], true});
    return s;
  };
  for (const auto& s : snapshots_) {
    char g[64];
    PetscCall(PetscSNPrintf(g, sizeof(g), "/snapshots/%06" PetscInt_FMT, s.first));
    steps.push_back(step(s.second, g));
  }
  steps.push_back(step(time_, "/final"));
  const std::string h5name = fileNameOf(opt_.output), xmf = xdmfPathFor(opt_.output);
  suite::XdmfRectGrid grid;
  for (int d = opt_.dim - 1; d >= 0; --d) {
    grid.dims.push_back((unsigned long long)opt_.n[d] + 1);
    grid.origin.push_back(problem_.lo[d]);
    grid.spacing.push_back(dx_[d]);
  }
  PetscCall(suite::writeXdmfRectSeries(ctx_.comm(), xmf, h5name, grid, steps));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRunND::writeOutput() {
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(0);
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  PetscCall(out_.writeProvenance(ctx_));
  PetscCall(out_.writeAttribute("/", "problem", opt_.problem));
  PetscCall(out_.writeAttribute("/", "scheme", opt_.scheme));
  PetscCall(out_.writeAttribute("/", "time_integrator", opt_.time));
  PetscCall(out_.writeAttribute("/", "dim", opt_.dim));
  PetscCall(out_.writeAttribute("/", "nx", (long long)opt_.n[0]));
  PetscCall(out_.writeAttribute("/", "ny", (long long)opt_.n[1]));
  PetscCall(out_.writeAttribute("/", "nz", (long long)opt_.n[2]));
  PetscCall(out_.writeAttribute("/", "time", time_));
  PetscCall(out_.writeAttribute("/", "steps", (long long)steps_));
  PetscCall(out_.writeAttribute("/", "gamma", problem_.gamma));
  PetscCall(out_.writeAttribute("/", "cfl", opt_.cfl));
  PetscCall(out_.writeAttribute("/", "characteristic", opt_.characteristic ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "positivity_limiter", opt_.positivity ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "solve_seconds", wall_solve_));
  PetscCall(out_.writeAttribute("/", "solve_cpu_seconds_rank0", cpu_solve_));
  std::vector<double> tot;
  PetscCall(totals(U_, &tot));
  PetscCall(out_.writeAttribute("/", "totals_initial", totals0_));
  PetscCall(out_.writeAttribute("/", "totals_final", tot));
  if (have_errors_) {
    PetscCall(out_.writeAttribute("/errors", "l1_rho", err_l1_));
    PetscCall(out_.writeAttribute("/errors", "l2_rho", err_l2_));
    PetscCall(out_.writeAttribute("/errors", "linf_rho", err_linf_));
  }
  const char* axes[3] = {"/grid/x", "/grid/y", "/grid/z"};
  for (int d = 0; d < opt_.dim; ++d) {
    std::vector<double> xc(opt_.n[d]);
    for (PetscInt i = 0; i < opt_.n[d]; ++i) xc[i] = problem_.lo[d] + (i + 0.5) * dx_[d];
    PetscCall(out_.writeReplicated(axes[d], xc.data(), {(unsigned long long)xc.size()}, ""));
  }
  PetscCall(writeFields("/final", U_));
  if (opt_.spectrum) PetscCall(writeSpectrum("/spectrum"));
  PetscCall(writeXdmf());
  PetscCall(out_.commit(&ctx_));
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(), "euler: wrote %s", opt_.output.c_str()));
  PetscFunctionReturn(0);
}

} // namespace euler_app
