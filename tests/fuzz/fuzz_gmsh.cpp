// Fuzz target: the Gmsh .msh parser (lib/fem/mesh_parse.hpp) on arbitrary bytes. Rejection (ParseError) is
// fine; crashes, hangs, leaks and unbounded allocations are bugs. Seeds: corpus/gmsh/.
#include "fem/mesh_parse.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    suite::fem::parseGmsh(std::string(reinterpret_cast<const char*>(data), size), "fuzz.msh");
  } catch (const std::exception&) {
  }
  return 0;
}
