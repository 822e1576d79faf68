// Collective checks of the Euler run's options (see euler_options.hpp): one clear message naming the option,
// on every rank, before time or memory is spent.
#include "euler_options.hpp"

#include "core/resource_checks.hpp"
#include "euler/line_options.hpp"
#include "io/h5_output.hpp"

#include <cstdio>
#include <cstring>

namespace euler_app {

using namespace suite::euler;

namespace {
// 1D: the line's domain, boundaries and cell count.
PetscErrorCode checkLine(const suite::RunContext& ctx, const Options& o, const Problem& line) {
  MPI_Comm comm = ctx.comm();
  const PetscInt nx = o.n[0];
  PetscFunctionBeginUser;
  PetscCheck((line.bc_left == Bc::Periodic) == (line.bc_right == Bc::Periodic), comm, PETSC_ERR_ARG_WRONG,
             "Periodic boundaries must be set on both ends (-bc_left %s, -bc_right %s)", bcName(line.bc_left),
             bcName(line.bc_right));
  PetscCheck(line.xmax > line.xmin, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid domain: -xmax %g must exceed -xmin %g", line.xmax, line.xmin);
  // 3 unknowns per cell must fit the 32-bit PetscInt; PETSc itself wraps larger values silently.
  PetscCall(suite::checkIntOptionRange(comm, "-nx", 1));
  PetscCheck(nx <= PETSC_MAX_INT / 3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": 3 nx unknowns exceed the 32-bit PetscInt (at most %d cells)", nx,
             (int)(PETSC_MAX_INT / 3));
  PetscCall(suite::checkIntOptionRange(comm, "-max_steps", -1));
  PetscCall(suite::checkIntOptionRange(comm, "-snapshot_every", 0));
  // Measured peak memory: ~1.0 kB per cell explicit, ~1.6 kB implicit (GMRES(30) vectors), Sod N = 1e6; the
  // x-t image (-spacetime_every) holds one density row per record, counted where -max_steps bounds the records.
  const bool bounded = o.spacetime_every > 0 && o.max_steps > 0;
  const double records = bounded ? 1.0 + (double)o.max_steps / (double)o.spacetime_every : 0.0;
  char what[96];
  std::snprintf(what, sizeof what, "-nx %lld%s", (long long)nx,
                bounded ? " -max_steps/-spacetime_every" : "");
  PetscCall(suite::checkMemoryEstimate(
      comm, ((o.implicit ? 2000.0 : 1200.0) + 8.0 * records) * nx / ctx.size() + 5e7, what));
  const PetscInt width = 2 * kLineGhost;
  PetscCheck(nx >= width, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": below the stencil width %" PetscInt_FMT " of the schemes", nx,
             width);
  PetscCheck(nx >= kLineGhost * ctx.size(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -nx %" PetscInt_FMT ": each of the %d ranks needs at least %d cells", nx, ctx.size(),
             kLineGhost);
  PetscFunctionReturn(0);
}

// 2D/3D: cells per direction against the stencil, the 32-bit PetscInt and the memory estimate.
PetscErrorCode checkGrid(const suite::RunContext& ctx, const Options& o, const ProblemND& pr) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscCall(suite::checkIntOptionRange(comm, "-nx", 1));
  PetscCall(suite::checkIntOptionRange(comm, "-ny", 1));
  if (o.dim == 3) PetscCall(suite::checkIntOptionRange(comm, "-nz", 1));
  PetscCall(suite::checkIntOptionRange(comm, "-max_steps", -1));
  PetscCall(suite::checkIntOptionRange(comm, "-snapshot_every", 0));
  const char* names[3] = {"-nx", "-ny", "-nz"};
  double cells = 1.0;
  for (int d = 0; d < o.dim; ++d) {
    const bool periodic = pr.bc[d][0] == BcN::Periodic;
    const PetscInt need = periodic ? kLineGhost : 2 * kLineGhost;
    PetscCheck(o.n[d] >= need, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "Invalid %s %" PetscInt_FMT ": below the %s stencil width %" PetscInt_FMT " of the schemes",
               names[d], o.n[d], periodic ? "periodic" : "bounded", need);
    cells *= (double)o.n[d];
  }
  char what[160];
  if (o.dim == 2)
    std::snprintf(what, sizeof what, "-nx %lld -ny %lld", (long long)o.n[0], (long long)o.n[1]);
  else
    std::snprintf(what, sizeof what, "-nx %lld -ny %lld -nz %lld", (long long)o.n[0], (long long)o.n[1],
                  (long long)o.n[2]);
  PetscCall(suite::checkIndexCount(comm, cells * o.nv(), "unknowns (cells x conserved variables)", what));
  std::snprintf(what + std::strlen(what), sizeof what - std::strlen(what),
                " (%.3g cells) -line_batch_mb %lld", cells, (long long)o.line_batch_mb);
  // Measured layout: ~7 state vectors (TS stages, local ghosted copy) + line buffers + one direction's scalar
  // batch and transposed lines ~ 130 NV bytes per cell, plus the block-line batch (LineOptions::batch_bytes,
  // 256 MiB). Measured peak: 1.14 GB per rank for the 3D explosion at 128^3 on 2 ranks (estimate 1.05 GB).
  PetscCall(suite::checkIntOptionRange(comm, "-line_batch_mb", 1));
  PetscCall(suite::checkMemoryEstimate(
      comm, 130.0 * o.nv() * cells / ctx.size() + 5e7 + 1.2 * 1048576.0 * (double)o.line_batch_mb, what));
  PetscFunctionReturn(0);
}
// `formula` and `file`: the options a problem without a scale of its own needs; a file's grid unchanged; an
// obstacle with the features that do not know it refused.
PetscErrorCode checkUserProblem(MPI_Comm comm, const Options& o, const ProblemND& pr) {
  const char* names[3] = {"-nx", "-ny", "-nz"};
  const char axis[3] = {'x', 'y', 'z'};
  PetscFunctionBeginUser;
  if (pr.user_defined) {
    PetscCheck(o.t_final_set, comm, PETSC_ERR_ARG_WRONG, "-problem %s needs -t_final (the end time)",
               o.problem.c_str());
    for (int d = 0; d < o.dim; ++d) {
      PetscBool given = PETSC_FALSE;
      PetscCall(PetscOptionsHasName(nullptr, nullptr, names[d], &given));
      PetscCheck(given || pr.default_n[d] > 0, comm, PETSC_ERR_ARG_WRONG,
                 "-problem formula needs %s (the cells along %c)", names[d], axis[d]);
      PetscCheck(pr.initial_file.empty() || o.n[d] == pr.default_n[d], comm, PETSC_ERR_ARG_WRONG,
                 "%s %" PetscInt_FMT " differs from the %" PetscInt_FMT
                 " cells along %c of -initial_state %s",
                 names[d], o.n[d], pr.default_n[d], axis[d], pr.initial_file.c_str());
    }
  }
  if (pr.hasSolid()) {
    PetscCheck(o.filter_alpha >= 0.5, comm, PETSC_ERR_ARG_INCOMP,
               "-filter_alpha with a solid obstacle: the compact filter's lines do not stop at the solid");
    PetscCheck(!o.error, comm, PETSC_ERR_ARG_INCOMP,
               "-error with a solid obstacle: the problem's exact solution does not know the obstacle");
    PetscCheck(o.line_solve != "gather", comm, PETSC_ERR_ARG_INCOMP,
               "-line_solve gather with a solid obstacle: the fluid segments of a line are solved whole");
    PetscCheck(!o.spectrum, comm, PETSC_ERR_ARG_INCOMP,
               "-spectrum with a solid obstacle: the spectrum's FFT runs over the solid cells too");
  }
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode validateOptions(const suite::RunContext& ctx, const Options& o, const Problem& line,
                               const ProblemND& pr) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscCall(checkUserProblem(comm, o, pr));
  PetscCall(suite::checkIntOptionRange(comm, "-spacetime_every", 0));
  if (!o.output.empty()) PetscCall(suite::checkOutputWritable(comm, o.output, "output"));
  PetscCheck(!o.output_initial || !o.output.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-output_initial writes into -output: give -output FILE.h5");
  PetscCall(o.dim == 1 ? checkLine(ctx, o, line) : checkGrid(ctx, o, pr));
  PetscCheck(o.cfl > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -cfl %g: must be > 0", o.cfl);
  // The positivity limiter's bound (lib/euler/direction_sweep.hpp): a CFL number above it is refused, not reduced.
  PetscCheck(
      !o.positivity || o.implicit || o.cfl <= kPositivityCfl, comm, PETSC_ERR_ARG_OUTOFRANGE,
      "Invalid -cfl %g: the positivity limiter is proven up to -cfl %g (give -positivity false to run above "
      "it)",
      o.cfl, kPositivityCfl);
  PetscCall(suite::checkIntOptionRange(comm, "-max_retries", 0));
  PetscCheck(o.max_retries <= 30, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -max_retries %" PetscInt_FMT ": at most 30 (dt / 2^30)", o.max_retries);
  PetscCheck(o.dt >= 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -dt %g: must be >= 0 (0: CFL-controlled)",
             o.dt);
  PetscCheck(o.shock_threshold >= 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -shock_threshold %g: must be >= 0", o.shock_threshold);
  PetscCheck(o.shock_ppw == 0.0 || (o.shock_ppw >= 4.0 && o.shock_ppw < 1e300), comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -shock_ppw %g: must be >= 4 points per wavelength, or 0 (the amplitude test alone)",
             o.shock_ppw);
  PetscCheck(o.filter_alpha > -0.5 && o.filter_alpha <= 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -filter_alpha %g: must be in (-0.5, 0.5] (0.5: no filter)", o.filter_alpha);
  PetscCheck(o.filter_time >= 0.0 && o.filter_time < 1e300, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -filter_time %g: must be >= 0 (0: the full filter every step)", o.filter_time);
  // BDF2 keeps the previous solution in its own history: a state filtered after the step would not be it.
  PetscCheck(
      o.filter_alpha >= 0.5 || o.time != "bdf2", comm, PETSC_ERR_ARG_INCOMP,
      "-filter_alpha %g with -time bdf2: the multistep history would not hold the filtered states (use a "
      "one-step integrator)",
      o.filter_alpha);
  PetscCheck(o.t_final > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE, "Invalid -t_final %g: must be > 0", o.t_final);
  PetscCheck(o.snapshot_every >= 0 && o.spacetime_every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -snapshot_every/-spacetime_every: must be >= 0");
  PetscCheck(!o.error || pr.exact || !o.reference.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-error: problem '%s' has no exact solution%s", o.problem.c_str(),
             o.dim == 1 ? "; give -reference FILE.h5 of a fine-grid run" : "");
  PetscFunctionReturn(0);
}

} // namespace euler_app
