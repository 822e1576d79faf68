// lcpbench batch driver; see lcpbench_run.hpp and main.cpp.
#include "lcpbench_run.hpp"

#include "core/log.hpp"
#include "core/progress.hpp"
#include "io/h5_output.hpp"
#include "lcp/generators.hpp"
#include "lcp/readers.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

constexpr int kTagRequest = 4101, kTagWork = 4102;
constexpr int kFields = 6; // status, iterations, pivots, time, residual, cpu_time

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
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

} // namespace

PetscErrorCode runLcpBench(const suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  MPI_Comm comm = ctx.comm();
  const int rank = ctx.rank(), size = ctx.size();
  char family[64] = "random_box",
       solvers[1024] = "lemke,keller,cottle_dantzig,murty,bpp,fb_newton,smoothed_newton,pgs";
  char output[PETSC_MAX_PATH_LEN] = "", files[8192] = "";
  PetscInt n = 100, count = 500, max_it = 0, block_size = 3, chunk = 0, seed = 1;
  PetscReal cond = 1e4, qrange = 1e2, lower = -1e2, upper = 1e2, omega = 1.0, rel_tol = 1e-10;
  PetscBool strict = PETSC_FALSE, strict_set = PETSC_FALSE, refine = PETSC_TRUE;
  PetscBool family_set = PETSC_FALSE;
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
  PetscCall(PetscOptionsString("-file",
                               "Problem files for -family file (comma-separated; .dat Siconos, .h5 suite)",
                               "", files, files, sizeof files, nullptr));
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
  PetscCall(PetscOptionsString("-output", "HDF5 results file", "", output, output, sizeof output, nullptr));
  PetscOptionsEnd();
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) PetscFunctionReturn(0);

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
  if (!strict_set) strict = b.family == "file" ? PETSC_TRUE : PETSC_FALSE;
  if (b.family == "file") {
    b.files = split(files);
    PetscCheck(!b.files.empty(), comm, PETSC_ERR_ARG_WRONG, "-family file needs -file FILE[,FILE...]");
    for (const auto& f : b.files) {
      Problem p;
      std::string err;
      const bool h5 = f.size() > 3 && f.substr(f.size() - 3) == ".h5";
      if (h5) {
        PetscCall(readProblemH5(comm, f, &p)); // collective: a malformed HDF5 file stops the run
      } else {
        try {
          p = readSiconos(f);
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

  const int ns = static_cast<int>(b.solvers.size());
  const int rec_len = 2 + ns * kFields; // index, n, solver fields
  if (chunk == 0) chunk = std::max<long long>(1, std::min<long long>(64, b.count / (8LL * size)));
  PetscCall(suite::logInfo(comm, ctx.quiet(), "lcpbench: family %s, %lld problems%s, solvers %s, %d rank(s)",
                           family, b.count, b.family == "file" ? "" : (", n = " + std::to_string(n)).c_str(),
                           join(b.solver_names).c_str(), size));

  // ---- dynamic load balancing: rank 0 deals chunks of problem indices on request ----
  std::vector<double> all; // rank 0: count * rec_len
  if (rank == 0) all.assign(static_cast<size_t>(b.count) * rec_len, 0.0);
  const double t_start = MPI_Wtime();
  std::string err;
  std::vector<double> rec(rec_len);
  auto store = [&](const double* r) {
    const long long k = static_cast<long long>(r[0]);
    std::copy(r, r + rec_len, all.begin() + k * rec_len);
  };
  if (rank == 0) {
    suite::Progress progress(PETSC_COMM_SELF, ctx.quiet(), ctx.progressInterval(), 0.0);
    long long next = 0, done = 0, reported = -1;
    int active = size - 1;
    std::vector<double> msg;
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
        for (int off = 0; off + rec_len <= len; off += rec_len) {
          store(msg.data() + off);
          ++done;
        }
        long long work[2] = {next, std::min(b.count, next + (long long)chunk)};
        next = work[1];
        if (work[0] == work[1]) --active;
        PetscCallMPI(MPI_Send(work, 2, MPI_LONG_LONG, st.MPI_SOURCE, kTagWork, comm));
        if (block) break;
      }
      PetscFunctionReturn(0);
    };
    while (next < b.count || active > 0) {
      if (size > 1) PetscCall(serve(false));
      if (next < b.count) {
        const long long k = next++;
        int nk = 0;
        solveOne(b, k, rec.data() + 2, &nk, &err);
        rec[0] = static_cast<double>(k);
        rec[1] = nk;
        store(rec.data());
        ++done;
      } else if (active > 0) {
        PetscCall(serve(true));
      }
      if (done != reported) PetscCall(progress.updateCount(done, b.count, "problems"));
      reported = done;
    }
  } else {
    std::vector<double> out; // results of the previous chunk
    while (true) {
      PetscCallMPI(MPI_Send(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, 0, kTagRequest, comm));
      long long work[2];
      PetscCallMPI(MPI_Recv(work, 2, MPI_LONG_LONG, 0, kTagWork, comm, MPI_STATUS_IGNORE));
      if (work[0] >= work[1]) break;
      out.assign(static_cast<size_t>(work[1] - work[0]) * rec_len, 0.0);
      for (long long k = work[0]; k < work[1]; ++k) {
        double* r = out.data() + (k - work[0]) * rec_len;
        int nk = 0;
        solveOne(b, k, r + 2, &nk, &err);
        r[0] = static_cast<double>(k);
        r[1] = nk;
      }
    }
  }
  const double wall = MPI_Wtime() - t_start;

  // ---- results on rank 0: per-solver datasets, histograms, summary ----
  suite::H5Output out;
  PetscCall(out.open(comm, output));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(out.writeAttribute("/", "family", b.family));
  PetscCall(out.writeAttribute("/", "count", b.count));
  PetscCall(out.writeAttribute("/", "solvers", join(b.solver_names)));
  PetscCall(out.writeAttribute("/", "acceptance",
                               "natural residual |z - mid(l,u,z-w)|_inf <= rel_tol (1 + |q|_inf)"));
  PetscCall(out.writeAttribute("/", "rel_tol", (double)rel_tol));
  PetscCall(out.writeAttribute("/", "status_codes",
                               "0 solved, 1 max_iterations, 2 ray_termination, 3 breakdown, "
                               "4 unsupported, 5 not_accepted, 6 invalid_input, 7 numerical_error"));
  PetscCall(out.writeAttribute("/", "batch_wall_seconds", wall));
  if (b.family != "file") {
    PetscCall(out.writeAttribute("/", "n", (long long)n));
    PetscCall(out.writeAttribute("/", "cond", (double)cond));
    PetscCall(out.writeAttribute("/", "qrange", (double)qrange));
    PetscCall(out.writeAttribute("/", "seed", (long long)seed));
    if (b.family == "random_box") {
      PetscCall(out.writeAttribute("/", "lower", (double)lower));
      PetscCall(out.writeAttribute("/", "upper", (double)upper));
    }
  } else {
    PetscCall(out.writeAttribute("/", "files", join(b.files)));
  }
  const unsigned long long C = static_cast<unsigned long long>(b.count);
  // Only rank 0 holds the gathered table (workers keep one chunk): the replicated writes take rank 0's data;
  // the other ranks pass the same shapes with a dummy buffer (nothing selected).
  const bool r0 = rank == 0;
  std::vector<int> sizes(r0 ? C : 1);
  for (unsigned long long k = 0; r0 && k < C; ++k) sizes[k] = static_cast<int>(all[k * rec_len + 1]);
  PetscCall(out.writeReplicated("/problems/n", sizes.data(), {C}, ""));
  long long unsolved_total = 0, invalid_total = 0;
  std::string first_unsolved;
  PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8s %8s %10s %10s %12s %12s %12s", "solver", "solved",
                           "failed", "med.iter", "med.piv/n", "time [s]", "problems/s", "prob/cpu-s"));
  for (int s = 0; s < ns; ++s) {
    const std::string g = "/results/" + b.solver_names[s];
    std::vector<int> status(r0 ? C : 1);
    std::vector<long long> iters(r0 ? C : 1), pivs(r0 ? C : 1);
    std::vector<double> times(r0 ? C : 1), resid(r0 ? C : 1), cpu(r0 ? C : 1);
    std::vector<double> it_ok, pv_ok, pvn_ok;
    double tsum = 0.0, csum = 0.0;
    long long failed = 0;
    for (unsigned long long k = 0; r0 && k < C; ++k) {
      const double* r = &all[k * rec_len + 2 + s * kFields];
      status[k] = static_cast<int>(r[0]);
      iters[k] = static_cast<long long>(r[1]);
      pivs[k] = static_cast<long long>(r[2]);
      times[k] = r[3];
      resid[k] = r[4];
      cpu[k] = r[5];
      tsum += r[3];
      csum += r[5];
      if (status[k] == 0) {
        it_ok.push_back(r[1]);
        pv_ok.push_back(r[2]);
        pvn_ok.push_back(r[2] / std::max(1, sizes[k]));
      } else {
        ++failed;
        if (status[k] == static_cast<int>(Status::InvalidInput)) {
          if (s == 0) ++invalid_total;
        } else {
          ++unsolved_total;
          if (first_unsolved.empty())
            first_unsolved = b.solver_names[s] + " on problem " + std::to_string(k) + ": " +
                             statusName(static_cast<Status>(status[k]));
        }
      }
    }
    const suite::Dims d = {C};
    PetscCall(out.writeReplicated(g + "/status", status.data(), d, ""));
    PetscCall(out.writeReplicated(g + "/iterations", iters.data(), d, ""));
    PetscCall(out.writeReplicated(g + "/pivots", pivs.data(), d, ""));
    PetscCall(out.writeReplicated(g + "/time", times.data(), d, "s"));
    PetscCall(out.writeReplicated(g + "/residual", resid.data(), d, ""));
    PetscCall(out.writeReplicated(g + "/cpu_time", cpu.data(), d, "s"));
    // histograms of the solved problems: iterations (integer bins) and pivots in units of n (0.1 n bins)
    double maxes[2] = {it_ok.empty() ? 0.0 : *std::max_element(it_ok.begin(), it_ok.end()),
                       pvn_ok.empty() ? 0.0 : *std::max_element(pvn_ok.begin(), pvn_ok.end())};
    PetscCallMPI(MPI_Bcast(maxes, 2, MPI_DOUBLE, 0, comm)); // identical histogram shapes on every rank
    const double itmax = maxes[0];
    const long long iw = std::max(1LL, static_cast<long long>(std::ceil((itmax + 1) / 100.0)));
    const long long nib = static_cast<long long>(itmax) / iw + 1;
    std::vector<long long> ih(nib, 0);
    std::vector<double> ie(nib + 1);
    for (long long i = 0; i <= nib; ++i) ie[i] = static_cast<double>(i * iw);
    for (double v : it_ok) ++ih[static_cast<long long>(v) / iw];
    const double pmax = maxes[1];
    const long long npb = static_cast<long long>(std::floor(pmax / 0.1)) + 1;
    std::vector<long long> ph(npb, 0);
    std::vector<double> pe(npb + 1);
    for (long long i = 0; i <= npb; ++i) pe[i] = 0.1 * i;
    for (double v : pvn_ok) ++ph[std::min(npb - 1, static_cast<long long>(std::floor(v / 0.1)))];
    PetscCall(
        out.writeReplicated(g + "/histogram/iterations_counts", ih.data(), {(unsigned long long)nib}, ""));
    PetscCall(
        out.writeReplicated(g + "/histogram/iterations_edges", ie.data(), {(unsigned long long)nib + 1}, ""));
    PetscCall(
        out.writeReplicated(g + "/histogram/pivots_per_n_counts", ph.data(), {(unsigned long long)npb}, ""));
    PetscCall(out.writeReplicated(g + "/histogram/pivots_per_n_edges", pe.data(),
                                  {(unsigned long long)npb + 1}, ""));
    // summary (rank 0 values broadcast so that every rank writes identical attributes)
    double summ[8] = {static_cast<double>(failed),
                      median(it_ok),
                      median(pv_ok),
                      median(pvn_ok),
                      tsum,
                      tsum > 0 ? b.count / tsum : 0.0,
                      csum,
                      csum > 0 ? b.count / csum : 0.0};
    PetscCallMPI(MPI_Bcast(summ, 8, MPI_DOUBLE, 0, comm));
    PetscCall(out.writeAttribute(g, "failures", (long long)summ[0]));
    PetscCall(out.writeAttribute(g, "median_iterations", summ[1]));
    PetscCall(out.writeAttribute(g, "median_pivots", summ[2]));
    PetscCall(out.writeAttribute(g, "median_pivots_per_n", summ[3]));
    PetscCall(out.writeAttribute(g, "total_time", summ[4]));
    PetscCall(out.writeAttribute(g, "problems_per_second_per_core", summ[5]));
    PetscCall(out.writeAttribute(g, "total_cpu_time", summ[6]));
    PetscCall(out.writeAttribute(g, "problems_per_cpu_second", summ[7]));
    PetscCall(suite::logInfo(comm, ctx.quiet(), "  %-16s %8lld %8lld %10.1f %10.2f %12.4g %12.1f %12.1f",
                             b.solver_names[s].c_str(), b.count - (long long)summ[0], (long long)summ[0],
                             summ[1], summ[3], summ[4], summ[5], summ[7]));
  }
  PetscCall(out.commit(&ctx));
  long long tot[2] = {invalid_total, unsolved_total};
  PetscCallMPI(MPI_Bcast(tot, 2, MPI_LONG_LONG, 0, comm));
  PetscCall(suite::logInfo(comm, ctx.quiet(),
                           "lcpbench: %lld problems in %.3f s wall (%.1f problems/s), results in %s", b.count,
                           wall, b.count / std::max(wall, 1e-12), output));
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
    int len = static_cast<int>(first_unsolved.size());
    PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
    first_unsolved.resize(len);
    PetscCallMPI(MPI_Bcast(first_unsolved.data(), len, MPI_CHAR, 0, comm));
    PetscCheck(tot[1] == 0, comm, PETSC_ERR_NOT_CONVERGED,
               "%lld solver run(s) did not solve their problem (first: %s; -strict)", tot[1],
               first_unsolved.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
