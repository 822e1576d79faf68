// Euler HDF5 output for -dim 1|2|3: snapshots and the final state as primitive fields in ((z,) (y,) x) array
// order written collectively (1D: rho, u, p; 2D/3D: rho, u, v, w, p; enopade6: the shock-row flags), cell centres /grid/x[, y, z], the run's
// attributes, and the XDMF sidecar of every snapshot plus the final state. What only one layout has: 1D the
// per-quantity totals and errors as root attributes, /exact and the x-t image /spacetime; 2D/3D the totals as
// arrays, /errors and the energy spectra.
#include "euler_run.hpp"

#include "core/log.hpp"
#include "euler_state.hpp"
#include "io/xdmf.hpp"

namespace euler_app {

using namespace suite::euler;

namespace {
const char* const kFieldNames[5] = {"rho", "u", "v", "w", "p"};
} // namespace

PetscErrorCode EulerRun::primitiveFields(Vec U, std::vector<double> fields[5]) const {
  const PetscScalar* a;
  PetscFunctionBeginUser;
  for (int f = 0; f < 5; ++f) fields[f].resize(localCells());
  PetscCall(VecGetArrayRead(U, &a));
  for (PetscInt c = 0; c < localCells(); ++c) {
    const PrimN w = primitive(a + c * nv(), dim(), problem_.gamma);
    fields[0][c] = w.rho, fields[4][c] = w.p;
    for (int d = 0; d < 3; ++d) fields[1 + d][c] = w.u[d];
  }
  PetscCall(VecRestoreArrayRead(U, &a));
  PetscFunctionReturn(0);
}

// group/rho, group/u, ..., group/p: 1D rho, u, p; 2D/3D all five (w = 0 in 2D); group/shock, the ENO-Pade
// shock rows of this state (euler_shock_flags.cpp), for enopade6. t: the state's time (boundary ghosts).
PetscErrorCode EulerRun::writeFields(const std::string& group, Vec U, double t) {
  std::vector<double> fields[5];
  suite::Dims dims, start, count;
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U, fields));
  blockDims(&dims, &start, &count);
  for (int f = 0; f < 5; ++f)
    if (dim() > 1 || f == 0 || f == 1 || f == 4)
      PetscCall(
          out_.writeDistributed(group + "/" + kFieldNames[f], fields[f].data(), dims, start, count, ""));
  if (hasShockFlags()) {
    PetscCall(shockFlags(U, t, &fields[0]));
    PetscCall(out_.writeDistributed(group + "/shock", fields[0].data(), dims, start, count, ""));
  }
  if (!solid_.empty()) {
    for (PetscInt c = 0; c < localCells(); ++c) fields[0][c] = solid_[c];
    PetscCall(out_.writeDistributed(group + "/mask", fields[0].data(), dims, start, count, ""));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeSnapshot(PetscInt step, double t) {
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(0);
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  char group[64];
  PetscCall(PetscSNPrintf(group, sizeof(group), "/snapshots/%06" PetscInt_FMT, step));
  PetscCall(writeFields(group, U_, t));
  if (opt_.spectrum) PetscCall(writeSpectrum(std::string(group) + "/spectrum"));
  PetscCall(out_.writeAttribute(group, "time", t));
  PetscCall(out_.writeAttribute(group, "step", (long long)step));
  snapshots_.push_back({step, t});
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeRunAttributes() {
  PetscFunctionBeginUser;
  PetscCall(out_.writeProvenance(ctx_));
  PetscCall(out_.writeAttribute("/", "problem", opt_.problem));
  PetscCall(out_.writeAttribute("/", "scheme", opt_.scheme));
  PetscCall(out_.writeAttribute("/", "time_integrator", opt_.time));
  if (dim() > 1) {
    PetscCall(out_.writeAttribute("/", "dim", dim()));
    PetscCall(out_.writeAttribute("/", "ny", (long long)opt_.n[1]));
    PetscCall(out_.writeAttribute("/", "nz", (long long)opt_.n[2]));
  }
  PetscCall(out_.writeAttribute("/", "nx", (long long)opt_.n[0]));
  PetscCall(out_.writeAttribute("/", "time", time_));
  PetscCall(out_.writeAttribute("/", "steps", (long long)step_));
  PetscCall(out_.writeAttribute("/", "status", status_));
  PetscCall(out_.writeAttribute("/", "gamma", problem_.gamma));
  // The domain and the faces (every dim: an -initial_state input carries its extents; 1D also bc_left/right)
  for (int d = 0; d < dim(); ++d) {
    const std::string axis(1, "xyz"[d]);
    if (dim() > 1) { // 1D: writeLineResults
      PetscCall(out_.writeAttribute("/", axis + "min", problem_.lo[d]));
      PetscCall(out_.writeAttribute("/", axis + "max", problem_.hi[d]));
    }
    PetscCall(out_.writeAttribute("/", "bc_" + axis + "_lo", faceLabel(problem_, d, 0)));
    PetscCall(out_.writeAttribute("/", "bc_" + axis + "_hi", faceLabel(problem_, d, 1)));
  }
  if (problem_.hasSolid()) PetscCall(out_.writeAttribute("/", "solid_cells", solid_cells_));
  PetscCall(out_.writeAttribute("/", "cfl", opt_.cfl));
  PetscCall(out_.writeAttribute("/", "characteristic", opt_.characteristic ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "positivity_limiter", opt_.positivity ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "steps_retried", (long long)retries_));
  PetscCall(out_.writeAttribute("/", "filter_alpha", opt_.filter_alpha));
  PetscCall(out_.writeAttribute("/", "filter_time", opt_.filter_time));
  if (hasShockFlags()) {
    PetscCall(out_.writeAttribute("/", "shock_threshold", opt_.shock_threshold));
    PetscCall(out_.writeAttribute("/", "shock_ppw", opt_.shock_ppw));
    PetscCall(out_.writeAttribute("/", "shock_rows", shock_rows_[0]));
    PetscCall(out_.writeAttribute("/", "shock_sensor_rows", shock_rows_[1]));
  }
  PetscCall(out_.writeAttribute("/", "setup_seconds", wall_setup_));
  PetscCall(out_.writeAttribute("/", "solve_seconds", wall_solve_));
  PetscCall(out_.writeAttribute("/", "solve_cpu_seconds_rank0", cpu_solve_));
  PetscFunctionReturn(0);
}

// 1D: domain and boundaries, totals and errors per quantity, the exact solution, the x-t image.
PetscErrorCode EulerRun::writeLineResults() {
  std::vector<double> tot;
  PetscFunctionBeginUser;
  // bc_left / bc_right in the 1D problems' names (reflecting for a wall or symmetry face, inflow for a custom one)
  auto lineName = [&](int side) {
    const std::string f = faceLabel(problem_, 0, side);
    return f == "wall" || f == "symmetry" ? std::string("reflecting")
           : f == "custom"                ? std::string("inflow")
                                          : f;
  };
  PetscCall(out_.writeAttribute("/", "xmin", problem_.lo[0]));
  PetscCall(out_.writeAttribute("/", "xmax", problem_.hi[0]));
  PetscCall(out_.writeAttribute("/", "bc_left", lineName(0)));
  PetscCall(out_.writeAttribute("/", "bc_right", lineName(1)));
  PetscCall(totals(U_, &tot));
  const char* cn[3] = {"mass", "momentum", "energy"};
  for (int c = 0; c < 3; ++c) {
    PetscCall(out_.writeAttribute("/", std::string("total_") + cn[c] + "_initial", totals0_[c]));
    PetscCall(out_.writeAttribute("/", std::string("total_") + cn[c] + "_final", tot[c]));
  }
  const suite::Dims dims{(unsigned long long)opt_.n[0]}, start{(unsigned long long)s_[0]},
      count{(unsigned long long)m_[0]};
  const char* vn[3] = {"rho", "u", "p"};
  if (err_.have) { // the errors, and the solution they were measured against for the profile plots
    for (int c = 0; c < 3; ++c) {
      PetscCall(out_.writeAttribute("/", std::string("error_l1_") + vn[c], err_.l1[c]));
      PetscCall(out_.writeAttribute("/", std::string("error_l2_") + vn[c], err_.l2[c]));
      PetscCall(out_.writeAttribute("/", std::string("error_linf_") + vn[c], err_.linf[c]));
    }
    PetscCall(out_.writeAttribute("/", "error_reference", opt_.reference.empty() ? "exact" : opt_.reference));
    for (int c = 0; c < 3; ++c)
      PetscCall(out_.writeDistributed(std::string("/exact/") + vn[c], err_.exact[c].data(), dims, start,
                                      count, ""));
  }
  if (!spacetime_t_.empty()) {
    const unsigned long long nrec = spacetime_t_.size();
    PetscCall(out_.writeDistributed("/spacetime/rho", spacetime_rho_.data(), {nrec, dims[0]}, {0, start[0]},
                                    {nrec, count[0]}, ""));
    PetscCall(out_.writeReplicated("/spacetime/time", spacetime_t_.data(), {nrec}, ""));
  }
  PetscFunctionReturn(0);
}

// 2D/3D: totals as arrays, density errors, the final energy spectrum.
PetscErrorCode EulerRun::writeGridResults() {
  std::vector<double> tot;
  PetscFunctionBeginUser;
  PetscCall(totals(U_, &tot));
  PetscCall(out_.writeAttribute("/", "totals_initial", totals0_));
  PetscCall(out_.writeAttribute("/", "totals_final", tot));
  if (err_.have) {
    PetscCall(out_.writeAttribute("/errors", "l1_rho", err_.l1[0]));
    PetscCall(out_.writeAttribute("/errors", "l2_rho", err_.l2[0]));
    PetscCall(out_.writeAttribute("/errors", "linf_rho", err_.linf[0]));
  }
  if (opt_.spectrum) PetscCall(writeSpectrum("/spectrum"));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeXdmf() {
  std::vector<suite::XdmfStep> steps;
  PetscFunctionBeginUser;
  auto step = [&](double t, const std::string& g) {
    suite::XdmfStep s{t, {}};
    for (int f = 0; f < 5; ++f)
      if (f < 1 + dim() || f == 4) s.attributes.push_back({kFieldNames[f], g + "/" + kFieldNames[f], true});
    if (hasShockFlags()) s.attributes.push_back({"shock", g + "/shock", true});
    if (!solid_.empty()) s.attributes.push_back({"mask", g + "/mask", true});
    return s;
  };
  for (const auto& s : snapshots_) {
    char g[64];
    PetscCall(PetscSNPrintf(g, sizeof(g), "/snapshots/%06" PetscInt_FMT, s.first));
    steps.push_back(step(s.second, g));
  }
  steps.push_back(step(time_, "/final"));
  suite::XdmfRectGrid grid;
  for (int d = dim() - 1; d >= 0; --d) {
    grid.dims.push_back((unsigned long long)opt_.n[d] + 1);
    grid.origin.push_back(problem_.lo[d]);
    grid.spacing.push_back(dx_[d]);
  }
  PetscCall(suite::writeXdmfRectSeries(ctx_.comm(), suite::xdmfPathFor(opt_.output),
                                       suite::fileNameOf(opt_.output), grid, steps));
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeOutput() {
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(0);
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  PetscCall(writeRunAttributes());
  PetscCall(dim() == 1 ? writeLineResults() : writeGridResults());
  const char* axes[3] = {"/grid/x", "/grid/y", "/grid/z"};
  for (int d = 0; d < dim(); ++d) {
    std::vector<double> xc(opt_.n[d]);
    for (PetscInt i = 0; i < opt_.n[d]; ++i) xc[i] = problem_.lo[d] + (i + 0.5) * dx_[d];
    PetscCall(out_.writeReplicated(axes[d], xc.data(), {(unsigned long long)xc.size()}, ""));
  }
  PetscCall(writeFields("/final", U_, time_));
  PetscCall(writeXdmf());
  PetscCall(out_.commit(&ctx_));
  PetscFunctionReturn(0);
}

} // namespace euler_app
