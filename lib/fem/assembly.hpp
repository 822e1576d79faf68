// Total-Lagrangian assembly of an elastic body on a tetrahedral mesh: internal force f(u) = sum_e int B^T P
// dV, consistent tangent K = df/du, consistent and HRZ-lumped mass (Hinton, Rock & Zienkiewicz 1976), and
// consistent nodal loads (body force, surface traction). The free DOFs (not in a Dirichlet set) are numbered
// node by node; matrices are the upper triangle of the free-free block with a fixed pattern and a precomputed
// scatter.
#pragma once

#include "fem/element.hpp"
#include "fem/material.hpp"
#include "fem/second_order_system.hpp"
#include "fem/sparse.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace suite::fem {

struct AssemblyResult {
  double energy = 0; // strain energy int W dV
  int bad_elem = -1; // first element with det F <= 0 (then the result is not admissible)
  double min_detF = 1e300;
};

class ElasticModel final : public SecondOrderSystem {
public:
  // fixed[3*node + c] != 0: Dirichlet (zero displacement) DOF. Errors if an element is inverted.
  PetscErrorCode setup(MPI_Comm comm, const TetMesh& mesh, const Material& material, std::vector<char> fixed);

  int numFree() const { return nfree_; }
  int numDofs() const { return 3 * mesh_->numNodes(); }
  const std::vector<int>& eq() const { return eq_; } // eq[dof] = free index or -1
  const SymCsc& pattern() const { return K_; } // upper triangle of the free block (values: last tangent)
  const TetMesh& mesh() const { return *mesh_; }
  const Material& material() const { return *material_; }
  const Graph& nodeGraphOf() const { return node_graph_; }
  const ElementGeometry& geometry() const { return geo_; } // stiffness rule's quadrature points

  // Full displacement (3N, fixed entries as given) -> free internal force f (nfree) and, if K != nullptr, the
  // tangent values in K->val (pattern()). Returns admissibility in res.bad_elem < 0.
  AssemblyResult assemble(const double* u_full, double* f_free, std::vector<double>* K) const;

  // Mass on the pattern (consistent) or on the diagonal only (HRZ lumped), density rho.
  std::vector<double> consistentMass(double rho) const;
  std::vector<double> lumpedMass(double rho) const;
  // Consistent nodal loads (free entries) of a body force b (per unit volume) and of a uniform traction t on
  // faces.
  std::vector<double> bodyForce(const std::array<double, 3>& b) const;
  std::vector<double> tractionLoad(const std::vector<std::vector<int>>& faces,
                                   const std::array<double, 3>& t) const;

  // SecondOrderSystem on free DOFs (fixed DOFs held at zero). Linear material: f = K0 u with the stiffness
  // assembled once in setup (a sparse product instead of the element loop; no det F check, small strain).
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override;
  bool isLinear() const override { return material_->isLinear(); }
  // Result of the last internalForce call (admissibility, min det F).
  const AssemblyResult& lastAssembly() const { return last_; }

  // Distributed assembly (-solver petsc at several ranks): only the elements with owned[e] != 0 are assembled
  // (internal force, tangent, energy and mass are then this rank's partial sums; the linear stiffness is
  // reassembled). Empty: all elements (replicated computation).
  void setOwnedElements(std::vector<char> owned);
  // The elements whose first corner node this rank owns (node_part[node] = owning rank) as setOwnedElements.
  void ownElementsOfNodes(const std::vector<int>& node_part, int rank);
  bool partial() const { return !owned_.empty(); }
  bool ownsElement(int e) const { return owned_.empty() || owned_[e]; }

  void scatterFree(const double* free, double* full) const;              // full[fixed] untouched
  std::vector<double> fullVector(const std::vector<double>& free) const; // fixed DOFs zero
  void gatherFree(const double* full, double* free) const;

private:
  MPI_Comm comm_ = MPI_COMM_SELF;
  const TetMesh* mesh_ = nullptr;
  const Material* material_ = nullptr;
  ElementGeometry geo_;
  std::vector<int> eq_;
  int nfree_ = 0;
  SymCsc K_;
  std::vector<int> scatter_;               // per element (3 nen)^2 entries: index into K values or -1
  std::vector<std::pair<int, int>> pairs_; // compact tangent scatter (element upper index, K index)
  std::vector<size_t> pair_off_;           // pairs_ of element e: [pair_off_[e], pair_off_[e+1])
  Graph node_graph_;
  std::vector<double> u_full_, K0_;
  std::vector<char> owned_; // elements assembled by this rank (empty: all)
  AssemblyResult last_;
};

} // namespace suite::fem
