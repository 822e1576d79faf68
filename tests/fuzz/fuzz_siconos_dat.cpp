// Fuzz target: the Siconos numerics .dat parser (lib/lcp/readers.hpp parseSiconos) used by lcpbench -file.
// Each input is parsed as an LCP, a relay (box LCP) and an MLCP file (the kind follows the file name).
// Rejection (std::runtime_error) is fine; crashes, hangs, leaks and allocations beyond the input size are
// bugs (a header announcing more numbers than the text holds is refused before allocating). Seeds:
// corpus/siconos_dat/ (hand-written small files and broken variants).
#include "lcp/readers.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* name : {"lcp_fuzz.dat", "relay_fuzz.dat", "fuzz_mlcp.dat"}) {
    try {
      const suite::lcp::Problem p = suite::lcp::parseSiconos(text, name);
      (void)suite::lcp::validate(p);
    } catch (const std::exception&) {
    }
  }
  return 0;
}
