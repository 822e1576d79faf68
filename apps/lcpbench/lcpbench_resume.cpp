// lcpbench's resume (-resume, default on; see lcpbench.hpp): the batch header that identifies a batch, and the
// start of a run, which continues a matching OUT.partial (done problems are skipped, never recomputed; the
// run gets the next run number) or creates a new one. A mismatched or foreign OUT.partial is one clear error
// that leaves the file as it is (-resume 0 discards it).
#include "lcpbench.hpp"

#include "core/comma_list.hpp"
#include "core/log.hpp"
#include "core/rank0_work.hpp"

#include <algorithm>
#include <stdexcept>
#include <unistd.h>

namespace lcpbench_app {

namespace {

const char* const kHint = "; rerun with the same options to resume it, or pass -resume 0 to discard it";

// Throws unless OUT.partial (open read-only in f) holds a batch with exactly this header and size.
void checkResumable(suite::H5AppendFile& f, const std::string& partial, const BatchHeader& header,
                    unsigned long long count) {
  for (const auto& kv : header) {
    std::string have;
    if (!f.getAttribute("/batch", kv.first, &have))
      throw std::runtime_error(partial + " lacks the batch header attribute /batch/" + kv.first +
                               " (not an lcpbench batch?)" + kHint);
    if (have != kv.second)
      throw std::runtime_error(partial + " holds an interrupted batch with other parameters (" + kv.first +
                               ": '" + have + "' there, '" + kv.second + "' now)" + kHint);
  }
  if (f.size("/batch/done") != count)
    throw std::runtime_error(partial + ": /batch/done has the wrong size" + kHint);
}

// Reads the done flags into rp; returns the run number: one more than the largest run recorded among the
// done problems.
int readDone(suite::H5AppendFile& f, unsigned long long C, ResumePoint* rp) {
  for (unsigned long long a = 0; a < C; a += kBlock)
    f.read("/batch/done", a, rp->done.data() + a, std::min(kBlock, C - a));
  int last = -1;
  std::vector<int> runs;
  for (unsigned long long a = 0; a < C; a += kBlock) {
    const unsigned long long m = std::min(kBlock, C - a);
    runs.resize(m);
    f.read("/batch/run", a, runs.data(), m);
    for (unsigned long long i = 0; i < m; ++i)
      if (rp->done[a + i]) {
        ++rp->ndone;
        last = std::max(last, runs[i]);
      }
  }
  return last + 1;
}

// Continues OUT.partial; returns the note logged by rank 0.
std::string resumeStore(const std::string& partial, Store* store, ResumePoint* rp) {
  const unsigned long long C = static_cast<unsigned long long>(store->count());
  if (!suite::H5AppendFile::isHdf5(partial))
    throw std::runtime_error(partial +
                             " exists but is not an HDF5 file (not an interrupted lcpbench batch?)" + kHint);
  suite::H5AppendFile& f = store->file();
  f.open(partial, false); // read-only until the header matches: a refused resume leaves the file as is
  checkResumable(f, partial, store->header(), C);
  f.open(partial, true);
  store->resumeAs(readDone(f, C, rp));
  return "resuming " + partial + ": " + std::to_string(rp->ndone) + " of " + std::to_string(C) +
         " problems done in " + std::to_string(store->run()) + " earlier run(s)";
}

// Rank 0: resumes or creates OUT.partial; returns the note to log ("" if none).
std::string startStore(const std::string& partial, bool resume, Store* store, ResumePoint* rp) {
  std::string note;
  rp->done.assign(static_cast<size_t>(store->count()), 0);
  rp->ndone = 0;
  if (resume && access(partial.c_str(), F_OK) == 0)
    note = resumeStore(partial, store, rp);
  else
    store->create(partial);
  store->file().flush(); // from here on only raw data is written in place (no metadata) until completion
  return note;
}

} // namespace

// A resumed batch must match the header exactly (results must not depend on the run).
BatchHeader batchHeader(const Options& o, const Batch& b) {
  BatchHeader header = {{"family", b.family},
                        {"count", std::to_string(b.count)},
                        {"solvers", suite::joinCommaList(b.solver_names)},
                        {"max_it", std::to_string(o.max_it)},
                        {"omega", suite::exactText(o.omega)},
                        {"block_size", std::to_string(o.block_size)},
                        {"rel_tol", suite::exactText(o.rel_tol)},
                        {"refine", o.refine ? "1" : "0"}};
  if (b.fromFiles()) {
    header.push_back({"files", suite::joinCommaList(b.files)});
    header.push_back({"fclib_model", o.fclib_model});
    return header;
  }
  const BatchHeader generated = {{"n", std::to_string(o.n)},           {"seed", std::to_string(o.seed)},
                                 {"cond", suite::exactText(o.cond)},   {"qrange", suite::exactText(o.qrange)},
                                 {"lower", suite::exactText(o.lower)}, {"upper", suite::exactText(o.upper)}};
  header.insert(header.end(), generated.begin(), generated.end());
  return header;
}

PetscErrorCode startBatchFile(const suite::RunContext& ctx, const std::string& partial, bool resume,
                              Store* store, ResumePoint* rp) {
  std::string note;
  PetscFunctionBeginUser;
  PetscCall(suite::onRank0(ctx.comm(), PETSC_ERR_FILE_UNEXPECTED, "",
                           [&] { note = startStore(partial, resume, store, rp); }));
  PetscCallMPI(MPI_Bcast(&rp->ndone, 1, MPI_LONG_LONG, 0, ctx.comm()));
  if (ctx.rank() == 0 && !note.empty())
    PetscCall(suite::logInfo(PETSC_COMM_SELF, ctx.quiet(), "lcpbench: %s", note.c_str()));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
