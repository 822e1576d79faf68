// Block projected Gauss-Seidel over contact manifolds (see block_pgs.hpp).
#include "contact/block_pgs.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace suite::contact {

namespace {
// Fixed-capacity storage (no allocation per block update): a box-box manifold has at most 8 points.
constexpr int kMax = 16;
using MatX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax>;
using VecX = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;

// Proximal weight of a block update (relative to D's diagonal): the corners' rows are nearly dependent (D
// singular up to the 1e-6 / 1e-8 compliance), so the plain block answer can carry large self-equilibrated
// parts; (D + P) x = P z0 - q has the same fixed point (x = z0 where D z0 + q = 0) and stays near z0.
// Measured on the base-10 pyramid (fast mode): 1e-4 .. 1e-1 all stand, 1e-2 the least work.
constexpr double kProx = 1e-2;
// The inverse of a small symmetric positive definite matrix (Cholesky D = L L^T, then L^-T L^-1), written out:
// Eigen's general small-matrix paths cost more than the arithmetic at m <= 16.
MatX spdInverse(const MatX& D) {
  const int m = (int)D.rows();
  MatX L = MatX::Zero(m, m), Li = MatX::Zero(m, m), out(m, m);
  for (int j = 0; j < m; ++j) {
    double d = D(j, j);
    for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    L(j, j) = std::sqrt(d);
    for (int i = j + 1; i < m; ++i) {
      double s = D(i, j);
      for (int k = 0; k < j; ++k) s -= L(i, k) * L(j, k);
      L(i, j) = s / L(j, j);
    }
  }
  for (int j = 0; j < m; ++j) { // Li = L^-1 (lower), column by column
    Li(j, j) = 1.0 / L(j, j);
    for (int i = j + 1; i < m; ++i) {
      double s = 0.0;
      for (int k = j; k < i; ++k) s -= L(i, k) * Li(k, j);
      Li(i, j) = s / L(i, i);
    }
  }
  for (int i = 0; i < m; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = 0.0;
      for (int k = i; k < m; ++k) s += Li(k, i) * Li(k, j);
      out(i, j) = out(j, i) = s;
    }
  return out;
}

// One group of rows solved together: D (regularised), its LDL^T.
struct Block {
  std::vector<int> rows;
  MatX D, Dp, Dpinv; // Dp = D + kProx diag(D): the proximal term
  void build(const SparseBoxLcp& p) {
    const int m = (int)rows.size();
    D.resize(m, m);
    for (int a = 0; a < m; ++a) {
      D(a, a) = rowCoupling((*p.rows)[rows[a]], (*p.rows)[rows[a]]) + p.reg[rows[a]];
      for (int b = a + 1; b < m; ++b) D(a, b) = D(b, a) = rowCoupling((*p.rows)[rows[a]], (*p.rows)[rows[b]]);
    }
    Dp = D;
    Dp.diagonal() *= 1.0 + kProx;
    Dpinv = spdInverse(Dp); // applied many times per step
  }
};

struct Manifold {
  Block normal, tangent;
};

// Inner PGS iterations of a block whose proximal answer leaves its bounds (the outer sweeps go on from there):
// 2 and 5 stand the same, 20 costs twice the time (base-10 pyramid, fast mode).
constexpr int kInner = 2;

// One proximal block step on the block's rows (the other rows fixed); u and z updated. Returns the largest
// change of the block's row velocities it made.
double solveBlock(const SparseBoxLcp& p, const Block& blk, V6s* u, lcp::Vec* z) {
  const int m = (int)blk.rows.size();
  if (m == 0) return 0.0;
  VecX z0(m), w(m), lo(m), hi(m);
  for (int a = 0; a < m; ++a) {
    const int r = blk.rows[a];
    z0[a] = (*z)[r];
    lo[a] = p.lower(r, *z), hi[a] = p.upper(r, *z);
    w[a] = rowVelocity((*p.rows)[r], *u) + p.reg[r] * z0[a] + p.b[r];
  }
  // proximal step (D + P) x = P z0 - q with w = D z0 + q: x = z0 - (D + P)^-1 w; fixed point w = 0
  VecX x = z0 - blk.Dpinv * w;
  bool inside = x.allFinite();
  for (int a = 0; inside && a < m; ++a) inside = x[a] >= lo[a] && x[a] <= hi[a];
  if (!inside) { // inner PGS on (D + P) x = P z0 - q = Dp z0 - w
    const VecX r = blk.Dp * z0 - w;
    x = z0.cwiseMax(lo).cwiseMin(hi);
    for (int it = 0; it < kInner; ++it)
      for (int a = 0; a < m; ++a)
        if (blk.Dp(a, a) > 0)
          x[a] = std::clamp(x[a] - (blk.Dp.row(a).dot(x) - r[a]) / blk.Dp(a, a), lo[a], hi[a]);
  }
  const VecX dz = x - z0;
  for (int a = 0; a < m; ++a) {
    if (dz[a] == 0.0) continue;
    addRowImpulse((*p.rows)[blk.rows[a]], dz[a], u);
    (*z)[blk.rows[a]] = x[a];
  }
  // the change of the block's row velocities, D dz (a move along the corners' near-dependent directions, which
  // changes no velocity, does not count)
  return (blk.D * dz).lpNorm<Eigen::Infinity>();
}

// The manifolds of cs (contacts grouped by body pair) in the order of p.order; active rows only.
std::vector<Manifold> manifolds(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per) {
  std::map<std::pair<int, int>, int> index;
  std::vector<Manifold> out;
  std::vector<int> order = p.order;
  if (order.empty())
    for (int i = 0; i < p.size(); ++i) order.push_back(i);
  for (int r : order) {
    if (r % per != 0) continue; // one visit per contact, at its normal row
    const int c = r / per;
    const auto [it, fresh] = index.try_emplace({cs[c].a, cs[c].b}, (int)out.size());
    if (fresh) out.emplace_back();
    if ((int)out[it->second].tangent.rows.size() + per >
        kMax) { // an oversized manifold goes on in a new block
      index[{cs[c].a, cs[c].b}] = (int)out.size();
      out.emplace_back();
    }
    Manifold& cur = out[index[{cs[c].a, cs[c].b}]];
    for (int k = 0; k < per; ++k)
      if (p.active(c * per + k)) (k == 0 ? cur.normal : cur.tangent).rows.push_back(c * per + k);
  }
  for (Manifold& mf : out) mf.normal.build(p), mf.tangent.build(p);
  return out;
}
} // namespace

int blockPgsSweeps(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per, int max_sweeps, double tol,
                   lcp::Vec* z) {
  const std::vector<Manifold> mfs = manifolds(p, cs, per);
  V6s u = bodyImpulseVelocities(*p.rows, *z, p.nbodies);
  const int n = (int)mfs.size();
  int sweep = 0;
  for (double change = lcp::kInf; sweep < max_sweeps && !(change <= tol); ++sweep) {
    change = 0.0;
    for (int k = 0; k < n; ++k) {
      const Manifold& mf = mfs[p.symmetric && sweep % 2 ? n - 1 - k : k];
      change = std::max(change, solveBlock(p, mf.normal, &u, z));
      change = std::max(change, solveBlock(p, mf.tangent, &u, z));
    }
  }
  return sweep;
}

} // namespace suite::contact
