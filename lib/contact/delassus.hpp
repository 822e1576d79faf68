// The contact constraints of one step: one row per (contact, direction) with its Jacobian J (6 entries per
// body) and M^-1 J^T, the Delassus matrix A = J M^-1 J^T (+ reg A_ii on the diagonal, a compliance as in
// SPOOK) and b = J v* + stabilisation (normal rows: phi/dt for a gap, beta phi/dt for a penetration;
// Baumgarte). The friction formulations (friction_formulation.hpp) choose the rows and build their LCP from
// A and b; the stepper applies the impulses z of the rows: v += M^-1 J^T z.
#pragma once

#include "contact/body.hpp"
#include "contact/collision.hpp"
#include "lcp/problem.hpp"

#include <Eigen/Sparse>

#include <vector>

namespace suite::contact {

struct StepperOptions;

// A constraint row: the impulse of contact `contact` along dir (unit), a normal row or a friction row.
struct ConstraintRow {
  int contact = 0;
  Vec3 dir = Vec3::Zero();
  bool normal = true;
};

using V6 = Eigen::Matrix<double, 6, 1>;

// One constraint row: J = [ja for body ba, jb for body bb], with M^-1 J^T parts ma, mb (-1: static; its m part
// zero). Set by buildDelassus, which writes every member (the rows are rebuilt each step: no zero-fill first).
struct JRow {
  int ba = -1, bb = -1;
  V6 ja, jb, ma, mb;
};

using SpMat = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using M6 = Eigen::Matrix<double, 6, 6>;

// A dense (sparse false) or sparse in S (delassus_sparse.hpp; A left empty, denseDelassus() forms it). A
// deferred S is built by sparseMatrix() on first use (the body-space solves of the exact path need only the
// rows, the masses and reg).
struct DelassusSystem {
  std::vector<JRow> rows;
  lcp::Mat A;
  lcp::Vec b;
  bool sparse = false;
  mutable SpMat S;
  mutable bool S_deferred = false;
  int nbodies = 0;
  std::vector<M6> mass;      // sparse: the body mass matrices diag(m I, I_world) (zero for static bodies)
  lcp::Vec reg;              // sparse: the compliance part of A_ii, A_ii - (J M^-1 J^T)_ii, per row
  std::vector<double> scale; // sparse: A_ii = (1 + scale_i) (J M^-1 J^T)_ii
};

// inv_i: world inverse inertia per body (0 for static ones); vstar: velocities after the external forces.
DelassusSystem buildDelassus(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o);
// sparse: build S instead of A (the dense A only below the crossover, see StepperOptions::dense_max_rows);
// defer_S: S left to sparseMatrix().
DelassusSystem buildDelassus(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o, bool sparse,
                             bool defer_S = false);
// The sparse A of a sparse sys: sys.S, built here on the first call when deferred.
const SpMat& sparseMatrix(const DelassusSystem& sys);
// A_rr of sys (the compliance included), dense or sparse.
double delassusDiagonal(const DelassusSystem& sys, int r);
// The dense A of sys (sys.A, or formed from sys.S).
lcp::Mat denseDelassus(const DelassusSystem& sys);
// v += M^-1 J^T z, w += (M^-1 J^T z) angular part, over the rows of sys (z: one impulse per row).
void applyImpulses(const DelassusSystem& sys, const lcp::Vec& z, std::vector<Vec3>* v, std::vector<Vec3>* w);

} // namespace suite::contact
