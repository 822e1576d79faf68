// Block projected Gauss-Seidel over contact manifolds (see block_pgs.hpp).
#include "contact/block_pgs.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <array>
#include <type_traits>

namespace suite::contact {

namespace {
// Fixed-capacity storage (no allocation per block update): a box-box manifold has at most 8 points.
constexpr int kMax = 16;
using MatX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax>;
using VecX = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
using JX = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor, kMax, 6>;

// Proximal weight of a block update (relative to D's diagonal): the corners' rows are nearly dependent (D
// singular up to the 1e-6 / 1e-8 compliance), so the plain block answer can carry large self-equilibrated
// parts; (D + P) x = P z0 - q has the same fixed point (x = z0 where D z0 + q = 0) and stays near z0.
// Measured on the base-10 pyramid (fast mode): 1e-4 .. 1e-1 all stand, 1e-2 the least work.
constexpr double kProx = 1e-2;
// The inverse of a small symmetric positive definite matrix (Cholesky D = L L^T, then L^-T L^-1), written out
// on plain arrays: Eigen's general small-matrix paths cost more than the arithmetic at m <= 16. M: the size
// when known at compile time (the loops unrolled; a box face's 4 and 8 rows), else Eigen::Dynamic.
template <int M> void spdInverseSized(const MatX& D, MatX* out) {
  const int m = M == Eigen::Dynamic ? (int)D.rows() : M;
  double L[kMax][kMax], Li[kMax][kMax], inv_diag[kMax]; // inv_diag = 1 / L_jj: one division per row
  for (int j = 0; j < m; ++j) {
    double d = D(j, j);
    for (int k = 0; k < j; ++k) d -= L[j][k] * L[j][k];
    L[j][j] = std::sqrt(d);
    inv_diag[j] = 1.0 / L[j][j];
    for (int i = j + 1; i < m; ++i) {
      double s = D(i, j);
      for (int k = 0; k < j; ++k) s -= L[i][k] * L[j][k];
      L[i][j] = s * inv_diag[j];
    }
  }
  for (int j = 0; j < m; ++j) { // Li = L^-1 (lower), column by column
    Li[j][j] = inv_diag[j];
    for (int i = j + 1; i < m; ++i) {
      double s = 0.0;
      for (int k = j; k < i; ++k) s -= L[i][k] * Li[k][j];
      Li[i][j] = s * inv_diag[i];
    }
  }
  out->resize(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = 0.0;
      for (int k = i; k < m; ++k) s += Li[k][i] * Li[k][j];
      (*out)(i, j) = (*out)(j, i) = s;
    }
}

void spdInverse(const MatX& D, MatX* out) {
  if (D.rows() == 4) return spdInverseSized<4>(D, out);
  if (D.rows() == 8) return spdInverseSized<8>(D, out);
  spdInverseSized<Eigen::Dynamic>(D, out);
}

// One group of rows solved together, all between the same two bodies ba, bb (-1: static): the rows' J and
// M^-1 J^T parts at each body stacked (Ja, Ma, Jb, Mb: m x 6), so that the block's row velocities are
// Ja u_a + Jb u_b and its impulses move the bodies by Ma^T dz, Mb^T dz; D = Ja Ma^T + Jb Mb^T + diag(reg)
// (the rows share no other body), Dp = D + P, Dp^-1. Fixed capacity throughout: the blocks are kept from step
// to step (blockPgsSweeps), so a step allocates nothing for them.
struct Block {
  int m = 0, ba = -1, bb = -1;
  std::array<int, kMax> rows;
  JX Ja, Jb, Ma, Mb;
  VecX reg, b;
  MatX D, Dp, Dpinv; // Dp = D + kProx diag(D): the proximal term
  void build(const SparseBoxLcp& p) {
    if (m == 0) return;
    ba = (*p.rows)[rows[0]].ba, bb = (*p.rows)[rows[0]].bb;
    Ja.resize(m, 6), Jb.resize(m, 6), Ma.resize(m, 6), Mb.resize(m, 6), reg.resize(m), b.resize(m);
    for (int a = 0; a < m; ++a) {
      const JRow& R = (*p.rows)[rows[a]];
      Ja.row(a) = R.ja.transpose(), Jb.row(a) = R.jb.transpose();
      Ma.row(a) = R.ma.transpose(), Mb.row(a) = R.mb.transpose();
      reg[a] = p.reg[rows[a]], b[a] = p.b[rows[a]];
    }
    D.resize(m, m);
    for (int a = 0; a < m; ++a)
      for (int c = a; c < m; ++c) {
        double v = a == c ? reg[a] : 0.0;
        if (ba >= 0) v += Ja.row(a).dot(Ma.row(c));
        if (bb >= 0) v += Jb.row(a).dot(Mb.row(c));
        D(a, c) = D(c, a) = v;
      }
    Dp = D;
    Dp.diagonal() *= 1.0 + kProx;
    spdInverse(Dp, &Dpinv); // applied many times per step
  }
  void add(int row) { rows[m++] = row; }
  void readB(const SparseBoxLcp& p) {
    for (int a = 0; a < m; ++a) b[a] = p.b[rows[a]];
  }
};

struct Manifold {
  Block normal, tangent;
  int first = 0; // the position of its first contact in the sweep order
};

// Inner PGS iterations of a block whose proximal answer leaves its bounds (the outer sweeps go on from there):
// 2 and 5 stand the same, 20 costs twice the time (base-10 pyramid, fast mode).
constexpr int kInner = 2;

// One proximal block step on the block's rows (the other rows fixed); u and z updated. Returns the largest
// change of the block's row velocities it made. M: the block's size when known at compile time (a box face on
// a box face: 4 normal rows, 8 tangent rows; unrolled fixed-size products), else Eigen::Dynamic.
template <int M> double solveBlockSized(const SparseBoxLcp& p, const Block& blk, V6s* u, lcp::Vec* z) {
  using Vec = std::conditional_t<M == Eigen::Dynamic, VecX, Eigen::Matrix<double, M, 1>>;
  using Mat = std::conditional_t<M == Eigen::Dynamic, MatX, Eigen::Matrix<double, M, M>>;
  using Jm = std::conditional_t<M == Eigen::Dynamic, JX, Eigen::Matrix<double, M, 6, Eigen::RowMajor>>;
  const int m = blk.m;
  const Eigen::Map<const Mat> D(blk.D.data(), m, m), Dp(blk.Dp.data(), m, m), Dpinv(blk.Dpinv.data(), m, m);
  const Eigen::Map<const Jm> Ja(blk.Ja.data(), m, 6), Jb(blk.Jb.data(), m, 6), Ma(blk.Ma.data(), m, 6),
      Mb(blk.Mb.data(), m, 6);
  const Eigen::Map<const Vec> reg(blk.reg.data(), m), b(blk.b.data(), m);
  Vec z0, lo, hi;
  if constexpr (M == Eigen::Dynamic) z0.resize(m), lo.resize(m), hi.resize(m);
  for (int a = 0; a < m; ++a) {
    const int r = blk.rows[a];
    z0[a] = (*z)[r];
    lo[a] = p.lower(r, *z), hi[a] = p.upper(r, *z);
  }
  Vec w = reg.cwiseProduct(z0) + b; // the block's row velocities
  if (blk.ba >= 0) w.noalias() += Ja.lazyProduct((*u)[blk.ba]);
  if (blk.bb >= 0) w.noalias() += Jb.lazyProduct((*u)[blk.bb]);
  // proximal step (D + P) x = P z0 - q with w = D z0 + q: x = z0 - (D + P)^-1 w; fixed point w = 0
  Vec x = z0 - Dpinv.lazyProduct(w); // coefficient-wise: no general gemv at these sizes
  bool inside = x.allFinite();
  for (int a = 0; inside && a < m; ++a) inside = x[a] >= lo[a] && x[a] <= hi[a];
  if (!inside) { // inner PGS on (D + P) x = P z0 - q = Dp z0 - w
    const Vec r = Dp.lazyProduct(z0) - w;
    x = z0.cwiseMax(lo).cwiseMin(hi);
    for (int it = 0; it < kInner; ++it)
      for (int a = 0; a < m; ++a)
        if (Dp(a, a) > 0) x[a] = std::clamp(x[a] - (Dp.row(a).dot(x) - r[a]) / Dp(a, a), lo[a], hi[a]);
  }
  const Vec dz = x - z0;
  if (blk.ba >= 0) (*u)[blk.ba].noalias() += Ma.transpose().lazyProduct(dz);
  if (blk.bb >= 0) (*u)[blk.bb].noalias() += Mb.transpose().lazyProduct(dz);
  for (int a = 0; a < m; ++a) (*z)[blk.rows[a]] = x[a];
  // the change of the block's row velocities, D dz (a move along the corners' near-dependent directions, which
  // changes no velocity, does not count)
  return D.lazyProduct(dz).template lpNorm<Eigen::Infinity>();
}

double solveBlock(const SparseBoxLcp& p, const Block& blk, V6s* u, lcp::Vec* z) {
  switch (blk.m) {
  case 0:
    return 0.0;
  case 4:
    return solveBlockSized<4>(p, blk, u, z);
  case 8:
    return solveBlockSized<8>(p, blk, u, z);
  default:
    return solveBlockSized<Eigen::Dynamic>(p, blk, u, z);
  }
}

// The manifolds of cs (contacts grouped by body pair, a new block when one is full; active rows only) into
// *out, reused: their number returned, *seq their sweep order (by their first contact's place in p.order).
int manifolds(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per, std::vector<Manifold>* out,
              std::vector<int>* seq) {
  std::vector<std::array<int, 4>> key; // (a, b, place in the sweep order, contact), sorted by pair then place
  key.reserve(p.size() / per);
  auto visit = [&](int r) {
    if (r % per == 0) key.push_back({cs[r / per].a, cs[r / per].b, (int)key.size(), r / per});
  };
  if (p.order.empty())
    for (int i = 0; i < p.size(); ++i) visit(i);
  else
    for (int r : p.order) visit(r);
  std::sort(key.begin(), key.end());
  int n = 0;
  for (size_t k = 0; k < key.size(); ++k) {
    const bool same_pair = k > 0 && key[k][0] == key[k - 1][0] && key[k][1] == key[k - 1][1];
    if (!same_pair || (*out)[n - 1].tangent.m + per > kMax) {
      if (n == (int)out->size()) out->emplace_back();
      Manifold& mf = (*out)[n++];
      mf.normal.m = mf.tangent.m = 0, mf.first = key[k][2];
    }
    Manifold& cur = (*out)[n - 1];
    for (int j = 0, c = key[k][3]; j < per; ++j)
      if (p.active(c * per + j)) (j == 0 ? cur.normal : cur.tangent).add(c * per + j);
  }
  seq->resize(n);
  for (int k = 0; k < n; ++k) (*seq)[k] = k, (*out)[k].normal.build(p), (*out)[k].tangent.build(p);
  std::sort(seq->begin(), seq->end(), [&](int a, int b) { return (*out)[a].first < (*out)[b].first; });
  return n;
}
} // namespace

int blockPgsSweeps(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per, int max_sweeps, double tol,
                   lcp::Vec* z, const std::function<double(const lcp::Vec&)>* before_sweep) {
  // the manifolds' fixed-capacity blocks (4 kB of matrices each) kept from call to call on this thread
  thread_local std::vector<Manifold> mfs;
  thread_local std::vector<int> seq;
  const int n = manifolds(p, cs, per, &mfs, &seq);
  V6s u = bodyImpulseVelocities(*p.rows, *z, p.nbodies);
  int sweep = 0;
  for (double change = lcp::kInf; sweep < max_sweeps && !(change <= tol); ++sweep) {
    change = 0.0;
    if (before_sweep) {
      change = (*before_sweep)(*z);
      for (int k = 0; k < n; ++k) mfs[k].normal.readB(p), mfs[k].tangent.readB(p);
    }
    for (int k = 0; k < n; ++k) {
      const Manifold& mf = mfs[seq[p.symmetric && sweep % 2 ? n - 1 - k : k]];
      change = std::max(change, solveBlock(p, mf.normal, &u, z));
      change = std::max(change, solveBlock(p, mf.tangent, &u, z));
    }
  }
  return sweep;
}

} // namespace suite::contact
