// lcpbench's batch: problem k is generated (a family of lib/lcp, seeded per index) or the k-th -file (read up
// front by every rank), and given to every solver. A record depends on k alone, not on the rank solving it.
#include "lcpbench.hpp"

#include "core/rank0_work.hpp"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

// Reads one -file (collective for suite .h5 files); *err gets the reason it is invalid, or "".
PetscErrorCode readProblemFile(MPI_Comm comm, const std::string& f, FclibModel model, Problem* p,
                               std::string* err) {
  auto endsWith = [&f](const std::string& x) {
    return f.size() > x.size() && f.compare(f.size() - x.size(), x.size(), x) == 0;
  };
  PetscFunctionBeginUser;
  const bool fclib = isFclibFile(f); // every rank reads the same file: same answer
  if (!fclib && (endsWith(".h5") || endsWith(".hdf5"))) {
    PetscCall(readProblemH5(comm, f, p)); // collective: a malformed HDF5 file stops the run
  } else {
    try {
      *p = fclib ? readFclibLocal(f, model) : readSiconos(f);
    } catch (const std::exception& e) {
      *err = e.what();
    }
  }
  if (err->empty()) {
    *err = validate(*p);
    if (!err->empty()) *err = f + ": " + *err;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode makeBatch(MPI_Comm comm, const Options& o, Batch* b) {
  PetscFunctionBeginUser;
  b->family = o.family;
  b->solver_names = o.solvers;
  for (const auto& s : b->solver_names) b->solvers.push_back(s == "auto" ? nullptr : makeSolver(s));
  const auto at = std::find(o.solvers.begin(), o.solvers.end(), "auto");
  b->auto_index = at == o.solvers.end() ? -1 : static_cast<int>(at - o.solvers.begin());
  b->portfolio = builtinPortfolio();
  if (b->auto_index >= 0 && !o.portfolio.empty()) PetscCall(loadPortfolio(comm, o.portfolio, &b->portfolio));
  b->gp = {static_cast<int>(o.n), o.cond, o.qrange, o.lower, o.upper, static_cast<std::uint64_t>(o.seed)};
  b->opt = {static_cast<int>(o.max_it), o.rel_tol, nullptr, o.omega, static_cast<int>(o.block_size),
            o.refine == PETSC_TRUE};
  b->delay = o.delay;
  b->timing = {o.time_repeat, static_cast<int>(o.time_batches)};
  b->warmup = o.warmup;
  b->count = o.count;
  b->z_len = o.save_solutions ? static_cast<int>(o.n) : 0;
  if (!b->fromFiles()) PetscFunctionReturn(0);
  b->file_problems.resize(o.files.size());
  b->file_errors.resize(o.files.size());
  for (size_t i = 0; i < o.files.size(); ++i)
    PetscCall(readProblemFile(comm, o.files[i], fclibModel(o.fclib_model), &b->file_problems[i],
                              &b->file_errors[i]));
  b->count = static_cast<long long>(o.files.size());
  if (o.save_solutions) {
    int n_max = 1; // one NaN per problem when no file is valid
    for (const auto& p : b->file_problems) n_max = std::max(n_max, p.size());
    b->z_len = n_max;
  }
  PetscFunctionReturn(0);
}

namespace {

// Index of a solver name in the registry (the index lcpbench's auto records use), -1 if none.
double registryIndex(const std::string& name) {
  static const std::vector<std::string> names = solverNames();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1.0 : static_cast<double>(it - names.begin());
}

// The portfolio on p; its choices into rec[0, kAutoFields).
Result solveAutoRecorded(const Batch& b, const Problem* p, double* rec, const Timing& t) {
  std::fill(rec, rec + kAutoFields, -1.0);
  rec[2] = 0;
  if (!p) {
    Result r;
    r.status = Status::InvalidInput;
    return r;
  }
  AutoOptions ao;
  ao.rel_tol = b.opt.rel_tol;
  ao.max_iterations = b.opt.max_iterations;
  ao.portfolio = &b.portfolio;
  AutoInfo info;
  const Result r = timedRun(
      [&](bool timed) {
        ao.timed = timed;
        return solveAuto(*p, ao, timed ? &info : nullptr);
      },
      t);
  rec[0] = problemClassIndex(info.features.name());
  rec[1] = r.ok() ? registryIndex(info.solver) : -1.0;
  rec[2] = static_cast<double>(info.attempts.size());
  for (size_t j = 0; j < info.attempts.size() && j < static_cast<size_t>(kAutoMaxTried); ++j)
    rec[3 + j] = registryIndex(info.attempts[j].solver);
  return r;
}

// Problem k: the k-th file, or generated into *gen; *err: "" or why it is invalid (then no solver runs it).
// nullptr when there is no problem at all (an invalid file, a failed generation).
const Problem* problemOf(const Batch& b, long long k, Problem* gen, std::string* err) {
  if (b.fromFiles()) {
    *err = b.file_errors[k];
    return err->empty() ? &b.file_problems[k] : nullptr;
  }
  *err = suite::messageOf([&] { *gen = generate(b.family, b.gp, static_cast<std::uint64_t>(k)); });
  if (!err->empty()) return nullptr;
  *err = validate(*gen);
  return gen;
}

// The solver run j-th on problem k. A solve is faster right after the solves of some solvers than of others
// (their code and data still in the caches: auto runs bpp first, and listed after bpp it took 0.65 times its
// time listed first), so a fixed order would time each solver by its place in -solvers. Problem k runs the
// listed order rotated by k/2 (k even) or the reversed order rotated by k/2 (k odd): over the batch every
// solver runs in every place and after every other solver alike, and listing the solvers in another order
// only permutes which problem gets which arrangement.
size_t solverAt(size_t solvers, long long k, size_t j) {
  const size_t i = (j + static_cast<size_t>((k / 2) % static_cast<long long>(solvers))) % solvers;
  return k % 2 == 0 ? i : solvers - 1 - i;
}

// Problem k (p; nullptr: invalid input) solved by every solver with timing t, into rec[2, ...).
void solveAll(const Batch& b, long long k, const Problem* p, const Timing& t, double* rec) {
  for (size_t j = 0; j < b.solvers.size(); ++j) {
    const size_t s = solverAt(b.solvers.size(), k, j);
    Result r; // invalid input: no solver runs (zero counts and times, infinite residual)
    r.status = Status::InvalidInput;
    if (static_cast<int>(s) == b.auto_index) {
      r = solveAutoRecorded(b, p, rec + b.autoBase(), t);
    } else if (p) {
      r = timedRun(
          [&](bool timed) {
            SolverOptions so = b.opt;
            so.timed = timed;
            return solve(*b.solvers[s], *p, so);
          },
          t);
    }
    const double v[kFields] = {static_cast<double>(r.status),
                               static_cast<double>(r.iterations),
                               static_cast<double>(r.pivots),
                               r.time,
                               r.residual,
                               r.cpu_time};
    std::copy(v, v + kFields, rec + 2 + s * kFields);
    if (b.z_len > 0) { // the z returned, solved or not (NaN: none, or past its n)
      double* z = rec + b.zBase() + s * b.z_len;
      std::fill(z, z + b.z_len, std::nan(""));
      for (int i = 0; i < static_cast<int>(r.z.size()) && i < b.z_len; ++i) z[i] = r.z[i];
    }
  }
}

} // namespace

void solveOne(const Batch& b, long long k, double* rec) {
  Problem gen;
  std::string err;
  const Problem* p = problemOf(b, k, &gen, &err);
  rec[0] = static_cast<double>(k);
  rec[1] = p ? p->size() : 0;
  solveAll(b, k, err.empty() ? p : nullptr, b.timing, rec);
  if (b.delay > 0) usleep(static_cast<useconds_t>(b.delay * 1e6));
}

// The first touch of a solver's code and memory (page faults, caches, branch predictors, lazy initialisation)
// is paid by whichever solve comes first: timed, it makes the first solver of -solvers look slower than the
// same solver listed later. Every solver solves the same problems here, in the same way as timed (one run, the
// timer read, no -time_repeat batches), before any timed solve.
long long warmUp(const Batch& b) {
  std::vector<double> rec(static_cast<size_t>(b.recordLength()));
  const Timing once; // one run, as a timed solve without -time_repeat
  long long solves = 0;
  for (long long k = 0; k < b.count && k < b.warmup + 1000 && solves < b.warmup; ++k) {
    Problem gen;
    std::string err;
    const Problem* p = problemOf(b, k, &gen, &err);
    if (!p || !err.empty()) continue; // an invalid problem runs no solver: not a warm-up
    solveAll(b, k, p, once, rec.data());
    ++solves;
  }
  return solves;
}

} // namespace lcpbench_app
