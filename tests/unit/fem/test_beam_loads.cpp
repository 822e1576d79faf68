// Beam loads (fem/beam_loads.hpp) and the -mesh choice (fem::makeMesh): the tip traction sums to the total
// force, gravity to rho g times the volume, the tip mean, and the errors naming -tip_load and -mesh_file.
#include "fem/beam_loads.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

using namespace suite::fem;

namespace {
const Lame kLame{576.9230769230769, 384.6153846153846}; // E = 1000, nu = 0.3

BeamSpec beam(int ny) {
  BeamSpec s;
  s.length = 4;
  s.size = {1.0, 2.0};
  s.cells = {4, ny, 2};
  return s;
}

// Sum of the load's component c over the free DOFs.
double total(const std::vector<double>& f, int c) {
  double s = 0;
  for (size_t i = c; i < f.size(); i += 3) s += f[i];
  return s;
}
} // namespace

TEST(FemBeamLoads, TipTractionAndGravityTotals) {
  for (int order : {1, 2}) {
    TetMesh m;
    ASSERT_EQ(makeMesh(PETSC_COMM_SELF, "beam", beam(1), "", order, &m), 0);
    EXPECT_EQ(m.order(), order);
    auto mat = makeLinearMaterial(kLame);
    ElasticModel model; // nothing fixed: every DOF free, so the loads' totals are the forces' totals
    ASSERT_EQ(model.setup(PETSC_COMM_SELF, m, *mat, std::vector<char>(3 * m.numNodes(), 0)), 0);
    std::vector<double> f;
    ASSERT_EQ(tipTractionLoad(PETSC_COMM_SELF, model, 3.0, &f), 0);
    EXPECT_NEAR(total(f, 1), -3.0, 1e-12) << "P" << order;
    EXPECT_NEAR(total(f, 0), 0.0, 1e-14);
    const double g[3] = {0, -2, 0.5};
    addGravityLoad(model, 1.5, g, &f); // volume 8: rho g V = (0, -24, 6)
    EXPECT_NEAR(total(f, 1), -3.0 - 24.0, 1e-11) << "P" << order;
    EXPECT_NEAR(total(f, 2), 6.0, 1e-11) << "P" << order;
    ASSERT_EQ(tipTractionLoad(PETSC_COMM_SELF, model, 0.0, &f), 0); // no tip load: zero
    EXPECT_EQ(f, std::vector<double>(model.numFree(), 0.0));
    const double none[3] = {0, 0, 0};
    addGravityLoad(model, 1.5, none, &f);
    EXPECT_EQ(f, std::vector<double>(model.numFree(), 0.0));
  }
}

TEST(FemBeamLoads, TipNodesAndMean) {
  const TetMesh m = makeBeam(beam(1));
  const auto tip = tipNodes(m);
  ASSERT_EQ(tip.size(), 2u * 3u); // (1 + 1) x (2 + 1) nodes on x = 4
  std::vector<double> u(3 * m.numNodes(), 0.0);
  for (int v : tip) u[3 * v + 1] = -0.5, u[3 * v] = 0.25;
  EXPECT_DOUBLE_EQ(nodalMean(u, tip, 1, -1), 0.5);
  EXPECT_DOUBLE_EQ(nodalMean(u, tip, 0), 0.25);
  EXPECT_EQ(nodalMean(u, {}, 0), 0.0);
}

TEST(FemBeamLoads, Errors) {
  femtest::QuietErrors quiet;
  TetMesh m;
  EXPECT_NE(makeMesh(PETSC_COMM_SELF, "file", beam(1), "", 1, &m), 0); // -mesh file needs -mesh_file
  EXPECT_NE(makeMesh(PETSC_COMM_SELF, "file", beam(1), "no_such_mesh.msh", 1, &m), 0);
  ASSERT_EQ(makeMesh(PETSC_COMM_SELF, "beam", beam(1), "", 1, &m), 0);
  // Nodes on x = max but no boundary face there: a single tet with one corner at the far end.
  TetMesh tet;
  tet.nodes = {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  tet.elems = {0, 1, 2, 3};
  auto mat = makeLinearMaterial(kLame);
  ElasticModel model;
  ASSERT_EQ(model.setup(PETSC_COMM_SELF, tet, *mat, std::vector<char>(12, 0)), 0);
  std::vector<double> f;
  EXPECT_NE(tipTractionLoad(PETSC_COMM_SELF, model, 1.0, &f), 0);
}
