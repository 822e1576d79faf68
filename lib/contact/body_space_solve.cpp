// Body-space solve of the free contact rows (see body_space_solve.hpp).
#include "contact/body_space_solve.hpp"

#include "contact/delassus_sparse.hpp"

#include <Eigen/SparseCholesky>

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

namespace {
// K = M + J_F^T D_F^-1 J_F as 6 x 6 blocks: the diagonal ones per body, the others per body pair (a < b);
// static bodies get the identity (no row touches them).
Eigen::SparseMatrix<double> bodyMatrix(const std::vector<JRow>& rows, const std::vector<M6>& mass,
                                       const lcp::Vec& reg, const std::vector<int>& F) {
  std::vector<M6> diag = mass;
  std::map<std::pair<int, int>, M6> off;
  for (int i : F) {
    const JRow& J = rows[i];
    const double s = 1.0 / reg[i];
    if (J.ba >= 0) diag[J.ba] += s * J.ja * J.ja.transpose();
    if (J.bb >= 0) diag[J.bb] += s * J.jb * J.jb.transpose();
    if (J.ba >= 0 && J.bb >= 0) {
      const bool ab = J.ba < J.bb;
      auto it = off.emplace(ab ? std::make_pair(J.ba, J.bb) : std::make_pair(J.bb, J.ba), M6::Zero()).first;
      it->second += s * (ab ? J.ja * J.jb.transpose() : J.jb * J.ja.transpose());
    }
  }
  std::vector<Eigen::Triplet<double>> t;
  auto block = [&t](int a, int b, const M6& B) {
    for (int c = 0; c < 6; ++c)
      for (int r = 0; r < 6; ++r) t.emplace_back(6 * a + r, 6 * b + c, B(r, c));
  };
  for (size_t b = 0; b < diag.size(); ++b) block((int)b, (int)b, mass[b].isZero() ? M6::Identity() : diag[b]);
  for (const auto& [ab, B] : off) block(ab.first, ab.second, B), block(ab.second, ab.first, B.transpose());
  Eigen::SparseMatrix<double> K(6 * diag.size(), 6 * diag.size());
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// A_FF x (matrix-free: u = M^-1 J_F^T x per body, then J_i u + D_i x_i).
lcp::Vec applyFree(const std::vector<JRow>& rows, const lcp::Vec& reg, const std::vector<int>& F,
                   const lcp::Vec& x, int nbodies) {
  V6s u(nbodies, V6::Zero());
  for (size_t a = 0; a < F.size(); ++a) addRowImpulse(rows[F[a]], x[a], &u);
  lcp::Vec y(F.size());
  for (size_t a = 0; a < F.size(); ++a) y[a] = rowVelocity(rows[F[a]], u) + reg[F[a]] * x[a];
  return y;
}
} // namespace

bool bodySpaceSolve(const std::vector<JRow>& rows, const std::vector<M6>& mass, const lcp::Vec& reg,
                    const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) {
  for (int i : F)
    if (!(reg[i] > 0)) return false;
  const int nb = (int)mass.size();
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(bodyMatrix(rows, mass, reg, F));
  if (llt.info() != Eigen::Success) return false;
  auto solve = [&](const lcp::Vec& rhs) { // A_FF^-1 rhs by the Woodbury identity
    lcp::Vec g = lcp::Vec::Zero(6 * nb), out(F.size());
    for (size_t a = 0; a < F.size(); ++a) {
      const JRow& J = rows[F[a]];
      const double s = rhs[a] / reg[F[a]];
      if (J.ba >= 0) g.segment<6>(6 * J.ba) += s * J.ja;
      if (J.bb >= 0) g.segment<6>(6 * J.bb) += s * J.jb;
    }
    const lcp::Vec y = llt.solve(g);
    for (size_t a = 0; a < F.size(); ++a) {
      const JRow& J = rows[F[a]];
      double jy = 0.0;
      if (J.ba >= 0) jy += J.ja.dot(y.segment<6>(6 * J.ba));
      if (J.bb >= 0) jy += J.jb.dot(y.segment<6>(6 * J.bb));
      out[a] = (rhs[a] - jy) / reg[F[a]];
    }
    return out;
  };
  *x = solve(r);
  double err = (r - applyFree(rows, reg, F, *x, nb)).lpNorm<Eigen::Infinity>();
  for (int k = 0; k < 4; ++k) {
    const lcp::Vec cand = *x + solve(r - applyFree(rows, reg, F, *x, nb));
    const double e = (r - applyFree(rows, reg, F, cand, nb)).lpNorm<Eigen::Infinity>();
    if (!(e < err)) break;
    *x = cand, err = e;
  }
  return x->allFinite();
}

} // namespace suite::contact
