// lcpbench batch driver; see lcpbench_run.hpp and main.cpp.
//
// Streaming and resume (issue #8, batch resilience). Rank 0 deals chunks of problem indices and owns the
// results file; it never holds the whole table:
//   - At start it creates OUT.partial (single-process HDF5, lib/io/h5_append.hpp) with every per-problem
//     dataset preallocated at its final size (count) and the batch header (/batch attributes: family, n,
//     count, seed, cond, q range, bounds, solvers, files, solver options).
//   - Results arrive in chunks; at most -flush_every records (or -flush_seconds of wall time) are buffered,
//     then written in place, the file is flushed, and only then the /batch/done flags of those problems are
//     set and flushed again. Writes never change HDF5 metadata, so a process killed at any moment (SIGKILL
//     included) leaves a readable OUT.partial whose done-flagged entries are complete.
//   - SIGTERM / SIGUSR1 / SIGINT / -max_walltime: dealing stops, outstanding chunks are collected and flushed,
//     exit 0 with a message; OUT.partial stays.
//   - Rerunning the same command (-resume, default on) continues OUT.partial: the header must match (else a
//     clear error: -resume 0 discards it), done problems are skipped, never recomputed; /batch/run records for
//     every problem the run (0, 1, ...) that solved it; at completion /batch attributes solved_per_run and
//     run_wall_seconds sum it up. Attributes are written only at creation and completion (never while
//     problems are flushed), so the header cannot be torn by a kill.
//   - When every problem is done: OUT.partial is copied to OUT.tmp, histograms and summary attributes are
//     computed by one streamed pass over the datasets (blocks of 65536 problems) and written to the copy,
//     /batch complete = 1, OUT.tmp is renamed to OUT and OUT.partial removed. A kill in this phase leaves
//     OUT.partial complete: the next run of the command only redoes this phase.
#include "lcpbench_run.hpp"
#include "lcpbench_store.hpp"

#include "core/log.hpp"
#include "core/progress.hpp"
#include "core/resource_checks.hpp"
#include "core/run_context.hpp"
#include "core/version.hpp"
#include "io/h5_append.hpp"
#include "io/h5_output.hpp"
#include "lcp/generators.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

constexpr int kTagRequest = 4101, kTagWork = 4102;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

struct Batch {
  std::string family;
  GeneratorParams gp;
  long long count = 0;
  std::vector<std::string> files;
  std::vector<Problem> file_problems;   // family "file": every rank holds them (read up front)
  std::vector<std::string> file_errors; // "" or the reason a file is invalid
  std::vector<std::unique_ptr<Solver>> solvers;
  std::vector<std::string> solver_names;
  SolverOptions opt;
  double delay = 0.0; // testing: seconds of sleep after each problem
};

// Solves problem k with every solver; rec gets nsolvers * kFields values; n_out the problem size;
// err the validation message ("" if valid).
void solveOne(const Batch& b, long long k, double* rec, int* n_out, std::string* err) {
  Problem gen;
  const Problem* p = nullptr;
  err->clear();
  if (b.family == "file") {
    if (!b.file_errors[k].empty())
      *err = b.file_errors[k];
    else
      p = &b.file_problems[k];
  } else {
    try {
      gen = generate(b.family, b.gp, static_cast<std::uint64_t>(k));
      p = &gen;
      *err = validate(gen);
    } catch (const std::exception& e) {
      *err = e.what();
    }
  }
  *n_out = p ? p->size() : 0;
  const int ns = static_cast<int>(b.solvers.size());
  for (int s = 0; s < ns; ++s) {
    double* r = rec + s * kFields;
    if (!err->empty() || !p) {
      r[0] = static_cast<double>(Status::InvalidInput);
      r[1] = r[2] = r[3] = 0.0;
      r[4] = kInf;
      r[5] = 0.0;
      continue;
    }
    const Result res = solve(*b.solvers[s], *p, b.opt);
    r[0] = static_cast<double>(res.status);
    r[1] = res.iterations;
    r[2] = static_cast<double>(res.pivots);
    r[3] = res.time;
    r[4] = res.residual;
    r[5] = res.cpu_time;
  }
  if (b.delay > 0) usleep(static_cast<useconds_t>(b.delay * 1e6));
}

// Rank 0's error message (or "") broadcast; every rank then takes the same PetscCheck.
PetscErrorCode bcastError(MPI_Comm comm, std::string* err) {
  PetscFunctionBeginUser;
  int len = static_cast<int>(err->size());
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  err->resize(len);
  if (len > 0) PetscCallMPI(MPI_Bcast(err->data(), len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode runLcpBench(const suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  MPI_Comm comm = ctx.comm();
  const int rank = ctx.rank(), size = ctx.size();
  char family[64] = "random_box",
       solvers[1024] = "lemke,keller,cottle_dantzig,murty,bpp,fb_newton,smoothed_newton,pgs";
  char output[PETSC_MAX_PATH_LEN] = "", files[8192] = "";
  PetscInt n = 100, count = 500, max_it = 0, block_size = 3, chunk = 0, seed = 1, flush_every = 4096;
  PetscReal cond = 1e4, qrange = 1e2, lower = -1e2, upper = 1e2, omega = 1.0, rel_tol = 1e-10;
  PetscReal flush_seconds = 30.0, delay = 0.0;
  PetscBool strict = PETSC_FALSE, strict_set = PETSC_FALSE, refine = PETSC_TRUE, resume = PETSC_TRUE;
  PetscBool family_set = PETSC_FALSE;
  static const char* const kFclibModels[] = {"box_friction", "normal"};
  PetscInt fclib_model = 0;
  PetscOptionsBegin(comm, "", "lcpbench options", "");
  PetscCall(PetscOptionsString("-family", "Problem family: random_spd, random_box, pmatrix, psd, murty, file",
                               "", family, family, sizeof family, &family_set));
  PetscCall(PetscOptionsInt("-n", "Problem size (generated families)", "", n, &n, nullptr));
  PetscCall(PetscOptionsInt("-count", "Number of problems (generated families)", "", count, &count, nullptr));
  PetscCall(PetscOptionsInt("-seed", "Seed of the generators (problem k uses stream (seed, k))", "", seed,
                            &seed, nullptr));
  PetscCall(PetscOptionsReal("-cond", "Condition number of M (random_spd, random_box, pmatrix)", "", cond,
                             &cond, nullptr));
  PetscCall(PetscOptionsReal("-qrange", "q uniform in [-qrange, qrange]", "", qrange, &qrange, nullptr));
  lower = -qrange; // box defaults follow the q range: a mix of free and bound variables
  upper = qrange;
  PetscCall(PetscOptionsReal("-lower", "Lower bound of random_box problems (default -qrange)", "", lower,
                             &lower, nullptr));
  PetscCall(PetscOptionsReal("-upper", "Upper bound of random_box problems (default qrange)", "", upper,
                             &upper, nullptr));
  PetscCall(PetscOptionsString(
      "-file", "Problem files for -family file (comma-separated; .dat Siconos, .h5 suite, FCLib HDF5)", "",
      files, files, sizeof files, nullptr));
  char fclib_text[32];
  PetscCall(PetscStrncpy(fclib_text, kFclibModels[fclib_model], sizeof fclib_text));
  PetscCall(
      PetscOptionsString("-fclib_model",
                         "FCLib frictional-contact files as: box_friction (all unknowns, tangential bounds "
                         "+-mu times the frictionless normal force) or normal (the frictionless normal LCP)",
                         "", fclib_text, fclib_text, sizeof fclib_text, nullptr));
  PetscCall(suite::checkChoice(comm, "-fclib_model", fclib_text, kFclibModels, 2, &fclib_model));
  PetscCall(PetscOptionsString("-solvers", "Comma-separated solver names", "", solvers, solvers,
                               sizeof solvers, nullptr));
  PetscCall(PetscOptionsInt("-max_it", "Iteration / pivot cap of every solver (0: each solver's default)", "",
                            max_it, &max_it, nullptr));
  PetscCall(PetscOptionsReal("-omega", "PGS relaxation factor", "", omega, &omega, nullptr));
  PetscCall(PetscOptionsInt("-block_size", "Block size of pgs_block", "", block_size, &block_size, nullptr));
  PetscCall(PetscOptionsReal("-rel_tol", "Acceptance: residual <= rel_tol (1 + |q|_inf)", "", rel_tol,
                             &rel_tol, nullptr));
  PetscCall(PetscOptionsBool("-refine", "Active-set refinement of claimed solutions", "", refine, &refine,
                             nullptr));
  PetscCall(
      PetscOptionsInt("-chunk", "Problems per work request (0: automatic)", "", chunk, &chunk, nullptr));
  PetscCall(PetscOptionsBool("-strict",
                             "Exit non-zero if a solver leaves a problem unsolved (default: on for "
                             "-family file)",
                             "", strict, &strict, &strict_set));
  PetscCall(PetscOptionsString("-output", "HDF5 results file (OUT.partial while the batch runs)", "", output,
                               output, sizeof output, nullptr));
  PetscCall(PetscOptionsInt("-flush_every", "Write and flush results to OUT.partial every N problems", "",
                            flush_every, &flush_every, nullptr));
  PetscCall(PetscOptionsReal("-flush_seconds", "... and at least every S seconds of wall time", "",
                             flush_seconds, &flush_seconds, nullptr));
  PetscCall(PetscOptionsBool("-resume",
                             "Continue an interrupted batch found in OUT.partial (same options required); "
                             "-resume 0 discards it",
                             "", resume, &resume, nullptr));
  PetscCall(PetscOptionsReal("-delay_per_problem", "Testing: sleep this many seconds after each problem", "",
                             delay, &delay, nullptr));
  PetscOptionsEnd();
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) PetscFunctionReturn(0);
  PetscReal max_walltime = 0.0;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-max_walltime", &max_walltime, nullptr));

  // -file alone means -family file; -file with a generated family would silently ignore the files.
  if (files[0] && !family_set) std::snprintf(family, sizeof family, "file");
  PetscCheck(!files[0] || std::string(family) == "file", comm, PETSC_ERR_ARG_INCOMP,
             "-file is only read with -family file (given -family %s)", family);
  Batch b;
  b.family = family;
  const bool known_family = b.family == "file" || isFamily(b.family);
  PetscCheck(known_family, comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "Unknown family '%s' (option -family); known: %s, file", family, join(familyNames()).c_str());
  b.solver_names = split(solvers);
  PetscCheck(!b.solver_names.empty(), comm, PETSC_ERR_ARG_WRONG, "-solvers is empty; known: %s",
             join(solverNames()).c_str());
  for (const auto& s : b.solver_names) {
    auto sv = makeSolver(s);
    PetscCheck(sv != nullptr, comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
               "Unknown solver '%s' (option -solvers); known: %s", s.c_str(), join(solverNames()).c_str());
    PetscCheck(std::count(b.solver_names.begin(), b.solver_names.end(), s) == 1, comm, PETSC_ERR_ARG_WRONG,
               "Solver '%s' is listed twice in -solvers", s.c_str());
    b.solvers.push_back(std::move(sv));
  }
  PetscCheck(output[0], comm, PETSC_ERR_ARG_WRONG, "-output FILE.h5 is required");
  PetscCheck(cond >= 1.0 && std::isfinite(cond), comm, PETSC_ERR_ARG_OUTOFRANGE, "-cond %g: must be >= 1",
             (double)cond);
  PetscCheck(qrange >= 0.0 && std::isfinite(qrange), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-qrange %g: must be >= 0", (double)qrange);
  PetscCheck(!(lower > upper), comm, PETSC_ERR_ARG_OUTOFRANGE, "-lower %g > -upper %g (l > u)", (double)lower,
             (double)upper);
  PetscCheck(max_it >= 0 && block_size >= 1 && block_size <= 4 && chunk >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-max_it must be >= 0, -block_size in [1, 4], -chunk >= 0");
  PetscCheck(flush_every >= 1 && flush_seconds > 0 && delay >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flush_every must be >= 1, -flush_seconds > 0, -delay_per_problem >= 0");
  b.gp.n = static_cast<int>(n);
  b.gp.cond = cond;
  b.gp.qrange = qrange;
  b.gp.lower = lower;
  b.gp.upper = upper;
  b.gp.seed = static_cast<std::uint64_t>(seed);
  b.opt.max_iterations = static_cast<int>(max_it);
  b.opt.omega = omega;
  b.opt.block_size = static_cast<int>(block_size);
  b.opt.rel_tol = rel_tol;
  b.opt.refine = refine;
  b.delay = delay;
  if (!strict_set) strict = b.family == "file" ? PETSC_TRUE : PETSC_FALSE;
  if (b.family == "file") {
    b.files = split(files);
    PetscCheck(!b.files.empty(), comm, PETSC_ERR_ARG_WRONG, "-family file needs -file FILE[,FILE...]");
    for (const auto& f : b.files) {
      Problem p;
      std::string err;
      auto ends = [&](const char* e) {
        const std::string x(e);
        return f.size() > x.size() && f.compare(f.size() - x.size(), x.size(), x) == 0;
      };
      const bool fclib = isFclibFile(f); // every rank reads the same file: same answer
      const bool h5 = !fclib && (ends(".h5") || ends(".hdf5"));
      if (h5) {
        PetscCall(readProblemH5(comm, f, &p)); // collective: a malformed HDF5 file stops the run
      } else {
        try {
          p = fclib ? readFclibLocal(f, fclib_model == 0 ? FclibModel::BoxFriction : FclibModel::Normal)
                    : readSiconos(f);
        } catch (const std::exception& e) {
          err = e.what();
        }
      }
      if (err.empty()) {
        err = validate(p);
        if (!err.empty()) err = f + ": " + err;
      }
      b.file_problems.push_back(std::move(p));
      b.file_errors.push_back(err);
    }
    b.count = static_cast<long long>(b.files.size());
  } else {
    PetscCheck(n >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-n %d: must be >= 1", (int)n);
    PetscCheck(count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-count %d: must be >= 1", (int)count);
    b.count = count;
  }
  PetscCall(suite::checkOutputWritable(comm, output, "output"));

  // The batch header: a resumed batch must match it exactly (results must not depend on the run).
  std::vector<std::pair<std::string, std::string>> header = {{"family", b.family},
                                                             {"count", std::to_string(b.count)},
                                                             {"solvers", join(b.solver_names)},
                                                             {"max_it", std::to_string(max_it)},
                                                             {"omega", num(omega)},
                                                             {"block_size", std::to_string(block_size)},
                                                             {"rel_tol", num(rel_tol)},
                                                             {"refine", refine ? "1" : "0"}};
  if (b.family == "file") {
    header.push_back({"files", join(b.files)});
    header.push_back({"fclib_model", kFclibModels[fclib_model]});
  } else {
    for (const auto& kv : std::vector<std::pair<std::string, std::string>>{{"n", std::to_string(n)},
                                                                           {"seed", std::to_string(seed)},
                                                                           {"cond", num(cond)},
                                                                           {"qrange", num(qrange)},
                                                                           {"lower", num(lower)},
                                                                           {"upper", num(upper)}})
      header.push_back(kv);
  }

  const int ns = static_cast<int>(b.solvers.size());
  const int rec_len = 2 + ns * kFields; // index, n, solver fields
  if (chunk == 0) chunk = std::max<long long>(1, std::min<long long>(64, b.count / (8LL * size)));
  const std::string partial = std::string(output) + ".partial";

  // ---- rank 0 opens (resume) or creates OUT.partial ----
  Store store(BatchShape{b.count, b.solver_names}, header, rec_len);
  std::vector<unsigned char> done; // rank 0: done flags (1 byte per problem)
  long long ndone0 = 0;            // problems done before this run
  {
    std::string err, note;
    if (rank == 0) {
      try {
        store.start(partial, resume, &done, &ndone0, &note);
      } catch (const std::exception& e) {
        err = e.what();
      }
    }
    PetscCall(bcastError(comm, &err));
    PetscCheck(err.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "%s", err.c_str());
    PetscCallMPI(MPI_Bcast(&ndone0, 1, MPI_LONG_LONG, 0, comm));
    if (rank == 0 && !note.empty())
      PetscCall(suite::logInfo(PETSC_COMM_SELF, ctx.quiet(), "lcpbench: %s", note.c_str()));
  }
  PetscCall(suite::logInfo(comm, ctx.quiet(), "lcpbench: family %s, %lld problems%s, solvers %s, %d rank(s)",
                           family, b.count, b.family == "file" ? "" : (", n = " + std::to_string(n)).c_str(),
                           join(b.solver_names).c_str(), size));

  // ---- dynamic load balancing: rank 0 deals chunks of not-yet-done problem indices on request ----
  const double t_start = MPI_Wtime();
  std::string err;
  std::vector<double> rec(rec_len);
  int stopped = 0;
  long long ndone = ndone0;
  if (rank == 0) {
    const long long todo = b.count - ndone0;
    suite::Progress progress(PETSC_COMM_SELF, ctx.quiet(), ctx.progressInterval(), 0.0);
    long long next = 0, reported = -1;
    auto skipDone = [&]() {
      while (next < b.count && done[next]) ++next;
    };
    skipDone();
    int active = size - 1;
    double last_flush = MPI_Wtime();
    std::vector<double> msg;
    auto flushNow = [&]() -> PetscErrorCode {
      PetscFunctionBeginUser;
      std::string ferr;
      try {
        store.flush(MPI_Wtime() - t_start);
      } catch (const std::exception& e) {
        ferr = e.what();
      }
      // Rank 0 alone: in a multi-rank run an error on PETSC_COMM_SELF aborts the job with this message.
      PetscCheck(ferr.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: writing results failed: %s",
                 ferr.c_str());
      last_flush = MPI_Wtime();
      PetscFunctionReturn(0);
    };
    auto add = [&](const double* r) -> PetscErrorCode {
      PetscFunctionBeginUser;
      store.add(r);
      ++ndone;
      if (store.buffered() >= flush_every || MPI_Wtime() - last_flush >= flush_seconds) PetscCall(flushNow());
      PetscFunctionReturn(0);
    };
    auto checkStop = [&]() {
      if (suite::g_stop_signal && !stopped) stopped = 1;
      if (max_walltime > 0 && ctx.wallSeconds() >= max_walltime && !stopped) stopped = 2;
    };
    auto serve = [&](bool block) -> PetscErrorCode {
      PetscFunctionBeginUser;
      while (true) {
        int flag = 0;
        MPI_Status st;
        if (block) {
          PetscCallMPI(MPI_Probe(MPI_ANY_SOURCE, kTagRequest, comm, &st));
          flag = 1;
        } else {
          PetscCallMPI(MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, comm, &flag, &st));
        }
        if (!flag) break;
        int len = 0;
        PetscCallMPI(MPI_Get_count(&st, MPI_DOUBLE, &len));
        msg.resize(std::max(len, 1));
        PetscCallMPI(
            MPI_Recv(msg.data(), len, MPI_DOUBLE, st.MPI_SOURCE, kTagRequest, comm, MPI_STATUS_IGNORE));
        if (len > 0 && msg[0] != 0.0 && !stopped) stopped = 1; // the worker saw a stop signal
        for (int off = 1; off + rec_len <= len; off += rec_len) PetscCall(add(msg.data() + off));
        checkStop();
        long long work[2] = {next, next};
        if (!stopped) {
          while (work[1] < b.count && work[1] - work[0] < chunk && !done[work[1]]) ++work[1];
          next = work[1];
          skipDone();
        }
        if (work[0] == work[1]) --active;
        PetscCallMPI(MPI_Send(work, 2, MPI_LONG_LONG, st.MPI_SOURCE, kTagWork, comm));
        if (block) break;
      }
      PetscFunctionReturn(0);
    };
    while ((!stopped && next < b.count) || active > 0) {
      if (size > 1) PetscCall(serve(false));
      checkStop();
      if (!stopped && next < b.count) {
        const long long k = next++;
        skipDone();
        int nk = 0;
        solveOne(b, k, rec.data() + 2, &nk, &err);
        rec[0] = static_cast<double>(k);
        rec[1] = nk;
        PetscCall(add(rec.data()));
      } else if (active > 0) {
        PetscCall(serve(true));
      }
      if (ndone != reported) PetscCall(progress.updateCount(ndone - ndone0, todo, "problems"));
      reported = ndone;
    }
    PetscCall(flushNow());
  } else {
    std::vector<double> out(1, 0.0); // [stop flag, results of the previous chunk]
    while (true) {
      out[0] = suite::g_stop_signal ? 1.0 : 0.0;
      PetscCallMPI(MPI_Send(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, 0, kTagRequest, comm));
      long long work[2];
      PetscCallMPI(MPI_Recv(work, 2, MPI_LONG_LONG, 0, kTagWork, comm, MPI_STATUS_IGNORE));
      if (work[0] >= work[1]) break;
      out.assign(1 + static_cast<size_t>(work[1] - work[0]) * rec_len, 0.0);
      for (long long k = work[0]; k < work[1]; ++k) {
        double* r = out.data() + 1 + (k - work[0]) * rec_len;
        int nk = 0;
        solveOne(b, k, r + 2, &nk, &err);
        r[0] = static_cast<double>(k);
        r[1] = nk;
      }
    }
  }
  const double wall = MPI_Wtime() - t_start;
  long long counts[2] = {ndone, stopped};
  PetscCallMPI(MPI_Bcast(counts, 2, MPI_LONG_LONG, 0, comm));
  ndone = counts[0];
  if (counts[1] != 0 || ndone < b.count) {
    if (rank == 0) {
      std::string cerr;
      try {
        store.file().close();
      } catch (const std::exception& e) {
        cerr = e.what();
      }
      PetscCheck(cerr.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "lcpbench: %s", cerr.c_str());
    }
    PetscCall(suite::logInfo(comm, false,
                             "lcpbench: stop requested (%s): %lld of %lld problems done (%lld in this run, "
                             "%.3f s), flushed to %s; run the same command again to resume",
                             counts[1] == 2 ? "max_walltime" : "signal", ndone, b.count, ndone - ndone0, wall,
                             partial.c_str()));
    PetscFunctionReturn(0);
  }

  // ---- complete: statistics by a streamed pass, final attributes, OUT.partial -> OUT ----
  std::vector<double> table(static_cast<size_t>(ns) * 8, 0.0);
  long long tot[2] = {0, 0}; // invalid, unsolved
  std::string first_unsolved;
  err.clear();
  if (rank == 0) {
    try {
      // The statistics are added to a copy (OUT.tmp), renamed to OUT when complete; OUT.partial is removed
      // last. A kill during this phase (new datasets and attributes: metadata) leaves OUT.partial intact,
      // and running the command again redoes only this phase.
      suite::H5AppendFile& f = store.file();
      f.close();
      const std::string tmp = std::string(output) + ".tmp";
      std::filesystem::copy_file(partial, tmp, std::filesystem::copy_options::overwrite_existing);
      f.open(tmp, true);
      for (int s = 0; s < ns; ++s) {
        const SolverSummary S = summarise(f, b.solver_names[s], b.count);
        double* t = &table[8 * s];
        t[0] = S.failed, t[1] = S.med_it, t[2] = S.med_piv, t[3] = S.med_pvn, t[4] = S.tsum;
        t[5] = S.tsum > 0 ? b.count / S.tsum : 0.0, t[6] = S.csum, t[7] = S.csum > 0 ? b.count / S.csum : 0.0;
        if (s == 0) tot[0] = S.invalid;
        tot[1] += S.unsolved;
        if (first_unsolved.empty() && S.first_unsolved >= 0)
          first_unsolved = b.solver_names[s] + " on problem " + std::to_string(S.first_unsolved) + ": " +
                           statusName(static_cast<Status>(S.first_status));
      }
      f.setAttribute("/", "program", ctx.program());
      f.setAttribute("/", "version", std::string(suite::versionString()));
      f.setAttribute("/", "options", ctx.optionsText());
      f.setAttribute("/", "nranks", static_cast<long long>(size));
      f.setAttribute("/", "start_time", ctx.startTimeIso());
      f.setAttribute("/", "family", b.family);
      f.setAttribute("/", "count", b.count);
      f.setAttribute("/", "solvers", join(b.solver_names));
      f.setAttribute("/", "acceptance", "natural residual |z - mid(l,u,z-w)|_inf <= rel_tol (1 + |q|_inf)");
      f.setAttribute("/", "rel_tol", (double)rel_tol);
      f.setAttribute(
          "/", "status_codes",
          "0 solved, 1 max_iterations, 2 ray_termination, 3 breakdown, 4 unsupported, 5 not_accepted, "
          "6 invalid_input, 7 numerical_error");
      std::vector<double> walls, solved;
      store.runTotals(&walls, &solved);
      f.setAttribute("/batch", "run_wall_seconds", walls);
      f.setAttribute("/batch", "solved_per_run", solved);
      f.setAttribute("/", "batch_wall_seconds", std::accumulate(walls.begin(), walls.end(), 0.0));
      if (b.family != "file") {
        f.setAttribute("/", "n", (long long)n);
        f.setAttribute("/", "cond", (double)cond);
        f.setAttribute("/", "qrange", (double)qrange);
        f.setAttribute("/", "seed", (long long)seed);
        if (b.family == "random_box") {
          f.setAttribute("/", "lower", (double)lower);
          f.setAttribute("/", "upper", (double)upper);
        }
      } else {
        f.setAttribute("/", "files", join(b.files));
      }
      f.setAttribute("/", "wall_seconds", ctx.wallSeconds());
      f.setAttribute("/batch", "complete", 1LL);
      f.close();
      if (std::rename(tmp.c_str(), output) != 0)
        throw std::runtime_error("cannot rename " + tmp + " to " + output);
      std::remove(partial.c_str());
    } catch (const std::exception& e) {
      err = e.what();
    }
  }
  PetscCall(bcastError(comm, &err));
  PetscCheck(err.empty(), comm, PETSC_ERR_FILE_WRITE, "lcpbench: writing the results failed: %s",
             err.c_str());
  PetscCallMPI(MPI_Bcast(table.data(), static_cast<int>(table.size()), MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(tot, 2, MPI_LONG_LONG, 0, comm));
  PetscCall(bcastError(comm, &first_unsolved));
  PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8s %8s %10s %10s %12s %12s %12s", "solver", "solved",
                           "failed", "med.iter", "med.piv/n", "time [s]", "problems/s", "prob/cpu-s"));
  for (int s = 0; s < ns; ++s) {
    const double* t = &table[8 * s];
    PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8lld %8lld %10.1f %10.2f %12.4g %12.1f %12.1f",
                             b.solver_names[s].c_str(), b.count - (long long)t[0], (long long)t[0], t[1],
                             t[3], t[4], t[5], t[7]));
  }
  PetscCall(
      suite::logInfo(comm, ctx.quiet(),
                     "lcpbench: %lld problems (%lld in this run) in %.3f s wall (%.1f problems/s), results "
                     "in %s",
                     b.count, b.count - ndone0, wall, (b.count - ndone0) / std::max(wall, 1e-12), output));
  // Bad input: every rank holds the same file list and messages (generated problems are validated where
  // solved).
  if (b.family == "file") {
    for (size_t k = 0; k < b.file_errors.size(); ++k)
      if (!b.file_errors[k].empty())
        PetscCall(PetscPrintf(comm, "lcpbench: problem %zu recorded as invalid input: %s\n", k,
                              b.file_errors[k].c_str()));
  }
  PetscCheck(
      tot[0] == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
      "%lld problem(s) with invalid input (recorded with status 6 = invalid_input; the others kept their "
      "results in %s)",
      tot[0], output);
  if (strict) {
    PetscCheck(tot[1] == 0, comm, PETSC_ERR_NOT_CONVERGED,
               "%lld solver run(s) did not solve their problem (first: %s; -strict)", tot[1],
               first_unsolved.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
