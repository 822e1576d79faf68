// lcpbench's batch: where problem k comes from (generator family of lib/lcp, seeded per index, or the k-th
// -file read up front by every rank) and the solvers it is given to. solveOne turns problem k into its record
// of kFields values per solver; it depends on k alone, so results do not depend on the rank that solves it.
#pragma once

#include "lcpbench_options.hpp"
#include "lcpbench_store.hpp"

#include "lcp/generators.hpp"
#include "lcp/solver.hpp"

#include <memory>
#include <string>
#include <vector>

namespace lcpbench_app {

struct Batch {
  std::string family;
  suite::lcp::GeneratorParams gp;
  long long count = 0;
  std::vector<std::string> files;
  std::vector<suite::lcp::Problem> file_problems; // family "file": every rank holds them (read up front)
  std::vector<std::string> file_errors;           // "" or the reason a file is invalid
  std::vector<std::unique_ptr<suite::lcp::Solver>> solvers;
  std::vector<std::string> solver_names;
  suite::lcp::SolverOptions opt;
  double delay = 0.0; // testing: seconds of sleep after each problem

  bool fromFiles() const { return family == "file"; }
  int recordLength() const { return 2 + static_cast<int>(solvers.size()) * kFields; } // index, n, fields
};

// Collective: builds the batch of validated options (files are read here; a malformed HDF5 file is an
// error for the whole job, any other invalid file is recorded in file_errors).
PetscErrorCode makeBatch(MPI_Comm comm, const Options& o, Batch* b);

// Solves problem k with every solver: rec gets k, n and then kFields values per solver; *err the
// validation message ("" if valid).
void solveOne(const Batch& b, long long k, double* rec, std::string* err);

} // namespace lcpbench_app
