// Body-space solve of the free contact rows (see body_space_solve.hpp).
#include "contact/body_space_solve.hpp"

#include "contact/delassus_sparse.hpp"

#include <algorithm>
#include <limits>
#include <map>

namespace suite::contact {

std::vector<M6> bodyMassMatrices(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i) {
  std::vector<M6> m(bodies.size(), M6::Zero());
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].is_static) continue;
    m[i].topLeftCorner<3, 3>() = bodies[i].mass * Mat3::Identity();
    m[i].bottomRightCorner<3, 3>() = inv_i[i].inverse();
  }
  return m;
}

BodySpaceSolver::BodySpaceSolver(const std::vector<JRow>& rows, const std::vector<M6>& mass, lcp::Vec reg)
    : rows_(rows), mass_(mass), reg_(std::move(reg)) {
  buildPattern();
}

// The order of the bodies in K: AMD on the body graph (a body per node, an edge per pair sharing a row).
void BodySpaceSolver::orderBodies(const std::vector<std::pair<int, int>>& pairs) {
  const int nb = (int)mass_.size();
  std::vector<Eigen::Triplet<double>> t;
  for (int b = 0; b < nb; ++b) t.emplace_back(b, b, 1.0);
  for (const auto& [a, b] : pairs) t.emplace_back(a, b, 1.0), t.emplace_back(b, a, 1.0);
  Eigen::SparseMatrix<double> G(nb, nb);
  G.setFromTriplets(t.begin(), t.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inv; // inv.indices()[k]: the k-th body
  Eigen::AMDOrdering<int>()(G, inv);
  at_.assign(nb, 0);
  for (int k = 0; k < nb; ++k) at_[inv.indices()[k]] = 6 * k;
}

// K's block pattern in the body order (the 6 x 6 blocks of every body and of every body pair sharing a row),
// analysed by the block Cholesky; each row's pair and which of its bodies comes first in the order.
void BodySpaceSolver::buildPattern() {
  const int nb = (int)mass_.size();
  std::map<std::pair<int, int>, int> pair_id; // (a, b) -> index among the pairs, a < b
  for (const JRow& J : rows_)
    if (J.ba >= 0 && J.bb >= 0 && J.ba != J.bb) pair_id.emplace(std::minmax(J.ba, J.bb), (int)pair_id.size());
  std::vector<std::pair<int, int>> pairs(pair_id.size());
  for (const auto& [ab, k] : pair_id) pairs[k] = ab;
  orderBodies(pairs);
  std::vector<std::pair<int, int>> edges(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) edges[k] = {pos(pairs[k].first), pos(pairs[k].second)};
  pair_block_ = chol_.analyze(nb, edges);
  pair_of_.assign(rows_.size(), -1);
  a_first_.assign(rows_.size(), true);
  for (size_t i = 0; i < rows_.size(); ++i) {
    const JRow& J = rows_[i];
    if (J.ba < 0 || J.bb < 0 || J.ba == J.bb) continue;
    pair_of_[i] = pair_id.at(std::minmax(J.ba, J.bb));
    a_first_[i] = at_[J.ba] < at_[J.bb];
  }
}

// K += s J_i^T J_i: the diagonal blocks of its bodies and the lower block of its pair (row: the later body in
// the order, column: the earlier one).
void BodySpaceSolver::addRow(int i, double s) {
  const JRow& J = rows_[i];
  if (J.ba >= 0) chol_.diag(pos(J.ba)).noalias() += (s * J.ja) * J.ja.transpose();
  if (J.bb >= 0) chol_.diag(pos(J.bb)).noalias() += (s * J.jb) * J.jb.transpose();
  if (pair_of_[i] < 0) return;
  M6& L = chol_.lower(pair_block_[pair_of_[i]]);
  if (a_first_[i])
    L.noalias() += (s * J.jb) * J.ja.transpose();
  else
    L.noalias() += (s * J.ja) * J.jb.transpose();
}

// K(F) = M + J_F^T D_F^-1 J_F assembled into the fixed pattern and factorised (static bodies: identity).
bool BodySpaceSolver::factor(const std::vector<int>& F) {
  ok_ = false;
  chol_.setZero();
  for (size_t b = 0; b < mass_.size(); ++b)
    chol_.diag(pos((int)b)) = mass_[b].isZero() ? M6(M6::Identity()) : mass_[b];
  for (int i : F) addRow(i, 1.0 / reg_[i]);
  ++factorizations_;
  if (!chol_.factor()) return false;
  F_ = F, ok_ = true;
  return true;
}

// A_FF^-1 rhs by the Woodbury identity on the current factorisation.
lcp::Vec BodySpaceSolver::woodbury(const std::vector<int>& F, const lcp::Vec& rhs) const {
  lcp::Vec g = lcp::Vec::Zero(6 * (int)mass_.size()), out(F.size());
  for (size_t a = 0; a < F.size(); ++a) {
    const JRow& J = rows_[F[a]];
    const double s = rhs[a] / reg_[F[a]];
    if (J.ba >= 0) g.segment<6>(at_[J.ba]) += s * J.ja;
    if (J.bb >= 0) g.segment<6>(at_[J.bb]) += s * J.jb;
  }
  chol_.solve(&g);
  const lcp::Vec& y = g;
  for (size_t a = 0; a < F.size(); ++a) {
    const JRow& J = rows_[F[a]];
    double jy = 0.0;
    if (J.ba >= 0) jy += J.ja.dot(y.segment<6>(at_[J.ba]));
    if (J.bb >= 0) jy += J.jb.dot(y.segment<6>(at_[J.bb]));
    out[a] = (rhs[a] - jy) / reg_[F[a]];
  }
  return out;
}

// A_FF x (matrix-free: u = M^-1 J_F^T x per body, then J_i u + D_i x_i).
lcp::Vec BodySpaceSolver::applyFree(const std::vector<int>& F, const lcp::Vec& x) const {
  V6s u(mass_.size(), V6::Zero());
  for (size_t a = 0; a < F.size(); ++a) addRowImpulse(rows_[F[a]], x[a], &u);
  lcp::Vec y(F.size());
  for (size_t a = 0; a < F.size(); ++a) y[a] = rowVelocity(rows_[F[a]], u) + reg_[F[a]] * x[a];
  return y;
}

bool BodySpaceSolver::solve(const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) {
  for (int i : F)
    if (!(reg_[i] > 0)) return false;
  if (!(ok_ && F == F_) && !factor(F)) return false;
  ++solves_;
  *x = woodbury(F, r);
  // refined on A_FF (the Woodbury step loses about |D^-1 J| / |A| digits: residuals ~1e-7 |r| on a pyramid)
  // until the residual is at round-off, 16 eps |r|, or stops falling; at most 4 times
  lcp::Vec res = r - applyFree(F, *x);
  double err = res.lpNorm<Eigen::Infinity>();
  const double floor = 16 * std::numeric_limits<double>::epsilon() * r.lpNorm<Eigen::Infinity>();
  for (int k = 0; k < 4 && err > floor; ++k) {
    const lcp::Vec cand = *x + woodbury(F, res), cres = r - applyFree(F, cand);
    const double e = cres.lpNorm<Eigen::Infinity>();
    if (!(e < err)) break;
    *x = cand, res = cres, err = e;
  }
  return x->allFinite();
}

bool bodySpaceSolve(const std::vector<JRow>& rows, const std::vector<M6>& mass, const lcp::Vec& reg,
                    const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) {
  BodySpaceSolver s(rows, mass, reg);
  return s.solve(F, r, x);
}

} // namespace suite::contact
