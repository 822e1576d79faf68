// Body-space solve of the free contact rows (see body_space_solve.hpp).
#include "contact/body_space_solve.hpp"

#include "contact/delassus_sparse.hpp"

#include <algorithm>
#include <cmath>
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
  wcol_.assign(rows_.size(), -1);
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
  changed_.clear();
  for (int c = 0; c < (int)wcol_.size(); ++c) wcol_[c] = -1; // W's columns belong to the old factorisation
  wcount_ = 0;
  if (!chol_.factor()) return false;
  F_ = F, cur_ = F, ok_ = true;
  return true;
}

// A_FF^-1 rhs by the Woodbury identity on the current factorisation.
lcp::Vec BodySpaceSolver::woodbury(const std::vector<int>& F, const lcp::Vec& rhs) const {
  lcp::Vec g = lcp::Vec::Zero(6 * (int)mass_.size()), out(F.size());
  for (size_t a = 0; a < F.size(); ++a) addRowT(F[a], rhs[a] / reg_[F[a]], &g);
  kSolve(&g);
  for (size_t a = 0; a < F.size(); ++a) out[a] = (rhs[a] - rowDot(F[a], g)) / reg_[F[a]];
  return out;
}

// g += s J_i^T (row i's parts at its two bodies).
void BodySpaceSolver::addRowT(int i, double s, lcp::Vec* g) const {
  const JRow& J = rows_[i];
  if (J.ba >= 0) g->segment<6>(at_[J.ba]) += s * J.ja;
  if (J.bb >= 0) g->segment<6>(at_[J.bb]) += s * J.jb;
}

// A_FF x (matrix-free: u = M^-1 J_F^T x per body, then J_i u + D_i x_i).
lcp::Vec BodySpaceSolver::applyFree(const std::vector<int>& F, const lcp::Vec& x) const {
  V6s u(mass_.size(), V6::Zero());
  for (size_t a = 0; a < F.size(); ++a) addRowImpulse(rows_[F[a]], x[a], &u);
  lcp::Vec y(F.size());
  for (size_t a = 0; a < F.size(); ++a) y[a] = rowVelocity(rows_[F[a]], u) + reg_[F[a]] * x[a];
  return y;
}

// u_j . y for the changed row j of the update (J_j^T: nonzero at its two bodies only).
double BodySpaceSolver::rowDot(int i, const lcp::Vec& y) const {
  const JRow& J = rows_[i];
  double v = 0.0;
  if (J.ba >= 0) v += J.ja.dot(y.segment<6>(at_[J.ba]));
  if (J.bb >= 0) v += J.jb.dot(y.segment<6>(at_[J.bb]));
  return v;
}

// The free set F as a low-rank change of the factorised one F_: K(F) = K(F_) + U Sigma U^T with a column J_i^T
// per row added (Sigma_ii = 1 / D_i) or removed (-1 / D_i); false (nothing changed) when more rows differ than
// maxUpdate(). The columns of W = K(F_)^-1 U are kept per row until the next factorisation (the active-set
// iterations move F away from F_ a few rows at a time, so most columns are reused); S = Sigma^-1 + U^T W is
// small, symmetric and indefinite once a row is removed: LU.
bool BodySpaceSolver::update(const std::vector<int>& F) {
  std::vector<int> changed;
  std::vector<double> sign;
  size_t a = 0, b = 0;
  const int most = maxUpdate();
  while ((a < F.size() || b < F_.size()) && (int)changed.size() <= most) {
    if (b == F_.size() || (a < F.size() && F[a] < F_[b]))
      changed.push_back(F[a++]), sign.push_back(1.0);
    else if (a == F.size() || F_[b] < F[a])
      changed.push_back(F_[b++]), sign.push_back(-1.0);
    else
      ++a, ++b;
  }
  if ((int)changed.size() > most) return false;
  const int k = (int)changed.size();
  for (int i : changed)
    if (wcol_[i] < 0) wcol_[i] = newColumn(i);
  lcp::Mat S(k, k);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      S(i, j) = rowDot(changed[i], W_.col(wcol_[changed[j]])) + (i == j ? sign[i] * reg_[changed[i]] : 0.0);
  S_.compute(S);
  changed_ = std::move(changed);
  cur_ = F;
  ++updates_;
  return true;
}

// The rows by which a free set may differ from the factorised one to be solved by an update. Each solve with an
// update costs k more vector updates of K's size and the k x k LU, each update the solves of its new rows.
// Measured on resting pyramids of base 10 / 20 / 30 (exact, ms/step; 200, 200, 100 steps): without updates
// 1.32 / 13.8 / 84.5; k <= 16: 1.19 / 10.5 / 86.7; k <= 32: 1.26 / 15.4 / 86.6; k <= a quarter of the bodies
// (116 on base 30, W not yet kept across updates): base 30 120. The active-set path moves with round-off, so the
// iteration counts change too (base 20: 16.9 at 16, 24.9 at 32).
int BodySpaceSolver::maxUpdate() const {
  return 16;
}

// K(F_)^-1 J_i^T stored as the next column of W; its index.
int BodySpaceSolver::newColumn(int i) {
  const int n = 6 * (int)mass_.size();
  if (wcount_ == W_.cols()) W_.conservativeResize(n, std::max<Eigen::Index>(8, 2 * W_.cols()));
  lcp::Vec g = lcp::Vec::Zero(n);
  addRowT(i, 1.0, &g);
  chol_.solve(&g);
  W_.col(wcount_) = g;
  return wcount_++;
}

// y <- K(cur_)^-1 y: the factorisation of F_, corrected by the update's low-rank term when cur_ != F_.
void BodySpaceSolver::kSolve(lcp::Vec* y) const {
  chol_.solve(y);
  if (changed_.empty()) return;
  lcp::Vec t((int)changed_.size());
  for (size_t j = 0; j < changed_.size(); ++j) t[j] = rowDot(changed_[j], *y);
  const lcp::Vec z = S_.solve(t);
  for (size_t j = 0; j < changed_.size(); ++j) *y -= z[j] * W_.col(wcol_[changed_[j]]);
}

// A_FF x = r: refined on A_FF (the Woodbury step loses about |D^-1 J| / |A| digits: residuals ~1e-7 |r| on a
// pyramid) until the residual is at round-off, 16 eps |r|, or stops falling; at most 4 times. Returns the
// residual's max norm.
double BodySpaceSolver::refinedSolve(const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) const {
  *x = woodbury(F, r);
  lcp::Vec res = r - applyFree(F, *x);
  double err = res.lpNorm<Eigen::Infinity>();
  const double floor = 16 * std::numeric_limits<double>::epsilon() * r.lpNorm<Eigen::Infinity>();
  for (int k = 0; k < 4 && err > floor; ++k) {
    const lcp::Vec cand = *x + woodbury(F, res), cres = r - applyFree(F, cand);
    const double e = cres.lpNorm<Eigen::Infinity>();
    if (!(e < err)) break;
    *x = cand, res = cres, err = e;
  }
  return err;
}

// Componentwise backward error of x (Oettli & Prager 1964): max_i |r - A_FF x|_i / (|J| |M^-1 J^T| |x| + D |x|
// + |r|)_i, the scale an upper bound of |A_FF| |x| formed matrix-free.
double BodySpaceSolver::backwardError(const std::vector<int>& F, const lcp::Vec& r, const lcp::Vec& x) const {
  const lcp::Vec res = r - applyFree(F, x);
  V6s u(mass_.size(), V6::Zero());
  for (size_t a = 0; a < F.size(); ++a) {
    const JRow& J = rows_[F[a]];
    if (J.ba >= 0) u[J.ba] += std::abs(x[a]) * J.ma.cwiseAbs();
    if (J.bb >= 0) u[J.bb] += std::abs(x[a]) * J.mb.cwiseAbs();
  }
  double worst = 0.0;
  for (size_t a = 0; a < F.size(); ++a) {
    const JRow& J = rows_[F[a]];
    double scale = reg_[F[a]] * std::abs(x[a]) + std::abs(r[a]);
    if (J.ba >= 0) scale += J.ja.cwiseAbs().dot(u[J.ba]);
    if (J.bb >= 0) scale += J.jb.cwiseAbs().dot(u[J.bb]);
    const double w = std::abs(res[a]) / scale;
    worst = std::isnan(w) ? INFINITY : std::max(worst, scale > 0 ? w : (res[a] == 0 ? 0.0 : INFINITY));
  }
  return worst;
}

bool BodySpaceSolver::solve(const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) {
  for (int i : F)
    if (!(reg_[i] > 0)) return false;
  const bool same = ok_ && F == cur_;
  const bool updated = !same && ok_ && update(F);
  if (!same && !updated && !factor(F)) return false;
  ++solves_;
  refinedSolve(F, r, x);
  // an updated factorisation whose answer is not backward stable to 1e-13 (componentwise; a fresh one reaches
  // ~1e-16) is replaced by a fresh one: the answer is as accurate as without updates
  if (!changed_.empty() && !(backwardError(F, r, *x) <= 1e-13)) {
    if (!factor(F)) return false;
    refinedSolve(F, r, x);
  }
  return x->allFinite();
}

bool bodySpaceSolve(const std::vector<JRow>& rows, const std::vector<M6>& mass, const lcp::Vec& reg,
                    const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) {
  BodySpaceSolver s(rows, mass, reg);
  return s.solve(F, r, x);
}

} // namespace suite::contact
