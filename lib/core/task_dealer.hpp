// Dynamic load balancing of independent tasks over the ranks of a communicator, with every result gathered to
// every rank. Rank 0 deals task indices one at a time in their order (callers put the largest first: the
// longest-processing-time-first rule, Graham, SIAM J. Appl. Math. 17 (1969) 416-429), answers requests
// (MPI point-to-point) between the tasks it solves itself; the other ranks ask for the next task after each
// one. Then every rank receives every result (MPI_Allgatherv) and stores it at its task's index, so the
// results do not depend on which rank solved which task, nor on the number of ranks, provided solve(k)
// depends only on k. Used by the contact stepper's islands (-contact_islands); the idea is lcpbench's dealer
// (apps/lcpbench/lcpbench_dealer.cpp), which also streams results to a file and obeys stop requests.
#pragma once

#include <petscsys.h>

#include <functional>
#include <vector>

namespace suite {

using TaskSolve = std::function<std::vector<double>(int task)>;

// Collective on comm: results->at(k) = solve(k) for k in [0, ntasks), on every rank (ntasks the same on all).
PetscErrorCode dealTasks(MPI_Comm comm, int ntasks, const TaskSolve& solve,
                         std::vector<std::vector<double>>* results);

} // namespace suite
