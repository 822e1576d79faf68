// Fuzz target: the suite's HDF5 LCP problem files (lib/lcp/reader_hdf5.cpp), read by the production reader
// on PETSC_COMM_SELF from a temporary file holding the input. A corrupted or hostile file must give an error
// code (and then validate() must accept or refuse the problem), never a crash or a hang.
#include "lcp/readers.hpp"

#include <petscsys.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = [] {
    PetscInitializeNoArguments();
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); // errors are expected: no messages
    return "fuzz_lcp_h5_" + std::to_string(getpid()) + ".h5";
  }();
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  } else {
    return 0;
  }
  suite::lcp::Problem p;
  if (suite::lcp::readProblemH5(PETSC_COMM_SELF, path, &p) == 0) (void)suite::lcp::validate(p);
  std::remove(path.c_str());
  return 0;
}
