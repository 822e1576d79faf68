// lcpbench's end of a run: interrupted or complete (see lcpbench_finalize.hpp).
#include "lcpbench_finalize.hpp"
#include "lcpbench_util.hpp"

#include "core/log.hpp"
#include "core/version.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

constexpr int kColumns = 8; // per solver: failed, med.iter, med.piv, med.piv/n, time, prob/s, cpu, prob/cpu-s

// The statistics rank 0 computes and every rank prints and checks.
struct Totals {
  std::vector<double> table;    // kColumns per solver
  long long counts[2] = {0, 0}; // invalid, unsolved
  std::string first_unsolved;   // "solver on problem k: status" or ""
};

void summariseSolvers(suite::H5AppendFile& f, const Batch& b, Totals* T) {
  for (size_t s = 0; s < b.solver_names.size(); ++s) {
    const SolverSummary S = summarise(f, b.solver_names[s], b.count);
    double* t = &T->table[kColumns * s];
    t[0] = S.failed, t[1] = S.med_it, t[2] = S.med_piv, t[3] = S.med_pvn, t[4] = S.tsum;
    t[5] = S.tsum > 0 ? b.count / S.tsum : 0.0, t[6] = S.csum, t[7] = S.csum > 0 ? b.count / S.csum : 0.0;
    if (s == 0) T->counts[0] = S.invalid;
    T->counts[1] += S.unsolved;
    if (T->first_unsolved.empty() && S.first_unsolved >= 0)
      T->first_unsolved = b.solver_names[s] + " on problem " + std::to_string(S.first_unsolved) + ": " +
                          statusName(static_cast<Status>(S.first_status));
  }
}

void writeRunAttributes(suite::H5AppendFile& f, const suite::RunContext& ctx, const Options& o,
                        const Batch& b, Store* store) {
  f.setAttribute("/", "program", ctx.program());
  f.setAttribute("/", "version", std::string(suite::versionString()));
  f.setAttribute("/", "options", ctx.optionsText());
  f.setAttribute("/", "nranks", static_cast<long long>(ctx.size()));
  f.setAttribute("/", "start_time", ctx.startTimeIso());
  f.setAttribute("/", "family", b.family);
  f.setAttribute("/", "count", b.count);
  f.setAttribute("/", "solvers", join(b.solver_names));
  f.setAttribute("/", "acceptance", "natural residual |z - mid(l,u,z-w)|_inf <= rel_tol (1 + |q|_inf)");
  f.setAttribute("/", "rel_tol", (double)o.rel_tol);
  f.setAttribute("/", "status_codes",
                 "0 solved, 1 max_iterations, 2 ray_termination, 3 breakdown, 4 unsupported, 5 not_accepted, "
                 "6 invalid_input, 7 numerical_error");
  std::vector<double> walls, solved;
  store->runTotals(&walls, &solved);
  f.setAttribute("/batch", "run_wall_seconds", walls);
  f.setAttribute("/batch", "solved_per_run", solved);
  f.setAttribute("/", "batch_wall_seconds", std::accumulate(walls.begin(), walls.end(), 0.0));
}

void writeProblemAttributes(suite::H5AppendFile& f, const Options& o, const Batch& b) {
  if (b.fromFiles()) {
    f.setAttribute("/", "files", join(b.files));
    return;
  }
  f.setAttribute("/", "n", (long long)o.n);
  f.setAttribute("/", "cond", (double)o.cond);
  f.setAttribute("/", "qrange", (double)o.qrange);
  f.setAttribute("/", "seed", (long long)o.seed);
  if (b.family == "random_box") {
    f.setAttribute("/", "lower", (double)o.lower);
    f.setAttribute("/", "upper", (double)o.upper);
  }
}

// Rank 0 (throws): the statistics and final attributes are added to a copy (OUT.tmp), renamed to OUT when
// complete; OUT.partial is removed last. A kill during this phase (new datasets and attributes: metadata)
// leaves OUT.partial intact, and running the command again redoes only this phase.
void completeFile(const suite::RunContext& ctx, const Options& o, const Batch& b, const std::string& partial,
                  Store* store, Totals* T) {
  suite::H5AppendFile& f = store->file();
  f.close();
  const std::string tmp = o.output + ".tmp";
  std::filesystem::copy_file(partial, tmp, std::filesystem::copy_options::overwrite_existing);
  f.open(tmp, true);
  summariseSolvers(f, b, T);
  writeRunAttributes(f, ctx, o, b, store);
  writeProblemAttributes(f, o, b);
  f.setAttribute("/", "wall_seconds", ctx.wallSeconds());
  f.setAttribute("/batch", "complete", 1LL);
  f.close();
  if (std::rename(tmp.c_str(), o.output.c_str()) != 0)
    throw std::runtime_error("cannot rename " + tmp + " to " + o.output);
  std::remove(partial.c_str());
}

PetscErrorCode bcastTotals(MPI_Comm comm, Totals* T) {
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(T->table.data(), static_cast<int>(T->table.size()), MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(T->counts, 2, MPI_LONG_LONG, 0, comm));
  PetscCall(bcastError(comm, &T->first_unsolved));
  PetscFunctionReturn(0);
}

PetscErrorCode printSummary(const suite::RunContext& ctx, const Options& o, const Batch& b,
                            const RunSummary& r, const Totals& T) {
  MPI_Comm comm = ctx.comm();
  PetscFunctionBeginUser;
  PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8s %8s %10s %10s %12s %12s %12s", "solver", "solved",
                           "failed", "med.iter", "med.piv/n", "time [s]", "problems/s", "prob/cpu-s"));
  for (size_t s = 0; s < b.solver_names.size(); ++s) {
    const double* t = &T.table[kColumns * s];
    PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8lld %8lld %10.1f %10.2f %12.4g %12.1f %12.1f",
                             b.solver_names[s].c_str(), b.count - (long long)t[0], (long long)t[0], t[1],
                             t[3], t[4], t[5], t[7]));
  }
  const long long solved_now = b.count - r.ndone0;
  const double wall = r.deal.wall;
  PetscCall(suite::logInfo(comm, ctx.quiet(),
                           "lcpbench: %lld problems (%lld in this run) in %.3f s wall (%.1f problems/s), "
                           "results in %s",
                           b.count, solved_now, wall, solved_now / std::max(wall, 1e-12), o.output.c_str()));
  PetscFunctionReturn(0);
}

// Invalid input is an error; unsolved problems are one under -strict.
PetscErrorCode checkOutcome(MPI_Comm comm, const Options& o, const Batch& b, const Totals& T) {
  PetscFunctionBeginUser;
  // Every rank holds the same file list and messages (generated problems are validated where solved).
  for (size_t k = 0; k < b.file_errors.size(); ++k)
    if (!b.file_errors[k].empty())
      PetscCall(PetscPrintf(comm, "lcpbench: problem %zu recorded as invalid input: %s\n", k,
                            b.file_errors[k].c_str()));
  PetscCheck(
      T.counts[0] == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
      "%lld problem(s) with invalid input (recorded with status 6 = invalid_input; the others kept their "
      "results in %s)",
      T.counts[0], o.output.c_str());
  PetscCheck(!o.strict || T.counts[1] == 0, comm, PETSC_ERR_NOT_CONVERGED,
             "%lld solver run(s) did not solve their problem (first: %s; -strict)", T.counts[1],
             T.first_unsolved.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode finishInterrupted(const suite::RunContext& ctx, const Batch& b, const RunSummary& r,
                                 Store* store) {
  PetscFunctionBeginUser;
  const std::string cerr = rank0Try(ctx.rank(), [&] { store->file().close(); });
  PetscCheck(cerr.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: %s", cerr.c_str());
  PetscCall(suite::logInfo(ctx.comm(), false,
                           "lcpbench: stop requested (%s): %lld of %lld problems done (%lld in this run, "
                           "%.3f s), flushed to %s; run the same command again to resume",
                           r.deal.stopped == 2 ? "max_walltime" : "signal", r.deal.ndone, b.count,
                           r.deal.ndone - r.ndone0, r.deal.wall, r.partial.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode finishComplete(const suite::RunContext& ctx, const Options& o, const Batch& b,
                              const RunSummary& r, Store* store) {
  MPI_Comm comm = ctx.comm();
  Totals T;
  PetscFunctionBeginUser;
  T.table.assign(b.solver_names.size() * kColumns, 0.0);
  std::string err = rank0Try(ctx.rank(), [&] { completeFile(ctx, o, b, r.partial, store, &T); });
  PetscCall(bcastError(comm, &err));
  PetscCheck(err.empty(), comm, PETSC_ERR_FILE_WRITE, "lcpbench: writing the results failed: %s",
             err.c_str());
  PetscCall(bcastTotals(comm, &T));
  PetscCall(printSummary(ctx, o, b, r, T));
  PetscCall(checkOutcome(comm, o, b, T));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
