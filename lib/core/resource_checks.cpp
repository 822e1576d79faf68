// Option range and memory estimate checks (see resource_checks.hpp).
#include "core/resource_checks.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>

namespace suite {

PetscErrorCode checkIntOptionRange(MPI_Comm comm, const char* name, long long lo) {
  char text[256] = "";
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, name, text, sizeof text, &set));
  if (!set) PetscFunctionReturn(0);
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text, &end, 10);
  const bool ok = errno == 0 && end != text && *end == '\0' && v >= lo && v <= (long long)PETSC_MAX_INT;
  PetscCheck(ok, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: must be an integer in [%lld, %lld] (PetscInt is %d-bit)", name, text, lo,
             (long long)PETSC_MAX_INT, (int)(8 * sizeof(PetscInt)));
  PetscFunctionReturn(0);
}

PetscErrorCode checkChoice(MPI_Comm comm, const char* name, const char* value, const char* const* choices,
                           int n, PetscInt* index) {
  std::string list;
  PetscFunctionBeginUser;
  *index = -1;
  for (int i = 0; i < n; ++i) {
    if (!std::strcmp(value, choices[i])) *index = i;
    list += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(choices[i]);
  }
  PetscCheck(*index >= 0, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown %s '%s': %s", name, value, list.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode checkMemoryEstimate(MPI_Comm comm, double bytes_this_rank, const char* what) {
  MPI_Comm node;
  double need = bytes_this_rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &need, 1, MPI_DOUBLE, MPI_SUM, node));
  PetscCallMPI(MPI_Comm_free(&node));
  const double have = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
  int over = have > 0 && need > 0.9 * have;
  double worst = over ? need : 0.0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(
      worst == 0.0, comm, PETSC_ERR_MEM,
      "%s needs about %.3g GiB on one node, more than 90%% of its %.3g GiB of memory: use more nodes or a "
      "smaller problem",
      what, worst / 1073741824.0, have / 1073741824.0);
  PetscFunctionReturn(0);
}

} // namespace suite
