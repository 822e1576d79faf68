// The Delassus matrix A = J M^-1 J^T (+ reg A_ii on the diagonal) of the contact rows (delassus.hpp) built
// sparse: a row couples only with the rows that share a body with it, so A has at most 6 (rows per contact
// pair) x (rows of the contacts of its two bodies) entries per row (Erleben, "Stable, robust and versatile
// multibody dynamics animation", PhD thesis, Copenhagen 2005, ch. 6: the block-sparse contact matrix).
// Built in O(sum over bodies of (rows at the body)^2) time and memory instead of O(rows^2).
// Also the matrix-free operator w = A z + b through J and M^-1 (per body u = M^-1 J^T z, w_i = J_i u + D_i
// z_i + b_i: O(rows) per product), as in the sequential-impulse solvers (Catto, GDC 2005).
#pragma once

#include "contact/delassus.hpp"

#include <vector>

namespace suite::contact {

using V6s = std::vector<V6>;

// A = J M^-1 J^T of the rows, then A_ii *= 1 + diag_scale[i] (the compliance of delassus.hpp). nbodies: the
// number of bodies (the body indices of the rows are below it).
SpMat sparseDelassus(const std::vector<JRow>& rows, int nbodies, const std::vector<double>& diag_scale);
// Its entries as triplets; lower: the lower triangle only (what a symmetric LDL^T reads).
std::vector<Eigen::Triplet<double>> delassusTriplets(const std::vector<JRow>& rows, int nbodies,
                                                     const std::vector<double>& diag_scale, bool lower);

// A_rq = (J M^-1 J^T)_rq of two rows: the contributions of the bodies they share (no compliance).
double rowCoupling(const JRow& R, const JRow& Q);
// u = M^-1 J^T z per body (6-vectors: linear, angular), over nbodies bodies.
V6s bodyImpulseVelocities(const std::vector<JRow>& rows, const lcp::Vec& z, int nbodies);
// J_i u of row i.
inline double rowVelocity(const JRow& J, const V6s& u) {
  double s = 0.0;
  if (J.ba >= 0) s += J.ja.dot(u[J.ba]);
  if (J.bb >= 0) s += J.jb.dot(u[J.bb]);
  return s;
}
// u += M^-1 J_i^T dz.
inline void addRowImpulse(const JRow& J, double dz, V6s* u) {
  if (J.ba >= 0) (*u)[J.ba] += J.ma * dz;
  if (J.bb >= 0) (*u)[J.bb] += J.mb * dz;
}

} // namespace suite::contact
