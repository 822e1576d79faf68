// Mesh generator, P2 promotion, boundary faces and the TetGen/Gmsh readers (including bad input).
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace suite::fem;

TEST(FemMesh, BeamVolumeAndCounts) {
  BeamSpec s;
  s.length = 10;
  s.size = {1.0, 2.0};
  s.cells = {5, 2, 3};
  const TetMesh m = makeBeam(s);
  EXPECT_EQ(m.numNodes(), 6 * 3 * 4);
  EXPECT_EQ(m.numElems(), 6 * 5 * 2 * 3);
  double vol = 0;
  for (int e = 0; e < m.numElems(); ++e) {
    const int* t = m.elem(e);
    const double v = tetSignedVolume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]);
    EXPECT_GT(v, 0);
    vol += v;
  }
  EXPECT_NEAR(vol, 20.0, 1e-12);
  EXPECT_EQ(checkMesh(PETSC_COMM_SELF, m, "beam"), 0);
}

TEST(FemMesh, P2NodesAndFaces) {
  const TetMesh p1 = femtest::cube(2);
  const TetMesh p2 = promoteToP2(p1);
  EXPECT_EQ(p2.numNodes(), 5 * 5 * 5); // a 2x2x2-cell P2 mesh has the nodes of a 4x4x4 grid
  for (int axis = 0; axis < 3; ++axis) {
    double area = 0;
    for (const auto& f : facesOnPlane(p2, axis, 1.0)) {
      ASSERT_EQ(f.size(), 6u);
      const auto &a = p2.nodes[f[0]], &b = p2.nodes[f[1]], &c = p2.nodes[f[2]];
      const Eigen::Vector3d u(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
          v(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
      area += 0.5 * u.cross(v).norm();
      for (int k = 3; k < 6; ++k) EXPECT_NEAR(p2.nodes[f[k]][axis], 1.0, 1e-14);
    }
    EXPECT_NEAR(area, 1.0, 1e-12);
    EXPECT_EQ(nodesOnPlane(p2, axis, 0.0).size(), 25u);
  }
}

namespace {
void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}
const char* kNode = "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n";
} // namespace

TEST(FemMesh, TetGenReader) {
  writeFile("tg_ok.node", kNode);
  writeFile("tg_ok.ele", "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n");
  TetMesh m;
  ASSERT_EQ(readTetGen(PETSC_COMM_SELF, "tg_ok", &m), 0); // both tets positively oriented (6V = 1 and 2)
  EXPECT_EQ(m.numNodes(), 5);
  EXPECT_EQ(m.numElems(), 2);
  femtest::QuietErrors quiet;
  writeFile("tg_trunc.node", kNode);
  writeFile("tg_trunc.ele", "2 4 0\n0 0 1 2 3\n1 1 3\n");
  EXPECT_NE(readTetGen(PETSC_COMM_SELF, "tg_trunc", &m), 0);
  writeFile("tg_bad.node", "5 3 0 0\n0 0 0 x\n");
  writeFile("tg_bad.ele", "1 4 0\n0 0 1 2 3\n");
  EXPECT_NE(readTetGen(PETSC_COMM_SELF, "tg_bad", &m), 0);
  writeFile("tg_inv.node", kNode);
  writeFile("tg_inv.ele", "1 4 0\n0 0 2 1 3\n"); // inverted
  EXPECT_NE(readTetGen(PETSC_COMM_SELF, "tg_inv", &m), 0);
}

TEST(FemMesh, GmshReaders) {
  writeFile("g22.msh",
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
            "$Elements\n2\n1 2 2 0 1 1 2 3\n2 4 2 0 1 1 2 3 4\n$EndElements\n");
  writeFile("g41.msh",
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n"
            "0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n");
  TetMesh m;
  ASSERT_EQ(readGmsh(PETSC_COMM_SELF, "g22.msh", &m), 0);
  EXPECT_EQ(m.numElems(), 1);
  EXPECT_EQ(m.numNodes(), 4);
  ASSERT_EQ(readGmsh(PETSC_COMM_SELF, "g41.msh", &m), 0);
  EXPECT_EQ(m.numElems(), 1);
  femtest::QuietErrors quiet;
  writeFile("gtrunc.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n");
  EXPECT_NE(readGmsh(PETSC_COMM_SELF, "gtrunc.msh", &m), 0);
}
