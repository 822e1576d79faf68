// lcpbench's batch: problem source and solvers (see lcpbench_batch.hpp).
#include "lcpbench_batch.hpp"

#include "lcp/readers.hpp"

#include <unistd.h>

namespace lcpbench_app {

using namespace suite::lcp;

namespace {

bool endsWith(const std::string& s, const std::string& x) {
  return s.size() > x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

// Reads one -file (collective for suite .h5 files); *err gets the reason it is invalid, or "".
PetscErrorCode readProblemFile(MPI_Comm comm, const std::string& f, FclibModel model, Problem* p,
                               std::string* err) {
  PetscFunctionBeginUser;
  err->clear();
  const bool fclib = isFclibFile(f); // every rank reads the same file: same answer
  const bool h5 = !fclib && (endsWith(f, ".h5") || endsWith(f, ".hdf5"));
  if (h5) {
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

PetscErrorCode readProblemFiles(MPI_Comm comm, const Options& o, Batch* b) {
  PetscFunctionBeginUser;
  b->files = o.files;
  for (const auto& f : b->files) {
    Problem p;
    std::string err;
    PetscCall(readProblemFile(comm, f, fclibModel(o.fclib_model), &p, &err));
    b->file_problems.push_back(std::move(p));
    b->file_errors.push_back(err);
  }
  b->count = static_cast<long long>(b->files.size());
  PetscFunctionReturn(0);
}

// Problem k: generated, or the k-th file; nullptr when invalid (*err says why).
const Problem* problem(const Batch& b, long long k, Problem* gen, std::string* err) {
  err->clear();
  if (b.fromFiles()) {
    if (!b.file_errors[k].empty()) *err = b.file_errors[k];
    return b.file_errors[k].empty() ? &b.file_problems[k] : nullptr;
  }
  try {
    *gen = generate(b.family, b.gp, static_cast<std::uint64_t>(k));
    *err = validate(*gen);
    return gen;
  } catch (const std::exception& e) {
    *err = e.what();
  }
  return nullptr;
}

void fillRecord(const Result& res, double* r) {
  r[0] = static_cast<double>(res.status);
  r[1] = res.iterations;
  r[2] = static_cast<double>(res.pivots);
  r[3] = res.time;
  r[4] = res.residual;
  r[5] = res.cpu_time;
}

void fillInvalid(double* r) {
  r[0] = static_cast<double>(Status::InvalidInput);
  r[1] = r[2] = r[3] = 0.0;
  r[4] = kInf;
  r[5] = 0.0;
}

} // namespace

PetscErrorCode makeBatch(MPI_Comm comm, const Options& o, Batch* b) {
  PetscFunctionBeginUser;
  b->family = o.family;
  b->solver_names = o.solvers;
  for (const auto& s : b->solver_names) b->solvers.push_back(makeSolver(s));
  b->gp.n = static_cast<int>(o.n);
  b->gp.cond = o.cond;
  b->gp.qrange = o.qrange;
  b->gp.lower = o.lower;
  b->gp.upper = o.upper;
  b->gp.seed = static_cast<std::uint64_t>(o.seed);
  b->opt.max_iterations = static_cast<int>(o.max_it);
  b->opt.omega = o.omega;
  b->opt.block_size = static_cast<int>(o.block_size);
  b->opt.rel_tol = o.rel_tol;
  b->opt.refine = o.refine;
  b->delay = o.delay;
  if (b->fromFiles())
    PetscCall(readProblemFiles(comm, o, b));
  else
    b->count = o.count;
  PetscFunctionReturn(0);
}

void solveOne(const Batch& b, long long k, double* rec, std::string* err) {
  Problem gen;
  const Problem* p = problem(b, k, &gen, err);
  rec[0] = static_cast<double>(k);
  rec[1] = p ? p->size() : 0;
  for (size_t s = 0; s < b.solvers.size(); ++s) {
    double* r = rec + 2 + s * kFields;
    if (!err->empty() || !p)
      fillInvalid(r);
    else
      fillRecord(solve(*b.solvers[s], *p, b.opt), r);
  }
  if (b.delay > 0) usleep(static_cast<useconds_t>(b.delay * 1e6));
}

} // namespace lcpbench_app
