// Tetrahedral mesh generator (Kuhn/Freudenthal 6-tet split of each hexahedron along its main diagonal,
// conforming because every cube uses the same split; Kuhn 1960), P2 promotion, boundary sets and the node
// graph.
#include "fem/mesh.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace suite::fem {

double tetSignedVolume(const std::array<double, 3>& a, const std::array<double, 3>& b,
                       const std::array<double, 3>& c, const std::array<double, 3>& d) {
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

TetMesh makeBeam(const BeamSpec& s) {
  TetMesh m;
  const int nx = s.cells[0], ny = s.cells[1], nz = s.cells[2];
  const double h[3] = {s.length / nx, s.size[0] / ny, s.size[1] / nz};
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  m.nodes.reserve(static_cast<size_t>(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.nodes.push_back({i * h[0], j * h[1], k * h[2]});
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  m.elems.reserve(static_cast<size_t>(nx) * ny * nz * 24);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          int t[4];
          t[0] = id(c[0], c[1], c[2]);
          for (int q = 0; q < 3; ++q) {
            ++c[p[q]];
            t[q + 1] = id(c[0], c[1], c[2]);
          }
          if (tetSignedVolume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]) < 0)
            std::swap(t[2], t[3]);
          m.elems.insert(m.elems.end(), t, t + 4);
        }
  return m;
}

TetMesh promoteToP2(const TetMesh& p1) {
  static const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  TetMesh m;
  m.nodes = p1.nodes;
  m.nodes_per_elem = 10;
  std::map<std::pair<int, int>, int> mid;
  for (int e = 0; e < p1.numElems(); ++e) {
    const int* t = p1.elem(e);
    m.elems.insert(m.elems.end(), t, t + 4);
    for (const auto& ed : edges) {
      const int a = std::min(t[ed[0]], t[ed[1]]), b = std::max(t[ed[0]], t[ed[1]]);
      auto it = mid.find({a, b});
      if (it == mid.end()) {
        const auto &x = m.nodes[a], &y = m.nodes[b];
        m.nodes.push_back({0.5 * (x[0] + y[0]), 0.5 * (x[1] + y[1]), 0.5 * (x[2] + y[2])});
        it = mid.emplace(std::make_pair(a, b), m.numNodes() - 1).first;
      }
      m.elems.push_back(it->second);
    }
  }
  return m;
}

PetscErrorCode checkMesh(MPI_Comm comm, const TetMesh& mesh, const char* source) {
  PetscFunctionBeginUser;
  PetscCheck(mesh.numNodes() > 0 && mesh.numElems() > 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "Mesh %s: empty mesh (%d nodes, %d elements)", source, mesh.numNodes(), mesh.numElems());
  for (int e = 0; e < mesh.numElems(); ++e) {
    const int* t = mesh.elem(e);
    for (int a = 0; a < mesh.nodes_per_elem; ++a) {
      PetscCheck(t[a] >= 0 && t[a] < mesh.numNodes(), comm, PETSC_ERR_FILE_UNEXPECTED,
                 "Mesh %s: element %d references node %d, but there are %d nodes", source, e, t[a],
                 mesh.numNodes());
      for (int b = 0; b < a; ++b)
        PetscCheck(t[a] != t[b], comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s: element %d repeats node %d",
                   source, e, t[a]);
    }
    const double v = tetSignedVolume(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    PetscCheck(v > 0, comm, PETSC_ERR_FILE_UNEXPECTED,
               "Mesh %s: inverted element %d (signed volume %g <= 0, det F <= 0 in the input)", source, e, v);
  }
  PetscFunctionReturn(0);
}

static double bboxDiagonal(const TetMesh& mesh) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& x : mesh.nodes)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], x[i]), hi[i] = std::max(hi[i], x[i]);
  double d = 0;
  for (int i = 0; i < 3; ++i) d += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return std::sqrt(d);
}

std::vector<double> flatCoordinates(const TetMesh& mesh) {
  std::vector<double> xyz(3 * mesh.nodes.size());
  for (size_t v = 0; v < mesh.nodes.size(); ++v)
    for (int i = 0; i < 3; ++i) xyz[3 * v + i] = mesh.nodes[v][i];
  return xyz;
}

std::vector<int> cornerNodes(const TetMesh& mesh) {
  std::vector<int> tets(4 * static_cast<size_t>(mesh.numElems()));
  for (int e = 0; e < mesh.numElems(); ++e)
    for (int a = 0; a < 4; ++a) tets[4 * static_cast<size_t>(e) + a] = mesh.elem(e)[a];
  return tets;
}

std::vector<int> nodesOnPlane(const TetMesh& mesh, int axis, double value, double tol) {
  const double eps = tol * bboxDiagonal(mesh);
  std::vector<int> out;
  for (int n = 0; n < mesh.numNodes(); ++n)
    if (std::abs(mesh.nodes[n][axis] - value) <= eps) out.push_back(n);
  return out;
}

std::vector<std::vector<int>> facesOnPlane(const TetMesh& mesh, int axis, double value, double tol) {
  // Face f of a tet is opposite corner f; corners and (for P2) edge nodes in order 0,1,2, 01,12,02.
  static const int corners[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  auto edgeIndex = [](int a, int b) {
    static const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    for (int i = 0; i < 6; ++i)
      if ((edges[i][0] == a && edges[i][1] == b) || (edges[i][0] == b && edges[i][1] == a)) return 4 + i;
    return -1;
  };
  const double eps = tol * bboxDiagonal(mesh);
  auto on = [&](int n) { return std::abs(mesh.nodes[n][axis] - value) <= eps; };
  std::vector<std::vector<int>> out;
  for (int e = 0; e < mesh.numElems(); ++e) {
    const int* t = mesh.elem(e);
    for (const auto& c : corners) {
      if (!(on(t[c[0]]) && on(t[c[1]]) && on(t[c[2]]))) continue;
      std::vector<int> f = {t[c[0]], t[c[1]], t[c[2]]};
      if (mesh.nodes_per_elem == 10)
        for (int q = 0; q < 3; ++q) f.push_back(t[edgeIndex(c[q], c[(q + 1) % 3])]);
      out.push_back(f);
    }
  }
  return out;
}

void nodeGraph(const TetMesh& mesh, std::vector<int>* xadj, std::vector<int>* adj) {
  const int n = mesh.numNodes(), k = mesh.nodes_per_elem;
  std::vector<std::vector<int>> nb(n);
  for (int e = 0; e < mesh.numElems(); ++e) {
    const int* t = mesh.elem(e);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        if (a != b) nb[t[a]].push_back(t[b]);
  }
  xadj->assign(n + 1, 0);
  adj->clear();
  for (int i = 0; i < n; ++i) {
    std::sort(nb[i].begin(), nb[i].end());
    nb[i].erase(std::unique(nb[i].begin(), nb[i].end()), nb[i].end());
    adj->insert(adj->end(), nb[i].begin(), nb[i].end());
    (*xadj)[i + 1] = static_cast<int>(adj->size());
  }
}

double facesArea(const TetMesh& mesh, const std::vector<std::vector<int>>& faces) {
  double area = 0;
  for (const auto& f : faces) {
    const auto &a = mesh.nodes[f[0]], &b = mesh.nodes[f[1]], &c = mesh.nodes[f[2]];
    const Eigen::Vector3d u(b[0] - a[0], b[1] - a[1], b[2] - a[2]), w(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    area += 0.5 * u.cross(w).norm();
  }
  return area;
}

PetscErrorCode clampPlane(MPI_Comm comm, const char* option, const std::string& s, const TetMesh& mesh,
                          std::vector<char>* fixed) {
  PetscFunctionBeginUser;
  fixed->assign(3 * mesh.numNodes(), 0);
  if (s == "none") PetscFunctionReturn(0);
  PetscCheck(s.size() >= 3 && (s[0] == 'x' || s[0] == 'y' || s[0] == 'z') && s[1] == '=', comm,
             PETSC_ERR_ARG_WRONG, "%s %s: expected a plane such as x=0 (or none)", option, s.c_str());
  char* end = nullptr;
  const double value = std::strtod(s.c_str() + 2, &end);
  PetscCheck(end && *end == '\0', comm, PETSC_ERR_ARG_WRONG, "%s %s: bad coordinate", option, s.c_str());
  for (int v : nodesOnPlane(mesh, s[0] - 'x', value))
    for (int c = 0; c < 3; ++c) (*fixed)[3 * v + c] = 1;
  PetscFunctionReturn(0);
}

} // namespace suite::fem
