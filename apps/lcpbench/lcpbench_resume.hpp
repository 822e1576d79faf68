// lcpbench's resume (-resume, default on): the batch header that identifies a batch, and the start of a
// run, which continues a matching OUT.partial (done problems are skipped, never recomputed; the run gets the
// next run number) or creates a new one. A mismatched or foreign OUT.partial is one clear error that leaves
// the file as it is (-resume 0 discards it).
#pragma once

#include "lcpbench_batch.hpp"
#include "lcpbench_options.hpp"
#include "lcpbench_store.hpp"

#include "core/run_context.hpp"

#include <string>
#include <vector>

namespace lcpbench_app {

// Where this run starts.
struct ResumePoint {
  std::vector<unsigned char> done; // rank 0: done flags (1 byte per problem)
  long long ndone = 0;             // every rank: problems done before this run
};

// The batch header: a resumed batch must match it exactly (results must not depend on the run).
BatchHeader batchHeader(const Options& o, const Batch& b);

// Collective: rank 0 resumes (o.resume and OUT.partial exists) or creates OUT.partial; one error for the
// job if that fails.
PetscErrorCode startBatchFile(const suite::RunContext& ctx, const std::string& partial, bool resume,
                              Store* store, ResumePoint* rp);

} // namespace lcpbench_app
