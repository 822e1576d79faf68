// Total-Lagrangian element loop (Bonet & Wood 2008, ch. 8): F = I + sum_a u_a (x) dN_a/dX, f_a = sum_q w P
// dN_a, K_ab(i,k) = sum_q w dN_a/dX_J A_iJkL dN_b/dX_L; HRZ lumping (Hinton, Rock & Zienkiewicz, Earthq. Eng.
// Struct. Dyn. 4 (1976) 245) scales the consistent diagonal to the element mass.
#include "fem/assembly.hpp"

#include <algorithm>

namespace suite::fem {

PetscErrorCode ElasticModel::setup(MPI_Comm comm, const TetMesh& mesh, const Material& material,
                                   std::vector<char> fixed) {
  PetscFunctionBeginUser;
  comm_ = comm;
  mesh_ = &mesh;
  material_ = &material;
  PetscCall(checkMesh(comm, mesh, "(setup)"));
  PetscCall(computeGeometry(comm, mesh, stiffnessRule(mesh.order()), &geo_));
  const int N = mesh.numNodes();
  PetscCheck(static_cast<int>(fixed.size()) == 3 * N, comm, PETSC_ERR_ARG_SIZ,
             "fixed flags: %d entries for %d DOFs", static_cast<int>(fixed.size()), 3 * N);
  eq_.assign(3 * N, -1);
  nfree_ = 0;
  for (int d = 0; d < 3 * N; ++d)
    if (!fixed[d]) eq_[d] = nfree_++;
  nodeGraph(mesh, &node_graph_.xadj, &node_graph_.adj);
  node_graph_.n = N;

  // Pattern: free DOF pairs of adjacent (or identical) nodes, upper triangle, sorted by row within a column.
  K_ = SymCsc();
  K_.n = nfree_;
  K_.colptr.assign(nfree_ + 1, 0);
  std::vector<std::vector<int>> cols(nfree_);
  for (int v = 0; v < N; ++v) {
    for (int c = 0; c < 3; ++c) {
      const int col = eq_[3 * v + c];
      if (col < 0) continue;
      auto& rows = cols[col];
      auto add = [&](int w) {
        for (int r = 0; r < 3; ++r) {
          const int row = eq_[3 * w + r];
          if (row >= 0 && row <= col) rows.push_back(row);
        }
      };
      add(v);
      for (int k = node_graph_.xadj[v]; k < node_graph_.xadj[v + 1]; ++k) add(node_graph_.adj[k]);
      std::sort(rows.begin(), rows.end());
    }
  }
  for (int c = 0; c < nfree_; ++c) K_.colptr[c + 1] = K_.colptr[c] + static_cast<int>(cols[c].size());
  K_.rowind.reserve(K_.colptr[nfree_]);
  for (auto& r : cols) K_.rowind.insert(K_.rowind.end(), r.begin(), r.end());
  K_.val.assign(K_.rowind.size(), 0.0);

  const int nen = mesh.nodes_per_elem, nd = 3 * nen, ne = mesh.numElems();
  scatter_.assign(static_cast<size_t>(ne) * nd * nd, -1);
  for (int e = 0; e < ne; ++e) {
    const int* t = mesh.elem(e);
    int* s = scatter_.data() + static_cast<size_t>(e) * nd * nd;
    for (int p = 0; p < nd; ++p)
      for (int q = 0; q < nd; ++q) {
        const int r = eq_[3 * t[p / 3] + p % 3], c = eq_[3 * t[q / 3] + q % 3];
        if (r < 0 || c < 0 || r > c) continue;
        const auto b = K_.rowind.begin() + K_.colptr[c], en = K_.rowind.begin() + K_.colptr[c + 1];
        s[p * nd + q] = static_cast<int>(std::lower_bound(b, en, r) - K_.rowind.begin());
      }
  }
  // Compact scatter of the element tangent: for every element entry that lands in the global upper triangle,
  // (index into the element's upper triangle, index into K values) -- at most nd (nd + 1) / 2 per element.
  pair_off_.assign(ne + 1, 0);
  pairs_.clear();
  pairs_.reserve(static_cast<size_t>(ne) * nd * (nd + 1) / 2);
  for (int e = 0; e < ne; ++e) {
    const int* s = scatter_.data() + static_cast<size_t>(e) * nd * nd;
    for (int p = 0; p < nd; ++p)
      for (int q = 0; q < nd; ++q)
        if (s[p * nd + q] >= 0) pairs_.push_back({p <= q ? p * nd + q : q * nd + p, s[p * nd + q]});
    pair_off_[e + 1] = pairs_.size();
  }
  K0_.clear();
  if (material.isLinear()) {
    std::vector<double> zero(3 * N, 0.0), f(nfree_);
    std::vector<double> K0;
    assemble(zero.data(), f.data(), &K0);
    K0_.swap(K0);
  }
  PetscFunctionReturn(0);
}

AssemblyResult ElasticModel::assemble(const double* u, double* f, std::vector<double>* K) const {
  AssemblyResult res;
  const TetMesh& mesh = *mesh_;
  const int nen = geo_.nen, nd = 3 * nen, nq = geo_.nq, ne = mesh.numElems();
  std::fill(f, f + nfree_, 0.0);
  if (K) K->assign(K_.val.size(), 0.0);
  double ue[30 * 3], fe[30], ke[30 * 30];
  Mat3 F, P;
  for (int e = 0; e < ne; ++e) {
    if (!owned_.empty() && !owned_[e]) continue;
    const int* t = mesh.elem(e);
    for (int a = 0; a < nen; ++a)
      for (int i = 0; i < 3; ++i) ue[3 * a + i] = u[3 * t[a] + i];
    std::fill(fe, fe + nd, 0.0);
    if (K) std::fill(ke, ke + nd * nd, 0.0);
    for (int q = 0; q < nq; ++q) {
      const double* g = geo_.grad(e, q);
      const double w = geo_.weight(e, q);
      F.setIdentity();
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < 3; ++i)
          for (int J = 0; J < 3; ++J) F(i, J) += ue[3 * a + i] * g[3 * a + J];
      const double det = F.determinant();
      res.min_detF = std::min(res.min_detF, det);
      if (!(det > 0)) {
        if (res.bad_elem < 0) res.bad_elem = e;
        continue;
      }
      double W;
      if (K)
        material_->evaluateWithTangent(F, g, nen, w, &W, &P, ke);
      else
        material_->evaluate(F, &W, &P, nullptr);
      res.energy += w * W;
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < 3; ++i)
          fe[3 * a + i] += w * (P(i, 0) * g[3 * a] + P(i, 1) * g[3 * a + 1] + P(i, 2) * g[3 * a + 2]);
    }
    for (int p = 0; p < nd; ++p) {
      const int r = eq_[3 * t[p / 3] + p % 3];
      if (r >= 0) f[r] += fe[p];
    }
    if (!K) continue;
    double* kv = K->data();
    const size_t pe = pair_off_[e + 1];
    for (size_t k = pair_off_[e]; k < pe; ++k) kv[pairs_[k].second] += ke[pairs_[k].first];
  }
  return res;
}

namespace {
// Element consistent mass of one component: m_ab = rho int N_a N_b dV (exact: conical rule with 4^3 points).
void elementMass(const TetMesh& mesh, int e, double rho, const QuadRule& rule, std::vector<double>* m) {
  const int nen = mesh.nodes_per_elem;
  const int* t = mesh.elem(e);
  const double vol6 =
      6 * tetSignedVolume(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
  m->assign(nen * nen, 0.0);
  double N[10], dN[10][3];
  for (size_t q = 0; q < rule.points.size(); ++q) {
    shapeFunctions(mesh.order(), rule.points[q].data(), N, dN);
    const double w = rho * rule.weights[q] * vol6; // straight-sided: detJ = 6 V
    for (int a = 0; a < nen; ++a)
      for (int b = 0; b < nen; ++b) (*m)[a * nen + b] += w * N[a] * N[b];
  }
}
} // namespace

std::vector<double> ElasticModel::consistentMass(double rho) const {
  std::vector<double> M(K_.val.size(), 0.0);
  const QuadRule rule = tetConicalRule(4);
  const int nen = mesh_->nodes_per_elem, nd = 3 * nen;
  std::vector<double> m;
  for (int e = 0; e < mesh_->numElems(); ++e) {
    if (!owned_.empty() && !owned_[e]) continue;
    elementMass(*mesh_, e, rho, rule, &m);
    const int* s = scatter_.data() + static_cast<size_t>(e) * nd * nd;
    for (int a = 0; a < nen; ++a)
      for (int b = 0; b < nen; ++b)
        for (int i = 0; i < 3; ++i) {
          const int idx = s[(3 * a + i) * nd + 3 * b + i];
          if (idx >= 0) M[idx] += m[a * nen + b];
        }
  }
  return M;
}

std::vector<double> ElasticModel::lumpedMass(double rho) const {
  std::vector<double> M(K_.val.size(), 0.0);
  const QuadRule rule = tetConicalRule(4);
  const int nen = mesh_->nodes_per_elem, nd = 3 * nen;
  std::vector<double> m;
  for (int e = 0; e < mesh_->numElems(); ++e) {
    if (!owned_.empty() && !owned_[e]) continue;
    elementMass(*mesh_, e, rho, rule, &m);
    double total = 0, diag = 0;
    for (int a = 0; a < nen; ++a) {
      diag += m[a * nen + a];
      for (int b = 0; b < nen; ++b) total += m[a * nen + b];
    }
    const int* s = scatter_.data() + static_cast<size_t>(e) * nd * nd;
    for (int a = 0; a < nen; ++a)
      for (int i = 0; i < 3; ++i) {
        const int idx = s[(3 * a + i) * nd + 3 * a + i];
        if (idx >= 0) M[idx] += m[a * nen + a] * total / diag;
      }
  }
  return M;
}

std::vector<double> ElasticModel::bodyForce(const std::array<double, 3>& b) const {
  std::vector<double> f(nfree_, 0.0);
  const QuadRule rule = tetConicalRule(3);
  const int nen = mesh_->nodes_per_elem;
  double N[10], dN[10][3];
  for (int e = 0; e < mesh_->numElems(); ++e) {
    const int* t = mesh_->elem(e);
    const double vol6 =
        6 * tetSignedVolume(mesh_->nodes[t[0]], mesh_->nodes[t[1]], mesh_->nodes[t[2]], mesh_->nodes[t[3]]);
    for (size_t q = 0; q < rule.points.size(); ++q) {
      shapeFunctions(mesh_->order(), rule.points[q].data(), N, dN);
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < 3; ++i) {
          const int r = eq_[3 * t[a] + i];
          if (r >= 0) f[r] += rule.weights[q] * vol6 * N[a] * b[i];
        }
    }
  }
  return f;
}

std::vector<double> ElasticModel::tractionLoad(const std::vector<std::vector<int>>& faces,
                                               const std::array<double, 3>& t) const {
  // Uniform traction on flat triangles: P1 corners get area/3; P2 corners 0 and midsides area/3.
  std::vector<double> f(nfree_, 0.0);
  for (const auto& face : faces) {
    const auto &a = mesh_->nodes[face[0]], &b = mesh_->nodes[face[1]], &c = mesh_->nodes[face[2]];
    const Eigen::Vector3d u(b[0] - a[0], b[1] - a[1], b[2] - a[2]), v(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    const double area = 0.5 * u.cross(v).norm();
    const bool p2 = face.size() == 6;
    for (size_t k = 0; k < face.size(); ++k) {
      const double share = p2 ? (k < 3 ? 0.0 : area / 3) : area / 3;
      for (int i = 0; i < 3; ++i) {
        const int r = eq_[3 * face[k] + i];
        if (r >= 0) f[r] += share * t[i];
      }
    }
  }
  return f;
}

bool ElasticModel::internalForce(const double* u, double* f, std::vector<double>* K, double* energy) {
  if (!K0_.empty()) {
    symMultiply(K_, K0_, u, f);
    if (K) *K = K0_;
    last_ = AssemblyResult();
    for (int i = 0; i < nfree_; ++i) last_.energy += 0.5 * u[i] * f[i];
    if (energy) *energy = last_.energy;
    return true;
  }
  u_full_.resize(eq_.size(), 0.0);
  scatterFree(u, u_full_.data());
  last_ = assemble(u_full_.data(), f, K);
  if (energy) *energy = last_.energy;
  return last_.bad_elem < 0;
}

void ElasticModel::setOwnedElements(std::vector<char> owned) {
  owned_ = std::move(owned);
  if (material_->isLinear()) {
    std::vector<double> zero(eq_.size(), 0.0), f(nfree_), K0;
    K0_.clear();
    assemble(zero.data(), f.data(), &K0);
    K0_.swap(K0);
  }
}

void ElasticModel::ownElementsOfNodes(const std::vector<int>& node_part, int rank) {
  std::vector<char> owned(mesh_->numElems(), 0);
  for (int e = 0; e < mesh_->numElems(); ++e) owned[e] = node_part[mesh_->elem(e)[0]] == rank;
  setOwnedElements(std::move(owned));
}

std::vector<double> ElasticModel::fullVector(const std::vector<double>& free) const {
  std::vector<double> full(eq_.size(), 0.0);
  scatterFree(free.data(), full.data());
  return full;
}

void ElasticModel::scatterFree(const double* free, double* full) const {
  for (size_t d = 0; d < eq_.size(); ++d)
    if (eq_[d] >= 0) full[d] = free[eq_[d]];
}

void ElasticModel::gatherFree(const double* full, double* free) const {
  for (size_t d = 0; d < eq_.size(); ++d)
    if (eq_[d] >= 0) free[eq_[d]] = full[d];
}

} // namespace suite::fem
