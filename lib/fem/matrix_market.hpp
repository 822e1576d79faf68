// Matrix Market coordinate reader (Boisvert, Pozo & Remington, "The Matrix Market exchange formats", NIST
// 1996): real/integer/pattern, symmetric/general; the result is the upper triangle of the symmetrised pattern
// A + A^T (values of the upper entries where given, diagonal added), which is what the orderings and solvers
// use. The parsing is parseMatrixMarket (mesh_parse.hpp, MPI-free, fuzzed); this wrapper reads the file.
#pragma once

#include "fem/mesh_parse.hpp"
#include "fem/sparse.hpp"

#include <petscsys.h>

#include <string>

namespace suite::fem {

PetscErrorCode readMatrixMarket(MPI_Comm comm, const std::string& path, SymCsc* A, MatrixMarketInfo* info);

} // namespace suite::fem
