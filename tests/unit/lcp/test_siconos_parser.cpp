// parseSiconos on hostile headers: a size announcing more numbers than the text holds is refused as truncated
// before anything of that size is allocated (the fuzz target relies on it); a valid relay file parses.
#include "lcp/readers.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace suite::lcp;

namespace {

void expectTruncated(const std::string& text, const std::string& name) {
  try {
    parseSiconos(text, name);
    FAIL() << "accepted: " << text;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated file"), std::string::npos) << e.what();
  }
}

TEST(SiconosParser, HostileSizesRefusedBeforeAllocation) {
  // 2^20 x 2^20 dense M would be 8 TiB
  expectTruncated("1048576 0 1048576 1048576 1048576 1048576 1 2 3", "lcp_hostile.dat");
  expectTruncated("0 1 1048575 1048575 1 2 3", "hostile_mlcp.dat");
  expectTruncated("3 0 3 3 3 3 4 1 0 1 4 1 0 1 4 -1 2", "lcp_short_q.dat");
}

TEST(SiconosParser, RelayFileParses) {
  const Problem p = parseSiconos("2 0 2 2 2 2 2 1 1 2 -1 3 -1 -1 1 1", "relay_small.dat");
  ASSERT_EQ(p.size(), 2);
  EXPECT_EQ(p.kind, Kind::Box);
  EXPECT_EQ(p.M(1, 0), 1.0);
  EXPECT_EQ(p.q[1], 3.0);
  EXPECT_EQ(p.l[0], -1.0);
  EXPECT_EQ(p.u[1], 1.0);
  EXPECT_EQ(validate(p), "");
}

} // namespace
