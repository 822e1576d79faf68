// What every program says when it ends, the same way in every app: the run's status (also the `status` root
// attribute of its output file) and one end-of-run summary line naming what it wrote.
//   euler: completed: 250 steps to t = 0.2 in 1.23 s (8.1e+06 cell-steps/s); wrote sod.h5, sod.xmf
//   contact: stopped by walltime: 120 of 400 steps in 5.00 s; wrote pile.h5, pile.xmf
//   reorder: completed: bcsstk10.mtx, 3 orderings in 0.01 s; no output file (-output FILE writes one)
#pragma once

#include "core/run_context.hpp"
#include "core/time_loop.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {

// "completed", "stopped by walltime", "stopped by signal" or "failed at step N" (N: the step that failed).
std::string runStatus(const LoopSummary& s);

// "<program>: <status>: <what>; wrote A, B" or, when written is empty, "...; no output file (-output FILE writes
// one)". Printed on rank 0 unless -quiet.
PetscErrorCode logRunSummary(const RunContext& ctx, const std::string& status, const std::string& what,
                             const std::vector<std::string>& written);

// "N steps to t = T in W s": the steps and the wall time of this run alone (a restart counts from its step; a
// restart that finds nothing left to do says so instead of a rate).
std::string stepsText(const LoopSummary& s);

} // namespace suite
