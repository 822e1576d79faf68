// P1/P2 tetrahedral shape functions and quadrature (Hammer-Marlowe-Stroud 4-point rule; Stroud's conical
// product rule: Gauss-Legendre on [0,1]^3 through the Duffy map xi=u, eta=v(1-u), zeta=w(1-u)(1-v), Stroud
// 1971).
#include "fem/element.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace suite::fem {

QuadRule tetCentroidRule() {
  return {{{0.25, 0.25, 0.25}}, {1.0 / 6.0}};
}

QuadRule tetFourPointRule() {
  const double a = 0.5854101966249685, b = 0.1381966011250105;
  return {{{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}}, {1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 24}};
}

static void gaussLegendre01(int n, std::vector<double>* x, std::vector<double>* w) {
  // Newton iteration on P_n from the Chebyshev-like initial guess; mapped from [-1,1] to [0,1].
  x->resize(n);
  w->resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      if (n == 1) p0 = 1, p1 = z;
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    (*x)[i] = 0.5 * (1 - z);
    (*w)[i] = 1.0 / ((1 - z * z) * dp * dp); // 2/((1-z^2)P'^2) on [-1,1], halved for [0,1]
  }
}

QuadRule tetConicalRule(int n) {
  std::vector<double> x, w;
  gaussLegendre01(n, &x, &w);
  QuadRule r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double u = x[i], v = x[j], s = x[k];
        r.points.push_back({u, v * (1 - u), s * (1 - u) * (1 - v)});
        r.weights.push_back(w[i] * w[j] * w[k] * (1 - u) * (1 - u) * (1 - v));
      }
  return r;
}

QuadRule stiffnessRule(int order) {
  return order == 2 ? tetFourPointRule() : tetCentroidRule();
}

void shapeFunctions(int order, const double xi[3], double* N, double (*dN)[3]) {
  const double L[4] = {1 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (order == 1) {
    for (int a = 0; a < 4; ++a) {
      N[a] = L[a];
      for (int j = 0; j < 3; ++j) dN[a][j] = dL[a][j];
    }
    return;
  }
  static const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  for (int a = 0; a < 4; ++a) {
    N[a] = L[a] * (2 * L[a] - 1);
    for (int j = 0; j < 3; ++j) dN[a][j] = (4 * L[a] - 1) * dL[a][j];
  }
  for (int e = 0; e < 6; ++e) {
    const int p = edges[e][0], q = edges[e][1];
    N[4 + e] = 4 * L[p] * L[q];
    for (int j = 0; j < 3; ++j) dN[4 + e][j] = 4 * (dL[p][j] * L[q] + L[p] * dL[q][j]);
  }
}

PetscErrorCode computeGeometry(MPI_Comm comm, const TetMesh& mesh, const QuadRule& rule, ElementGeometry* g) {
  PetscFunctionBeginUser;
  const int nen = mesh.nodes_per_elem, nq = static_cast<int>(rule.points.size()), ne = mesh.numElems();
  g->nen = nen;
  g->nq = nq;
  g->wdet.assign(static_cast<size_t>(ne) * nq, 0.0);
  g->grads.assign(static_cast<size_t>(ne) * nq * nen * 3, 0.0);
  std::vector<double> N(nen);
  std::vector<double> dN(nen * 3);
  for (int e = 0; e < ne; ++e) {
    const int* t = mesh.elem(e);
    for (int q = 0; q < nq; ++q) {
      shapeFunctions(mesh.order(), rule.points[q].data(), N.data(),
                     reinterpret_cast<double(*)[3]>(dN.data()));
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero(); // J(i,j) = dX_i/dxi_j
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) J(i, j) += mesh.nodes[t[a]][i] * dN[a * 3 + j];
      const double det = J.determinant();
      PetscCheck(det > 0, comm, PETSC_ERR_ARG_WRONG,
                 "Mesh: element %d has det J = %g <= 0 at quadrature point %d (inverted or degenerate)", e,
                 det, q);
      const Eigen::Matrix3d Jinv = J.inverse();
      g->wdet[static_cast<size_t>(e) * nq + q] = rule.weights[q] * det;
      double* gr = g->grads.data() + (static_cast<size_t>(e) * nq + q) * nen * 3;
      for (int a = 0; a < nen; ++a)
        for (int j = 0; j < 3; ++j) {
          double s = 0;
          for (int k = 0; k < 3; ++k) s += dN[a * 3 + k] * Jinv(k, j);
          gr[a * 3 + j] = s;
        }
    }
  }
  PetscFunctionReturn(0);
}

} // namespace suite::fem
