// Lagrange tetrahedra P1 (4 nodes) and P2 (10 nodes, VTK edge order 01,12,02,03,13,23): shape functions,
// quadrature rules (centroid; 4-point degree-2 rule, Hammer-Marlowe-Stroud 1956; Stroud conical product
// Gauss rules, Stroud 1971 sec. 2.7) and per-element geometry (physical gradients, weights) on the reference
// mesh.
#pragma once

#include "fem/mesh.hpp"

#include <vector>

namespace suite::fem {

struct QuadRule {
  std::vector<std::array<double, 3>> points; // reference coordinates (xi, eta, zeta)
  std::vector<double> weights;               // sum = 1/6 (reference volume)
};
QuadRule tetCentroidRule();
QuadRule tetFourPointRule();
QuadRule tetConicalRule(int n); // n^3 points, exact for degree 2n-1-... (>= 2n-3 in total degree)
// Stiffness rule of the element order: centroid for P1, 4-point for P2.
QuadRule stiffnessRule(int order);

// N[a] and dN[a][0..2] (reference derivatives) at xi for order 1 or 2.
void shapeFunctions(int order, const double xi[3], double* N, double (*dN)[3]);

// Geometry of all elements at all quadrature points of a rule: for element e, point q, the weight w*detJ and
// the physical gradients dN/dX (nodes_per_elem x 3).
struct ElementGeometry {
  int nen = 4, nq = 1;
  std::vector<double> wdet;  // [e*nq + q]
  std::vector<double> grads; // [((e*nq + q)*nen + a)*3 + j]
  const double* grad(int e, int q) const {
    return grads.data() + (static_cast<size_t>(e) * nq + q) * nen * 3;
  }
  double weight(int e, int q) const { return wdet[static_cast<size_t>(e) * nq + q]; }
};
// Errors if some detJ <= 0 (inverted or degenerate element), naming the element.
PetscErrorCode computeGeometry(MPI_Comm comm, const TetMesh& mesh, const QuadRule& rule, ElementGeometry* g);

} // namespace suite::fem
