// Small helpers shared by the parts of lcpbench: comma lists, exact number text, and rank 0's errors made
// collective (rank 0 alone touches the results file; every rank then takes the same PetscCheck).
#pragma once

#include <petscsys.h>

#include <exception>
#include <string>
#include <vector>

namespace lcpbench_app {

// "a,b,,c" -> {a, b, c} (empty items dropped).
std::vector<std::string> split(const std::string& s);
// {a, b} -> "a, b".
std::string join(const std::vector<std::string>& v);
// The shortest text that reads back as exactly v (%.17g).
std::string num(double v);

// Rank 0's error message (or "") broadcast to every rank.
PetscErrorCode bcastError(MPI_Comm comm, std::string* err);

// Runs f() on rank 0 only and returns the message of what it threw ("" if nothing or another rank).
template <class F> std::string rank0Try(int rank, F&& f) {
  if (rank != 0) return "";
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

} // namespace lcpbench_app
