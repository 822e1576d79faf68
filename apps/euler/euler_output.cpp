// Euler run output: snapshots, final state, grid, provenance, errors (exact or reference), XDMF sidecar, x-t
// data.
#include "euler_run.hpp"

#include "core/log.hpp"
#include "io/h5_input.hpp"
#include "io/xdmf.hpp"

#include <cmath>

namespace euler_app {

using namespace suite::euler;

PetscErrorCode EulerRun::writeSnapshot(PetscInt step, double time) {
  std::vector<double> rho, u, p;
  PetscFunctionBeginUser;
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  PetscCall(primitiveArrays(U_, &rho, &u, &p));
  char group[64];
  PetscCall(PetscSNPrintf(group, sizeof(group), "/snapshots/%06" PetscInt_FMT, step));
  const suite::Dims dims{(unsigned long long)opt_.nx}, start{(unsigned long long)xs_},
      count{(unsigned long long)xm_};
  const std::string g(group);
  PetscCall(out_.writeDistributed(g + "/rho", rho.data(), dims, start, count, ""));
  PetscCall(out_.writeDistributed(g + "/u", u.data(), dims, start, count, ""));
  PetscCall(out_.writeDistributed(g + "/p", p.data(), dims, start, count, ""));
  PetscCall(out_.writeAttribute(g, "time", time));
  PetscCall(out_.writeAttribute(g, "step", (long long)step));
  snapshots_.push_back({step, time});
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::computeErrors() {
  std::vector<double> rho, u, p;
  PetscFunctionBeginUser;
  PetscCall(primitiveArrays(U_, &rho, &u, &p));
  const std::vector<double>* num[3] = {&rho, &u, &p};
  std::vector<double>* ref = exact_;
  for (int c = 0; c < 3; ++c) ref[c].resize(xm_);
  double scale[3] = {0, 0, 0};
  if (!opt_.reference.empty()) {
    suite::H5Input in;
    PetscCall(in.open(ctx_.comm(), opt_.reference));
    const char* names[3] = {"/final/rho", "/final/u", "/final/p"};
    for (int c = 0; c < 3; ++c) {
      std::vector<double> fine;
      suite::Dims dims;
      PetscCall(in.readAll(names[c], &fine, &dims));
      const long long nf = (long long)fine.size();
      PetscCheck(nf >= opt_.nx && nf % opt_.nx == 0, ctx_.comm(), PETSC_ERR_ARG_SIZ,
                 "-reference %s has %lld cells: must be a multiple of -nx %" PetscInt_FMT,
                 opt_.reference.c_str(), nf, opt_.nx);
      const long long r = nf / opt_.nx;
      for (PetscInt k = 0; k < xm_; ++k) { // linear interpolation of the fine point values at x_j
        const double s = (xs_ + k + 0.5) * r - 0.5;
        const long long i0 = (long long)std::floor(s);
        const double w = s - i0;
        ref[c][k] = (1.0 - w) * fine[i0] + (w > 0 ? w * fine[std::min(i0 + 1, nf - 1)] : 0.0);
      }
      for (double v : fine) scale[c] = std::max(scale[c], std::abs(v));
    }
    PetscCall(in.close());
  } else {
    for (PetscInt k = 0; k < xm_; ++k) {
      const Prim w = problem_.exact(xc_[k], time_);
      ref[0][k] = w.rho, ref[1][k] = w.u, ref[2][k] = w.p;
    }
  }
  double sums[6] = {0, 0, 0, 0, 0, 0}, maxes[6] = {0, 0, 0, 0, 0, 0};
  for (int c = 0; c < 3; ++c)
    for (PetscInt k = 0; k < xm_; ++k) {
      const double e = std::abs((*num[c])[k] - ref[c][k]);
      sums[c] += e * dx_;
      sums[3 + c] += e * e * dx_;
      maxes[c] = std::isnan(e) ? INFINITY : std::max(maxes[c], e);
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sums, 6, MPI_DOUBLE, MPI_SUM, ctx_.comm()));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, maxes, 3, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  const double L = problem_.xmax - problem_.xmin;
  for (int c = 0; c < 3; ++c) {
    errors_.l1[c] = sums[c] / L;
    errors_.l2[c] = std::sqrt(sums[3 + c] / L);
    errors_.linf[c] = maxes[c];
  }
  have_errors_ = true;
  const char* vn[3] = {"rho", "u", "p"};
  for (int c = 0; c < 3; ++c)
    PetscCall(suite::logInfo(ctx_.comm(), false, "error %s: L1 %.6e L2 %.6e Linf %.6e (against %s)", vn[c],
                             errors_.l1[c], errors_.l2[c], errors_.linf[c],
                             opt_.reference.empty() ? "exact solution" : opt_.reference.c_str()));
  if (!opt_.reference.empty()) {
    double rel = 0;
    for (int c = 0; c < 3; ++c) rel = std::max(rel, errors_.linf[c] / std::max(scale[c], 1e-300));
    ref_diff_ = rel;
    PetscCall(suite::logInfo(ctx_.comm(), false, "reference max relative difference %.6e", rel));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::writeOutput() {
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(0);
  if (!out_.isOpen()) PetscCall(out_.open(ctx_.comm(), opt_.output));
  PetscCall(out_.writeProvenance(ctx_));
  PetscCall(out_.writeAttribute("/", "problem", opt_.problem));
  PetscCall(out_.writeAttribute("/", "scheme", opt_.scheme));
  PetscCall(out_.writeAttribute("/", "time_integrator", opt_.time));
  PetscCall(out_.writeAttribute("/", "time", time_));
  PetscCall(out_.writeAttribute("/", "steps", (long long)steps_));
  PetscCall(out_.writeAttribute("/", "nx", (long long)opt_.nx));
  PetscCall(out_.writeAttribute("/", "gamma", problem_.gamma));
  PetscCall(out_.writeAttribute("/", "cfl", opt_.cfl));
  PetscCall(out_.writeAttribute("/", "xmin", problem_.xmin));
  PetscCall(out_.writeAttribute("/", "xmax", problem_.xmax));
  PetscCall(out_.writeAttribute("/", "bc_left", bcName(problem_.bc_left)));
  PetscCall(out_.writeAttribute("/", "bc_right", bcName(problem_.bc_right)));
  PetscCall(out_.writeAttribute("/", "characteristic", opt_.characteristic ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "positivity_limiter", opt_.positivity ? 1 : 0));
  PetscCall(out_.writeAttribute("/", "solve_seconds", wall_solve_));
  PetscCall(out_.writeAttribute("/", "solve_cpu_seconds_rank0", cpu_solve_));
  Vec3 tot;
  PetscCall(totals(U_, &tot));
  const char* cn[3] = {"mass", "momentum", "energy"};
  for (int c = 0; c < 3; ++c) {
    PetscCall(out_.writeAttribute("/", std::string("total_") + cn[c] + "_initial", totals0_[c]));
    PetscCall(out_.writeAttribute("/", std::string("total_") + cn[c] + "_final", tot[c]));
  }
  if (have_errors_) {
    const char* vn[3] = {"rho", "u", "p"};
    for (int c = 0; c < 3; ++c) {
      PetscCall(out_.writeAttribute("/", std::string("error_l1_") + vn[c], errors_.l1[c]));
      PetscCall(out_.writeAttribute("/", std::string("error_l2_") + vn[c], errors_.l2[c]));
      PetscCall(out_.writeAttribute("/", std::string("error_linf_") + vn[c], errors_.linf[c]));
    }
    PetscCall(out_.writeAttribute("/", "error_reference", opt_.reference.empty() ? "exact" : opt_.reference));
  }
  const suite::Dims d1{(unsigned long long)opt_.nx}, s1{(unsigned long long)xs_}, c1{(unsigned long long)xm_};
  if (have_errors_) { // the solution the errors were measured against, for the profile plots
    PetscCall(out_.writeDistributed("/exact/rho", exact_[0].data(), d1, s1, c1, ""));
    PetscCall(out_.writeDistributed("/exact/u", exact_[1].data(), d1, s1, c1, ""));
    PetscCall(out_.writeDistributed("/exact/p", exact_[2].data(), d1, s1, c1, ""));
  }
  const suite::Dims dims{(unsigned long long)opt_.nx}, start{(unsigned long long)xs_},
      count{(unsigned long long)xm_};
  PetscCall(out_.writeDistributed("/grid/x", xc_.data(), dims, start, count, ""));
  std::vector<double> rho, u, p;
  PetscCall(primitiveArrays(U_, &rho, &u, &p));
  PetscCall(out_.writeDistributed("/final/rho", rho.data(), dims, start, count, ""));
  PetscCall(out_.writeDistributed("/final/u", u.data(), dims, start, count, ""));
  PetscCall(out_.writeDistributed("/final/p", p.data(), dims, start, count, ""));
  if (!spacetime_t_.empty()) {
    const unsigned long long nrec = spacetime_t_.size();
    PetscCall(out_.writeDistributed("/spacetime/rho", spacetime_rho_.data(),
                                    {nrec, (unsigned long long)opt_.nx}, {0, (unsigned long long)xs_},
                                    {nrec, (unsigned long long)xm_}, ""));
    PetscCall(out_.writeReplicated("/spacetime/time", spacetime_t_.data(), {nrec}, ""));
  }
  // XDMF sidecar: every snapshot plus the final state.
  std::vector<suite::XdmfStep> steps;
  for (const auto& s : snapshots_) {
    char g[64];
    PetscCall(PetscSNPrintf(g, sizeof(g), "/snapshots/%06" PetscInt_FMT, s.step));
    steps.push_back({s.time,
                     {{"rho", std::string(g) + "/rho", true},
                      {"u", std::string(g) + "/u", true},
                      {"p", std::string(g) + "/p", true}}});
  }
  steps.push_back({time_, {{"rho", "/final/rho", true}, {"u", "/final/u", true}, {"p", "/final/p", true}}});
  const std::string h5name = fileNameOf(opt_.output), xmf = xdmfPathFor(opt_.output);
  suite::XdmfRectGrid grid{{(unsigned long long)opt_.nx + 1}, {problem_.xmin}, {dx_}};
  PetscCall(suite::writeXdmfRectSeries(ctx_.comm(), xmf, h5name, grid, steps));
  PetscCall(out_.commit(&ctx_));
  PetscCall(
      suite::logInfo(ctx_.comm(), ctx_.quiet(), "euler: wrote %s and %s", opt_.output.c_str(), xmf.c_str()));
  PetscFunctionReturn(0);
}

} // namespace euler_app
