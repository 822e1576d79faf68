// Matrix Market coordinate reader; see matrix_market.hpp. Errors name the file and the line.
#include "fem/matrix_market.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace suite::fem {

PetscErrorCode readMatrixMarket(MPI_Comm comm, const std::string& path, SymCsc* A, MatrixMarketInfo* info) {
  PetscFunctionBeginUser;
  std::ifstream in(path);
  PetscCheck(in, comm, PETSC_ERR_FILE_OPEN, "Matrix %s: cannot open (option -matrix)", path.c_str());
  std::string line, banner, object, format;
  PetscCheck(std::getline(in, line), comm, PETSC_ERR_FILE_UNEXPECTED, "Matrix %s: empty file", path.c_str());
  {
    std::istringstream s(line);
    s >> banner >> object >> format >> info->field >> info->symmetry;
    for (auto* w : {&object, &format, &info->field, &info->symmetry})
      std::transform(w->begin(), w->end(), w->begin(), ::tolower);
  }
  PetscCheck(banner == "%%MatrixMarket" && object == "matrix" && format == "coordinate", comm,
             PETSC_ERR_FILE_UNEXPECTED, "Matrix %s line 1: not a Matrix Market coordinate matrix ('%s')",
             path.c_str(), line.c_str());
  PetscCheck(info->field == "real" || info->field == "integer" || info->field == "pattern", comm,
             PETSC_ERR_FILE_UNEXPECTED, "Matrix %s: field '%s' not supported (real|integer|pattern)",
             path.c_str(), info->field.c_str());
  PetscCheck(info->symmetry == "symmetric" || info->symmetry == "general", comm, PETSC_ERR_FILE_UNEXPECTED,
             "Matrix %s: symmetry '%s' not supported (symmetric|general)", path.c_str(),
             info->symmetry.c_str());
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line[0] != '%') break;
  }
  {
    std::istringstream s(line);
    PetscCheck((s >> info->rows >> info->cols >> info->entries) && info->rows > 0 &&
                   info->rows == info->cols && info->entries >= 0,
               comm, PETSC_ERR_FILE_UNEXPECTED,
               "Matrix %s line %d: bad size line '%s' (need a square matrix)", path.c_str(), lineno,
               line.c_str());
  }
  const int n = static_cast<int>(info->rows);
  const bool pattern = info->field == "pattern";
  std::vector<std::map<int, double>> cols(n);
  for (int c = 0; c < n; ++c) cols[c][c] = 0.0; // structural diagonal
  for (long long k = 0; k < info->entries; ++k) {
    PetscCheck(std::getline(in, line), comm, PETSC_ERR_FILE_UNEXPECTED,
               "Matrix %s: truncated after line %d (%lld of %lld entries)", path.c_str(), lineno, k,
               info->entries);
    ++lineno;
    std::istringstream s(line);
    long long i, j;
    double v = 1.0;
    PetscCheck((s >> i >> j) && (pattern || (s >> v)), comm, PETSC_ERR_FILE_UNEXPECTED,
               "Matrix %s line %d: malformed entry '%s'", path.c_str(), lineno, line.c_str());
    PetscCheck(i >= 1 && i <= n && j >= 1 && j <= n, comm, PETSC_ERR_FILE_UNEXPECTED,
               "Matrix %s line %d: index (%lld, %lld) outside 1..%d", path.c_str(), lineno, i, j, n);
    const int r = static_cast<int>(std::min(i, j)) - 1, c = static_cast<int>(std::max(i, j)) - 1;
    if (info->symmetry == "general" && i > j) {
      cols[c].emplace(r, 0.0); // pattern of A^T; keep the upper value if given
    } else {
      cols[c][r] = v;
    }
  }
  *A = SymCsc();
  A->n = n;
  A->colptr.assign(n + 1, 0);
  for (int c = 0; c < n; ++c) {
    for (const auto& [r, v] : cols[c]) A->rowind.push_back(r), A->val.push_back(v);
    A->colptr[c + 1] = static_cast<int>(A->rowind.size());
  }
  PetscFunctionReturn(0);
}

} // namespace suite::fem
