// Fuzz target: the Matrix Market coordinate parser (lib/fem/mesh_parse.hpp) used by `reorder`. Rejection
// (ParseError) is fine; crashes, hangs, leaks and unbounded allocations are bugs. Seeds:
// corpus/matrix_market/.
#include "fem/mesh_parse.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    suite::fem::MatrixMarketInfo info;
    suite::fem::parseMatrixMarket(std::string(reinterpret_cast<const char*>(data), size), "fuzz.mtx", &info);
  } catch (const std::exception&) {
  }
  return 0;
}
