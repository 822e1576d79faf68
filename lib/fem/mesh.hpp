// Tetrahedral meshes: storage, the structured beam/box generator (6 tetrahedra per hexahedron,
// Kuhn/Freudenthal split along the main diagonal; H. W. Kuhn 1960, H. Freudenthal 1942), P1 -> P2 promotion,
// boundary sets.
#pragma once

#include "core/named_choice.hpp"

#include <petscsys.h>

#include <array>
#include <string>
#include <vector>

namespace suite::fem {

// Nodes (x,y,z per node) and elements (4 nodes for P1, 10 for P2; P2 edge order 01,12,02,03,13,23 as in
// Gmsh/VTK).
struct TetMesh {
  std::vector<std::array<double, 3>> nodes;
  std::vector<int> elems; // nodes_per_elem ints per element
  int nodes_per_elem = 4;
  int order() const { return nodes_per_elem == 10 ? 2 : 1; }
  int numNodes() const { return static_cast<int>(nodes.size()); }
  int numElems() const { return nodes_per_elem ? static_cast<int>(elems.size()) / nodes_per_elem : 0; }
  const int* elem(int e) const { return elems.data() + static_cast<size_t>(e) * nodes_per_elem; }
};

struct BeamSpec {
  double length = 10.0;                    // along x
  std::array<double, 2> size = {1.0, 1.0}; // y and z extents
  std::array<int, 3> cells = {10, 1, 1};   // hexahedra along x, y, z
};

// Structured box [0,L]x[0,sy]x[0,sz], 6 positively oriented tets per hex; nodes numbered x fastest.
TetMesh makeBeam(const BeamSpec& spec);
// Adds a midside node on every edge (straight-sided P2).
TetMesh promoteToP2(const TetMesh& p1);

// Signed volume of the straight tetrahedron (corner nodes a,b,c,d): det[b-a, c-a, d-a] / 6.
double tetSignedVolume(const std::array<double, 3>& a, const std::array<double, 3>& b,
                       const std::array<double, 3>& c, const std::array<double, 3>& d);
// Errors (naming the element and its volume) if any element has non-positive volume, a node index out of
// range, or a repeated node.
PetscErrorCode checkMesh(MPI_Comm comm, const TetMesh& mesh, const char* source);

// Nodes with |x[axis] - value| <= tol * (bounding-box diagonal).
std::vector<int> nodesOnPlane(const TetMesh& mesh, int axis, double value, double tol = 1e-9);
// Boundary faces (corner node triples, plus the 3 edge nodes for P2: 0,1,2, 01,12,02) whose nodes lie on the
// plane.
std::vector<std::vector<int>> facesOnPlane(const TetMesh& mesh, int axis, double value, double tol = 1e-9);
// Area of boundary faces (of their corner triangles).
double facesArea(const TetMesh& mesh, const std::vector<std::vector<int>>& faces);
// A clamped plane "x=0" / "y=1.5" / "z=-2" or "none" (option `option`): fixed[3 v + c] = 1 for every DOF c of
// the nodes on it (fixed: 3 per node). Collective error on a malformed plane.
PetscErrorCode clampPlane(MPI_Comm comm, const char* option, const std::string& plane, const TetMesh& mesh,
                          std::vector<char>* fixed);
// Flat node coordinates (x,y,z per node) and the 4 corner nodes of each element (HDF5/XDMF output).
std::vector<double> flatCoordinates(const TetMesh& mesh);
std::vector<int> cornerNodes(const TetMesh& mesh);
// Node adjacency graph (CSR, no self loops, sorted): nodes sharing an element.
void nodeGraph(const TetMesh& mesh, std::vector<int>* xadj, std::vector<int>* adj);

// Readers: clear error naming the file and line on malformed or truncated input, or an inverted element.
PetscErrorCode readTetGen(MPI_Comm comm, const std::string& basename,
                          TetMesh* mesh);                                       // <base>.node + <base>.ele
PetscErrorCode readGmsh(MPI_Comm comm, const std::string& path, TetMesh* mesh); // .msh 2.2 ASCII / 4.1 ASCII
// By name: *.msh is Gmsh, otherwise a TetGen basename (a trailing .node or .ele is dropped).
PetscErrorCode readMeshFile(MPI_Comm comm, const std::string& path, TetMesh* mesh);

// The named choices of an app's -mesh (for suite::optionsChoice): "beam" or "file".
std::vector<suite::Choice> meshChoices();
// The mesh of that choice: the structured beam, or the mesh file (an empty name is an error naming
// -mesh_file), promoted to P2 for order 2.
PetscErrorCode makeMesh(MPI_Comm comm, const std::string& kind, const BeamSpec& beam, const std::string& file,
                        int order, TetMesh* mesh);

} // namespace suite::fem
