// Rank-0 logging.
#include "core/log.hpp"

#include <cstdarg>
#include <cstdio>

namespace suite {

PetscErrorCode logInfo(MPI_Comm comm, bool quiet, const char* fmt, ...) {
  PetscFunctionBeginUser;
  if (quiet) PetscFunctionReturn(0);
  char buf[4096];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  PetscCall(PetscPrintf(comm, "%s\n", buf));
  PetscFunctionReturn(0);
}

} // namespace suite
