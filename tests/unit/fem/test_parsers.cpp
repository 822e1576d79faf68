// MPI-free parsers (lib/fem/mesh_parse.hpp): valid inputs give the expected meshes/matrices; malformed,
// truncated and hostile inputs throw ParseError with a message naming the problem (no allocation of the
// claimed sizes).
#include "fem/mesh_parse.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace suite::fem;

namespace {
std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}
const char* kNode10 =
    "10 3 0 0\n1 0 0 0\n2 2 0 0\n3 0 2 0\n4 0 0 2\n5 1 1 0\n6 0 1 1\n7 1 0 0\n8 0 1 0\n9 0 0 1\n"
    "10 1 0 1\n";
} // namespace

TEST(FemParsers, TetGenTenNodeEdgesMatchedByPosition) {
  // Midside nodes given in the order 01(7), 12(5), 02(8), 03(9), 13(10), 23(6), shuffled in the file.
  const TetMesh m = parseTetGen(kNode10, "1 10 0\n1 1 2 3 4 6 10 9 8 5 7\n", "t");
  ASSERT_EQ(m.nodes_per_elem, 10);
  const int expect[10] = {0, 1, 2, 3, 6, 4, 7, 8, 9, 5}; // VTK order 01,12,02,03,13,23 (0-based)
  for (int a = 0; a < 10; ++a) EXPECT_EQ(m.elem(0)[a], expect[a]) << a;
}

TEST(FemParsers, HostileCountsAreRejectedBeforeAllocation) {
  EXPECT_NE(errorOf([] {
              parseTetGen("100000000000 3 0 0\n1 0 0 0\n", "1 4 0\n1 1 2 3 4\n", "h");
            }).find("cannot fit in the rest of the file"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseGmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n999999999999\n1 0 0 0\n", "h.msh");
            }).find("cannot fit"),
            std::string::npos);
  MatrixMarketInfo info;
  EXPECT_NE(errorOf([&] {
              parseMatrixMarket(
                  "%%MatrixMarket matrix coordinate real general\n2000000000 2000000000 1000000000000\n",
                  "h.mtx", &info);
            }).find("more than a"),
            std::string::npos);
}

TEST(FemParsers, MalformedAndTruncatedInput) {
  EXPECT_NE(errorOf([] {
              parseTetGen("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 x\n4 0 0 1\n", "1 4 0\n1 1 2 3 4\n", "b");
            }).find("b.node line 4: malformed coordinate 'x'"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseGmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n", "t.msh");
            }).find("truncated file"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseGmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n1 1 1 1\n$EndNodes\n",
                        "d.msh");
            }).find("duplicate node tag 1"),
            std::string::npos);
  MatrixMarketInfo info;
  EXPECT_NE(errorOf([&] {
              parseMatrixMarket("%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 nan\n2 2 1\n",
                                "n.mtx", &info);
            }).find("n.mtx line 3: malformed entry"),
            std::string::npos);
}

TEST(FemParsers, MatrixMarketSymmetrisedUpperTriangle) {
  MatrixMarketInfo info;
  const SymCsc A = parseMatrixMarket(
      "%%MatrixMarket matrix coordinate real general\n3 3 3\n2 1 5\n1 3 7\n3 1 9\n", "g.mtx", &info);
  // Upper pattern of A + A^T with the diagonal: (0,0) (0,1) (1,1) (0,2) (2,2); values of upper entries only.
  EXPECT_EQ(A.n, 3);
  EXPECT_EQ(A.colptr, (std::vector<int>{0, 1, 3, 5}));
  EXPECT_EQ(A.rowind, (std::vector<int>{0, 0, 1, 0, 2}));
  EXPECT_EQ(A.val[1], 0.0); // (2,1) was a lower entry: pattern only
  EXPECT_EQ(A.val[3], 7.0); // (1,3) upper value kept over the lower (3,1)
}
