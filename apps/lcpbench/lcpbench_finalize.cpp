// lcpbench's end of a run: an interrupted one leaves OUT.partial; a complete one gets its statistics and
// attributes in a copy renamed to OUT (main.cpp), then the summary table and the checks of the outcome.
#include "lcpbench.hpp"

#include "core/comma_list.hpp"
#include "core/log.hpp"
#include "core/rank0_work.hpp"
#include "core/run_summary.hpp"
#include "core/version.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

void writeRunAttributes(suite::H5AppendFile& f, const suite::RunContext& ctx, const Options& o,
                        const Batch& b, Store* store) {
  f.setAttribute("/", "program", ctx.program());
  f.setAttribute("/", "version", std::string(suite::versionString()));
  f.setAttribute("/", "options", ctx.optionsText());
  f.setAttribute("/", "nranks", static_cast<long long>(ctx.size()));
  f.setAttribute("/", "start_time", ctx.startTimeIso());
  f.setAttribute("/", "family", b.family);
  f.setAttribute("/", "count", b.count);
  f.setAttribute("/", "solvers", suite::joinCommaList(b.solver_names));
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
  if (b.fromFiles()) return f.setAttribute("/", "files", suite::joinCommaList(o.files));
  f.setAttribute("/", "n", (long long)o.n);
  f.setAttribute("/", "cond", (double)o.cond);
  f.setAttribute("/", "qrange", (double)o.qrange);
  f.setAttribute("/", "seed", (long long)o.seed);
  if (b.family != "random_box") return;
  f.setAttribute("/", "lower", (double)o.lower);
  f.setAttribute("/", "upper", (double)o.upper);
}

// Rank 0 (throws): OUT.partial copied to OUT.tmp, completed, renamed to OUT; OUT.partial removed last.
void completeFile(const suite::RunContext& ctx, const Options& o, const Batch& b, const RunState& st,
                  Store* store, std::vector<SolverSummary>* S, std::string* auto_line) {
  const std::string partial = o.output + ".partial";
  suite::H5AppendFile& f = store->file;
  f.close();
  const std::string tmp = o.output + ".tmp";
  std::filesystem::copy_file(partial, tmp, std::filesystem::copy_options::overwrite_existing);
  f.open(tmp, true);
  for (size_t s = 0; s < b.solver_names.size(); ++s) {
    (*S)[s] = summarise(f, b.solver_names[s], b.count);
    f.setAttribute("/results/" + b.solver_names[s], "warmup_solves", st.warmup_solves);
  }
  f.setAttribute(
      "/", "timing",
      "every solver timed after the same untimed warm-up: warmup_solves solves of the batch's first "
      "valid problems on every rank, this run (/results/<solver> attribute warmup_solves)");
  if (b.auto_index >= 0) *auto_line = summariseAuto(f, b.count);
  writeRunAttributes(f, ctx, o, b, store);
  f.setAttribute("/", "wall_seconds", ctx.wallSeconds());
  f.setAttribute("/batch", "complete", 1LL);
  f.setAttribute("/", "status", "completed"); // the status every output file carries (core/run_summary.hpp)
  f.close();
  if (std::rename(tmp.c_str(), o.output.c_str()) != 0)
    throw std::runtime_error("cannot rename " + tmp + " to " + o.output);
  std::remove(partial.c_str());
}

PetscErrorCode printSummary(const suite::RunContext& ctx, const Options& o, const Batch& b,
                            const RunState& st, const std::vector<SolverSummary>& S,
                            const std::string& auto_line) {
  MPI_Comm comm = ctx.comm();
  const long long solved_now = b.count - st.ndone0;
  PetscFunctionBeginUser;
  PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8s %8s %10s %10s %12s %12s %12s %8s", "solver",
                           "solved", "failed", "med.iter", "med.piv/n", "time [s]", "problems/s",
                           "prob/cpu-s", "warm-up"));
  for (size_t s = 0; s < b.solver_names.size(); ++s)
    PetscCall(suite::logInfo(
        comm, ctx.quiet(), "  %-16s %8lld %8lld %10.1f %10.2f %12.4g %12.1f %12.1f %8lld",
        b.solver_names[s].c_str(), b.count - (long long)S[s].failed, (long long)S[s].failed, S[s].med_it,
        S[s].med_pvn, S[s].tsum, S[s].rate(b.count), S[s].cpuRate(b.count), st.warmup_solves));
  if (b.auto_index >= 0) // rank 0's line (PetscPrintf prints rank 0's arguments)
    PetscCall(suite::logInfo(comm, ctx.quiet(), "  %s", auto_line.c_str()));
  char what[192];
  PetscCall(PetscSNPrintf(what, sizeof what,
                          "%lld problems (%lld in this run) in %.3f s wall (%.1f problems/s)", b.count,
                          solved_now, st.wall, solved_now / std::max(st.wall, 1e-12)));
  PetscCall(suite::logRunSummary(ctx, "completed", what, {o.output}));
  PetscFunctionReturn(0);
}

// Invalid input is an error; unsolved problems are one under -strict.
PetscErrorCode checkOutcome(MPI_Comm comm, const Options& o, const Batch& b,
                            const std::vector<SolverSummary>& S) {
  long long unsolved = 0;
  std::string first; // "solver on problem k: status" of the first solver with an unsolved problem
  PetscFunctionBeginUser;
  for (size_t s = 0; s < S.size(); ++s) {
    unsolved += S[s].unsolved;
    if (first.empty() && S[s].first_unsolved >= 0)
      first = b.solver_names[s] + " on problem " + std::to_string(S[s].first_unsolved) + ": " +
              statusName(static_cast<Status>(S[s].first_status));
  }
  // Every rank holds the same file list and messages (generated problems are validated where solved).
  for (size_t k = 0; k < b.file_errors.size(); ++k)
    if (!b.file_errors[k].empty())
      PetscCall(PetscPrintf(comm, "lcpbench: problem %zu recorded as invalid input: %s\n", k,
                            b.file_errors[k].c_str()));
  PetscCheck(
      S[0].invalid == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
      "%lld problem(s) with invalid input (recorded with status 6 = invalid_input; the others kept their "
      "results in %s)",
      S[0].invalid, o.output.c_str());
  PetscCheck(!o.strict || unsolved == 0, comm, PETSC_ERR_NOT_CONVERGED,
             "%lld solver run(s) did not solve their problem (first: %s; -strict)", unsolved, first.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode finishRun(const suite::RunContext& ctx, const Options& o, const Batch& b, const RunState& st,
                         Store* store) {
  std::vector<SolverSummary> S(b.solver_names.size()); // rank 0 computes them, every rank prints and checks
  std::string auto_line;                               // rank 0's
  PetscFunctionBeginUser;
  if (st.stopped != 0 || st.ndone < b.count) { // interrupted: OUT.partial stays
    const char* status = st.stopped == 2 ? "stopped by walltime" : "stopped by signal";
    if (ctx.rank() == 0) {
      const std::string err = suite::messageOf([&] {
        store->file.setAttribute("/", "status", status);
        store->file.close();
      });
      PetscCheck(err.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: %s", err.c_str());
    }
    PetscCall(suite::logInfo(ctx.comm(), false,
                             "lcpbench: stop requested (%s): %lld of %lld problems done (%lld in this run, "
                             "%.3f s), flushed to %s; run the same command again to resume",
                             st.stopped == 2 ? "max_walltime" : "signal", st.ndone, b.count,
                             st.ndone - st.ndone0, st.wall, (o.output + ".partial").c_str()));
    char what[160];
    PetscCall(PetscSNPrintf(what, sizeof what, "%lld of %lld problems done (%lld in this run, %.3f s)",
                            st.ndone, b.count, st.ndone - st.ndone0, st.wall));
    PetscCall(suite::logRunSummary(ctx, status, what, {o.output + ".partial"}));
    PetscFunctionReturn(0);
  }
  PetscCall(suite::onRank0(ctx.comm(), PETSC_ERR_FILE_WRITE, "lcpbench: writing the results failed: ", [&] {
    completeFile(ctx, o, b, st, store, &S, &auto_line);
  }));
  PetscCallMPI(
      MPI_Bcast(S.data(), static_cast<int>(S.size() * sizeof(SolverSummary)), MPI_BYTE, 0, ctx.comm()));
  PetscCall(printSummary(ctx, o, b, st, S, auto_line));
  PetscCall(checkOutcome(ctx.comm(), o, b, S));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
