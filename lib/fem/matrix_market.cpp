// Matrix Market file reader: reads the file, parses it with parseMatrixMarket (mesh_parse.cpp); errors name the
// file and the line.
#include "fem/matrix_market.hpp"

#include <fstream>
#include <sstream>

namespace suite::fem {

PetscErrorCode readMatrixMarket(MPI_Comm comm, const std::string& path, SymCsc* A, MatrixMarketInfo* info) {
  PetscFunctionBeginUser;
  std::ifstream in(path, std::ios::binary);
  PetscCheck(in, comm, PETSC_ERR_FILE_OPEN, "Matrix %s: cannot open (option -matrix)", path.c_str());
  std::ostringstream s;
  s << in.rdbuf();
  std::string error;
  try {
    *A = parseMatrixMarket(s.str(), path, info);
  } catch (const ParseError& e) {
    error = e.what();
  }
  PetscCheck(error.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "Matrix %s", error.c_str());
  PetscFunctionReturn(0);
}

} // namespace suite::fem
