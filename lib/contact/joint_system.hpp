// The joint constraints of one step as an exactly solved equality block of the step's MLCP, and the position
// projection that keeps the joints on their constraint manifold.
//
// Velocity level (joint rows free, eliminated exactly): with G the joint rows at q_n (joint.hpp), S = G M^-1
// G^T (+ eps S_ii, eps = 1e-12: only so that redundant rows of closed loops factorise; a row's velocity error
// from it is eps times its impulse's velocity, below 1e-12 m/s in every scene), factorised once per step by a
// sparse LDL^T (Eigen's SimplicialLDLT, AMD ordering: O(bodies) on chains and trees),
//   project(u) = u - M^-1 G^T S^-1 (G u + beta)   (the velocities nearest to u in the kinetic metric with
//                                                   G v + beta = 0).
// The bias beta is SHAKE's (Ryckaert, Ciccotti & Berendsen, J. Comput. Phys. 23 (1977) 327; here on
// symplectic Euler): the impulses G^T lambda at q_n such that the positions the step reaches, q_n + dt v, lie
// on Phi = 0, found by the chord iteration beta += Phi(q_n + dt v) / dt with the step's factorisation (each
// iteration contracts the error by O(dt |w|); an iteration that fails to halve it ends SHAKE and the step keeps
// beta = 0, which is dissipative: the projection never raises the kinetic energy). A velocity-level step alone (beta = 0) loses kinetic energy of
// order m dt v^4 / L^2 per unit time to the projection (11% of a 90-degree pendulum's swing energy in 2 s at
// dt = 1e-3, measured); with the SHAKE bias the swing energy stays within O(dt) of its start without drift.
// With contacts (unilateral N, friction D rows) the MLCP of stepper.hpp with the G block is reduced to the
// contact rows by the Schur complement: v = project(v* + M^-1 N^T z), so the contact problem has
//   A = N P N^T = N M^-1 N^T - X^T S^-1 X,  X = G M^-1 N^T,   b = N project(v*) + c,
// which correctDelassus forms (dense; only the rows of contacts on jointed bodies get a correction).
//
// Position level (post-stabilisation, Cline & Pai, "Post-stabilization for rigid body simulation with contact
// and constraints", ICRA 2003): after the positions are integrated, Newton's method on Phi(q) = 0 with the
// minimum kinetic-metric step dq = -M^-1 G(q)^T S(q)^-1 Phi(q), refactorised at each iterate (quadratic
// convergence: G is the exact Jacobian of Phi), until max |Phi| <= tol. The metric M is the bodies' masses and
// inertias, except that a jointed body heavier than 10 times the lightest jointed body counts as 10 times that
// body's mass (its inertia scaled alike): with the true ratio, 1e4 on a chain with a heavy end load falling from horizontal, the
// minimum kinetic-metric step moves only the light links, by large rotations, and the damped iteration stalled
// at max |Phi| ~ 1e-6 (measured; with the cap 4 iterations per step on average, 7 at most). Equal masses, and
// ratios up to 10, keep the kinetic metric. A velocity-level step alone drifts by
// O(dt^2 |v|^2 / L) per step; after the projection the drift is the tolerance (1e-11 by default, in m for the
// point rows and as a dot product of unit vectors for the axis rows).
#pragma once

#include "contact/delassus.hpp"
#include "contact/delassus_sparse.hpp"
#include "contact/joint.hpp"
#include "contact/joint_actuation.hpp"

#include <Eigen/SparseCholesky>

#include <vector>

namespace suite::contact {

// The LDL^T of S = G M^-1 G^T with its symbolic analysis (AMD ordering, elimination tree) kept while the
// sparsity pattern stays the same: a mechanism's pattern is the same from step to step and from one Newton
// iteration of the projection to the next, so the ordering is computed once. A copy starts empty.
class JointFactorization {
public:
  JointFactorization() = default;
  JointFactorization(const JointFactorization&) {}
  JointFactorization& operator=(const JointFactorization&) {
    outer_.clear(), inner_.clear();
    return *this;
  }
  // S: the lower triangle; false when S is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& S);
  template <class Rhs> typename Rhs::PlainObject solve(const Eigen::MatrixBase<Rhs>& r) const {
    return ldlt_.solve(r);
  }

private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  std::vector<int> outer_, inner_; // the pattern ldlt_ was analysed for
};

class JointSystem {
public:
  // The joint rows at the bodies' poses and S factorised. inv_i: world inverse inertia per body (0 static).
  // extra: equality rows with their bias after the holonomic ones (the active limits and free motors of
  // joint_actuation.hpp); SHAKE and maxError concern the holonomic rows only.
  // cache: a factorization kept by the caller across steps (its symbolic analysis reused), else the system's own.
  JointSystem(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
              const std::vector<Joint>& joints, const ActuationRows* extra = nullptr,
              JointFactorization* cache = nullptr);
  JointSystem(const JointSystem&) = delete;
  JointSystem& operator=(const JointSystem&) = delete;
  int rows() const { return (int)rows_.size(); }
  int holonomicRows() const { return holonomic_; }
  // max_k |Phi_k| at the poses the system was built at.
  double maxError() const { return max_error_; }
  // v, w <- project(v, w); lambda += the impulses of the rows (the joint impulse on the bodies is G^T lambda).
  void project(std::vector<Vec3>* v, std::vector<Vec3>* w, Eigen::VectorXd* lambda) const;
  // SHAKE: v, w (satisfying G v + beta = 0) corrected, and beta updated, until the poses of bodies advanced by
  // dt with them satisfy max |Phi| <= tol, or max_it iterations. Returns the iterations; -1 when an iterate
  // fails to halve max |Phi| (the chord iteration diverges when dt |w| is of order 1): then v, w, lambda and
  // beta are restored to the velocity step alone (beta = 0), and the position projection closes the drift.
  // A converged answer whose kinetic energy exceeds energy_bound (that of the unconstrained velocities: the
  // joint impulses do no work) is a spurious root of the SHAKE equations (a link flipped) and is refused (-1).
  int shake(const std::vector<Body>& bodies, const std::vector<Joint>& joints, double dt, double tol,
            int max_it, double energy_bound, std::vector<Vec3>* v, std::vector<Vec3>* w,
            Eigen::VectorXd* lambda);
  // The joint block's answer to a change du of the bodies' velocities (per body (v, w), as many as the system
  // was built for): the change -M^-1 G^T S^-1 G du that leaves G v as it was (the block PGS of balanced and
  // fast: joint_coupling in contact_accuracy.hpp).
  V6s respond(const V6s& du) const;
  int bodies() const { return nbodies_; }
  // Does any joint row act on body i (dynamic)?
  bool touches(int body) const { return body >= 0 && body < (int)jointed_.size() && jointed_[body]; }
  // sys.A (dense) -= X^T S^-1 X, X = G M^-1 J^T of sys's rows; sys.b: built from projected velocities already.
  // global: the global index of each of sys's bodies (an island's problem), or nullptr (the whole scene).
  void correctDelassus(DelassusSystem* sys, const std::vector<int>* global = nullptr) const;
  // The joint's first row and its count in the rows (and in lambda).
  int firstRow(int joint) const { return first_[joint]; }
  const std::vector<JRow>& jacobian() const { return rows_; }
  bool ok() const { return ok_; }

private:
  Eigen::VectorXd solveRefined(const Eigen::VectorXd& r, V6s* du) const;
  int nbodies_ = 0;
  std::vector<JRow> rows_;
  std::vector<int> first_;
  std::vector<char> jointed_;
  double max_error_ = 0.0;
  int holonomic_ = 0;
  Eigen::VectorXd bias_, base_bias_; // base: the extra rows' bias (zero on the holonomic rows)
  const JointFactorization& factorization() const { return factor_ ? *factor_ : own_; }
  JointFactorization& factorization() { return factor_ ? *factor_ : own_; }
  JointFactorization own_;
  JointFactorization* factor_ = nullptr; // the caller's, when given
  bool ok_ = true;
};

// The joint rows as JRows (static bodies and the world as -1) with their M^-1 J^T parts, and Phi per row.
void jointJacobian(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                   const std::vector<Joint>& joints, std::vector<JRow>* rows, std::vector<double>* phi,
                   std::vector<int>* first);

// The kinetic energy of the dynamic bodies at velocities v, w.
double kineticEnergy(const std::vector<Body>& bodies, const std::vector<Vec3>& v, const std::vector<Vec3>& w);

// max_k |Phi_k| of the joints at the bodies' poses.
double maxError(const std::vector<Body>& bodies, const std::vector<Joint>& joints);

// Post-stabilisation: Newton on Phi(q) = 0 (above) until max |Phi| <= tol or max_it iterations. Returns the
// iterations taken; *error: max |Phi| at the end (> tol: not converged).
// cache: as JointSystem's.
int projectPositions(const std::vector<Joint>& joints, double tol, int max_it, std::vector<Body>* bodies,
                     double* error, JointFactorization* cache = nullptr);

} // namespace suite::contact
