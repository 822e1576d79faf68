// Matrix Market coordinate reader (Boisvert, Pozo & Remington, "The Matrix Market exchange formats", NIST
// 1996): real/integer/pattern, symmetric/general; the result is the upper triangle of the symmetrised pattern
// A + A^T (values of the upper entries where given, diagonal added), which is what the orderings and solvers
// use.
#pragma once

#include "fem/sparse.hpp"

#include <petscsys.h>

#include <string>

namespace suite::fem {

struct MatrixMarketInfo {
  std::string field, symmetry; // e.g. "pattern", "symmetric"
  long long rows = 0, cols = 0, entries = 0;
};

PetscErrorCode readMatrixMarket(MPI_Comm comm, const std::string& path, SymCsc* A, MatrixMarketInfo* info);

} // namespace suite::fem
