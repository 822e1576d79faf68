// Fuzz target of the contact app's scene-file parser (suite::contact::parseScene, MPI- and PETSc-free):
// any input must either parse or be rejected with an exception, never crash, hang or leak.
#include "contact/scenes.hpp"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    suite::contact::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const std::exception&) {
  } // rejection is fine
  return 0;
}
