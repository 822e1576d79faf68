// Helpers shared by the parts of lcpbench (see lcpbench_util.hpp).
#include "lcpbench_util.hpp"

#include <cstdio>
#include <sstream>

namespace lcpbench_app {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

PetscErrorCode bcastError(MPI_Comm comm, std::string* err) {
  PetscFunctionBeginUser;
  int len = static_cast<int>(err->size());
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  err->resize(len);
  if (len > 0) PetscCallMPI(MPI_Bcast(err->data(), len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

} // namespace lcpbench_app
