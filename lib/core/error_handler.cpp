// Error reporting policy of the suite (see error_handler.hpp).
#include "core/error_handler.hpp"

#include <cstdio>

namespace suite {
namespace {

PetscErrorCode suiteErrorHandler(MPI_Comm comm, int line, const char* fun, const char* file, PetscErrorCode n,
                                 PetscErrorType p, const char* mess, void*) {
  if (p != PETSC_ERROR_INITIAL) return n; // traceback levels: the first report said it all
  const char* text = mess;
  if (!text || !text[0]) PetscErrorMessage(n, &text, nullptr);
  int world = 1, csize = 1, crank = 0, wrank = 0, mpi_up = 0;
  MPI_Initialized(&mpi_up);
  if (mpi_up && PETSC_COMM_WORLD != MPI_COMM_NULL) {
    MPI_Comm_size(PETSC_COMM_WORLD, &world);
    MPI_Comm_rank(PETSC_COMM_WORLD, &wrank);
  }
  if (mpi_up && comm != MPI_COMM_NULL) {
    MPI_Comm_size(comm, &csize);
    MPI_Comm_rank(comm, &crank);
  }
  const bool collective = (csize == world);
  if (collective && crank != 0) return n;
  if (!PetscInitializeCalled) // still inside PetscInitialize: the command line or an -options_file is at
                              // fault
    std::fprintf(stderr,
                 "ERROR: %s (while reading the command line and -options_file)\n       (in %s() at %s:%d)\n",
                 text ? text : "unknown error", fun, file, line);
  else if (collective)
    std::fprintf(stderr, "ERROR: %s\n       (in %s() at %s:%d)\n", text ? text : "unknown error", fun, file,
                 line);
  else
    std::fprintf(stderr, "ERROR on rank %d: %s\n       (in %s() at %s:%d)\n", wrank,
                 text ? text : "unknown error", fun, file, line);
  std::fflush(stderr);
  if (!collective && world > 1) MPI_Abort(PETSC_COMM_WORLD, n ? n : 1);
  return n;
}

} // namespace

PetscErrorCode pushSuiteErrorHandler() {
  return PetscPushErrorHandler(suiteErrorHandler, nullptr);
}

PetscErrorCode agreeOnFailure(MPI_Comm comm, std::string* message) {
  int rank = 0, size = 1;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  int root = message->empty() ? size : rank;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &root, 1, MPI_INT, MPI_MIN, comm));
  if (root == size) PetscFunctionReturn(0);
  int len = (int)message->size();
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, root, comm));
  message->resize(len);
  PetscCallMPI(MPI_Bcast(message->data(), len, MPI_CHAR, root, comm));
  PetscFunctionReturn(0);
}

} // namespace suite
