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
                               ": '" + have + "' in the file, '" + kv.second + "' given)" + kHint);
  }
  if (f.size("/batch/done") != count)
    throw std::runtime_error(partial + ": /batch/done has the wrong size" + kHint);
}

// Continues OUT.partial (the done flags read into rp, the run number one more than the largest run recorded
// among the done problems); returns the note logged by rank 0.
std::string resumeStore(const std::string& partial, Store* store, RunState* st) {
  const unsigned long long C = static_cast<unsigned long long>(store->count);
  if (!suite::H5AppendFile::isHdf5(partial))
    throw std::runtime_error(partial +
                             " exists but is not an HDF5 file (not an interrupted lcpbench batch?)" + kHint);
  suite::H5AppendFile& f = store->file;
  f.open(partial, false); // read-only until the header matches: a refused resume leaves the file as is
  checkResumable(f, partial, store->header, C);
  f.open(partial, true);
  int last = -1;
  forBlocks<int>(f, "/batch/run", C, [&](unsigned long long a, const std::vector<int>& runs) {
    f.read("/batch/done", a, st->done.data() + a, runs.size());
    for (size_t i = 0; i < runs.size(); ++i)
      if (st->done[a + i]) {
        ++st->ndone0;
        last = std::max(last, runs[i]);
      }
  });
  store->run = last + 1;
  return "resuming " + partial + ": " + std::to_string(st->ndone0) + " of " + std::to_string(C) +
         " problems done in " + std::to_string(store->run) + " earlier run(s)";
}

// A resumed batch must match the header exactly (results must not depend on the run).
BatchHeader batchHeader(const Options& o, const Batch& b) {
  using std::to_string;
  using suite::exactText;
  BatchHeader h = {{"family", b.family},
                   {"count", to_string(b.count)},
                   {"solvers", suite::joinCommaList(b.solver_names)},
                   {"max_it", to_string(o.max_it)},
                   {"omega", exactText(o.omega)},
                   {"block_size", to_string(o.block_size)},
                   {"rel_tol", exactText(o.rel_tol)},
                   {"refine", o.refine ? "1" : "0"},
                   {"time_repeat", exactText(o.time_repeat)},
                   {"time_batches", to_string(o.time_batches)},
                   {"save_solutions", o.save_solutions ? "1" : "0"}};
  const BatchHeader files = {{"files", suite::joinCommaList(o.files)}, {"fclib_model", o.fclib_model}};
  const BatchHeader generated = {{"n", to_string(o.n)},         {"seed", to_string(o.seed)},
                                 {"cond", exactText(o.cond)},   {"qrange", exactText(o.qrange)},
                                 {"lower", exactText(o.lower)}, {"upper", exactText(o.upper)}};
  const BatchHeader& more = b.fromFiles() ? files : generated;
  h.insert(h.end(), more.begin(), more.end());
  if (b.auto_index >= 0) h.push_back({"portfolio", b.portfolio.source});
  return h;
}

} // namespace

PetscErrorCode startBatchFile(const suite::RunContext& ctx, const Options& o, const Batch& b, Store* store,
                              RunState* st) {
  const std::string partial = o.output + ".partial";
  std::string note; // rank 0's
  PetscFunctionBeginUser;
  store->header = batchHeader(o, b);
  PetscCall(suite::onRank0(ctx.comm(), PETSC_ERR_FILE_UNEXPECTED, "", [&] {
    st->done.assign(static_cast<size_t>(store->count), 0);
    if (o.resume && access(partial.c_str(), F_OK) == 0)
      note = resumeStore(partial, store, st);
    else
      store->create(partial);
    store->file.flush(); // from here on only raw data is written in place (no metadata) until completion
  }));
  PetscCallMPI(MPI_Bcast(&st->ndone0, 1, MPI_LONG_LONG, 0, ctx.comm()));
  if (ctx.rank() == 0 && !note.empty())
    PetscCall(suite::logInfo(PETSC_COMM_SELF, ctx.quiet(), "lcpbench: %s", note.c_str()));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
