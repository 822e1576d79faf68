// Fuzz target: the TetGen .node/.ele parser (lib/fem/mesh_parse.hpp). One input holds both files: the .node
// content, a line "%%ELE%%", then the .ele content (without the separator the whole input is the .node file
// and the .ele file is empty). Rejection (ParseError) is fine; crashes, hangs, leaks are bugs. Seeds:
// corpus/tetgen/.
#include "fem/mesh_parse.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  const std::string sep = "\n%%ELE%%\n";
  const size_t k = in.find(sep);
  const std::string node = k == std::string::npos ? in : in.substr(0, k);
  const std::string ele = k == std::string::npos ? std::string() : in.substr(k + sep.size());
  try {
    suite::fem::parseTetGen(node, ele, "fuzz");
  } catch (const std::exception&) {
  }
  return 0;
}
