// MPI-free, PETSc-free parsers of the files users write for the FEM apps: they take the file CONTENT and
// throw ParseError with a message naming the file and line on malformed, truncated or hostile input (counts
// larger than the content could hold are rejected before anything is allocated). The apps' readers
// (readGmsh, readTetGen, readMatrixMarket) read the files and turn a ParseError into one collective error.
// Fuzz targets: tests/fuzz/fuzz_gmsh.cpp, fuzz_tetgen.cpp, fuzz_matrix_market.cpp.
#pragma once

#include "fem/mesh.hpp"
#include "fem/sparse.hpp"

#include <stdexcept>
#include <string>

namespace suite::fem {

struct ParseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Gmsh .msh ASCII 2.2 or 4.1; only tetrahedra (types 4 and 11) are kept. `name` appears in messages.
TetMesh parseGmsh(const std::string& content, const std::string& name);

// TetGen <base>.node and <base>.ele contents; 4-node (P1) or 10-node (P2, TetGen -o2) tetrahedra. The six
// extra nodes of a 10-node tet are matched to the edges by position (each must be the midpoint of one edge of
// its tet), so the file's edge order does not matter; the result uses the VTK edge order of TetMesh.
TetMesh parseTetGen(const std::string& node_content, const std::string& ele_content, const std::string& base);

struct MatrixMarketInfo {
  std::string field, symmetry; // e.g. "pattern", "symmetric"
  long long rows = 0, cols = 0, entries = 0;
};
// Matrix Market coordinate matrix -> upper triangle of the symmetrised pattern A + A^T with the diagonal.
SymCsc parseMatrixMarket(const std::string& content, const std::string& name, MatrixMarketInfo* info);

} // namespace suite::fem
