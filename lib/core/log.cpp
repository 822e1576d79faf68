// Rank-0 logging.
#include "core/log.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace suite {

// The line is formatted at its full length (a first pass measures it), never cut at a buffer's size.
PetscErrorCode logInfo(MPI_Comm comm, bool quiet, const char* fmt, ...) {
  PetscFunctionBeginUser;
  if (quiet) PetscFunctionReturn(0);
  va_list ap, again;
  va_start(ap, fmt);
  va_copy(again, ap);
  const int n = std::vsnprintf(nullptr, 0, fmt, ap);
  va_end(ap);
  std::vector<char> buf(n > 0 ? (size_t)n + 1 : 1, '\0');
  if (n > 0) std::vsnprintf(buf.data(), buf.size(), fmt, again);
  va_end(again);
  PetscCall(PetscPrintf(comm, "%s\n", buf.data()));
  PetscFunctionReturn(0);
}

} // namespace suite
