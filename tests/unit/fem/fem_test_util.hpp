// Helpers shared by the lib/fem unit tests.
#pragma once

#include "fem/assembly.hpp"
#include "fem/mesh.hpp"

#include <petscsys.h>

#include <cmath>
#include <vector>

namespace femtest {

// Silences PETSc's traceback printing for tests that expect an error code.
struct QuietErrors {
  QuietErrors() { PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); }
  ~QuietErrors() { PetscPopErrorHandler(); }
};

inline suite::fem::TetMesh cube(int n, int order = 1) {
  suite::fem::BeamSpec s;
  s.length = 1.0;
  s.size = {1.0, 1.0};
  s.cells = {n, n, n};
  auto m = suite::fem::makeBeam(s);
  return order == 2 ? suite::fem::promoteToP2(m) : m;
}

// Flags of nodes on the bounding box of the unit cube.
inline std::vector<char> boundaryNodes(const suite::fem::TetMesh& m) {
  std::vector<char> b(m.numNodes(), 0);
  for (int v = 0; v < m.numNodes(); ++v)
    for (int i = 0; i < 3; ++i)
      if (std::abs(m.nodes[v][i]) < 1e-12 || std::abs(m.nodes[v][i] - 1.0) < 1e-12) b[v] = 1;
  return b;
}

} // namespace femtest
