// Fuzz target of the contact library's MJCF reader (suite::contact::parseMjcf, MPI- and PETSc-free): any input
// must either parse or be rejected with an exception, never crash, hang or leak; a model that parses must also
// survive writeMjcf -> parseMjcf (the writer may refuse it with SceneError, the reader of its output may not).
#include "contact/mjcf.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  suite::contact::Model m;
  try {
    m = suite::contact::parseMjcf(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const std::exception&) {
    return 0; // rejection is fine
  }
  std::string xml;
  try {
    xml = suite::contact::writeMjcf(m, "fuzz");
  } catch (const suite::contact::SceneError&) {
    return 0; // what MJCF cannot express
  }
  try {
    suite::contact::parseMjcf(xml, "written");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_mjcf: the written model does not parse back: %s\n%s\n", e.what(), xml.c_str());
    std::abort();
  }
  return 0;
}
