// The joint block of the step's MLCP and the position projection (see joint_system.hpp).
#include "contact/joint_system.hpp"

#include "contact/delassus_sparse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace suite::contact {

namespace {
constexpr double kJointCompliance = 1e-12; // relative, on S_ii (joint_system.hpp)
// SHAKE's chord iteration is kept while each iterate at least halves max |Phi| (joint_system.hpp)
constexpr double kShakeContraction = 0.5;
constexpr double kMinNewtonStep = 1.0 / 1024; // the line search's last step
constexpr double kMetricMassRatio = 10.0; // the projection's metric: mass ratios capped (joint_system.hpp)
constexpr double kInfinity = std::numeric_limits<double>::infinity();

V6 invMassTimes(const Body& B, const Mat3& inv_i, const V6& j) {
  V6 m;
  m.head<3>() = B.inv_mass * j.head<3>();
  m.tail<3>() = inv_i * j.tail<3>();
  return m;
}

std::vector<Mat3> worldInverseInertia(const std::vector<Body>& bodies) {
  std::vector<Mat3> inv_i(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i)
    inv_i[i] = bodies[i].is_static ? Mat3::Zero() : bodies[i].invInertiaWorld();
  return inv_i;
}

// The lower triangle of S = G M^-1 G^T (+ the compliance), column-major: what the LDL^T reads (Lower).
Eigen::SparseMatrix<double> jointMatrix(const std::vector<JRow>& rows, int nbodies) {
  const std::vector<double> scale(rows.size(), kJointCompliance);
  const auto t = delassusTriplets(rows, nbodies, scale, true);
  Eigen::SparseMatrix<double> S((Eigen::Index)rows.size(), (Eigen::Index)rows.size());
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

// The step dq = M^-1 G^T mu applied to the poses: x += dx, q <- exp(dtheta) q.
void moveBodies(const V6s& dq, std::vector<Body>* bodies) {
  for (size_t i = 0; i < bodies->size(); ++i) {
    Body& B = (*bodies)[i];
    if (B.is_static) continue;
    B.x += dq[i].head<3>();
    const Vec3 th = dq[i].tail<3>();
    const double ang = th.norm();
    if (ang > 0) B.q = (Quat(Eigen::AngleAxisd(ang, th / ang)) * B.q).normalized();
  }
}

double maxAbs(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}
} // namespace

double kineticEnergy(const std::vector<Body>& bodies, const std::vector<Vec3>& v,
                     const std::vector<Vec3>& w) {
  double e = 0.0;
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].is_static)
      e += 0.5 * (bodies[i].mass * v[i].squaredNorm() + w[i].dot(bodies[i].inertiaWorld() * w[i]));
  return e;
}

double maxError(const std::vector<Body>& bodies, const std::vector<Joint>& joints) {
  std::vector<JointRow> jr;
  double e = 0.0;
  for (const Joint& j : joints) {
    jr.clear();
    jointRows(j, bodies, &jr);
    for (const JointRow& r : jr) e = std::max(e, std::abs(r.phi));
  }
  return e;
}

void jointJacobian(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                   const std::vector<Joint>& joints, std::vector<JRow>* rows, std::vector<double>* phi,
                   std::vector<int>* first) {
  rows->clear();
  phi->clear();
  first->clear();
  std::vector<JointRow> jr;
  for (const Joint& j : joints) {
    first->push_back((int)rows->size());
    jr.clear();
    jointRows(j, bodies, &jr);
    const bool a_dyn = !bodies[j.a].is_static, b_dyn = j.b >= 0 && !bodies[j.b].is_static;
    for (const JointRow& r : jr) {
      JRow J;
      J.ja = r.ja;
      J.jb = r.jb;
      J.ba = a_dyn ? j.a : -1;
      J.bb = b_dyn ? j.b : -1;
      J.ma = a_dyn ? invMassTimes(bodies[j.a], inv_i[j.a], r.ja) : V6::Zero().eval();
      J.mb = b_dyn ? invMassTimes(bodies[j.b], inv_i[j.b], r.jb) : V6::Zero().eval();
      rows->push_back(J);
      phi->push_back(r.phi);
    }
  }
}

bool JointFactorization::factorize(const Eigen::SparseMatrix<double>& S) {
  const int n = (int)S.cols(), nnz = (int)S.nonZeros();
  const bool same = n == (int)outer_.size() - 1 && nnz == (int)inner_.size() &&
                    std::equal(outer_.begin(), outer_.end(), S.outerIndexPtr()) &&
                    std::equal(inner_.begin(), inner_.end(), S.innerIndexPtr());
  if (!same) {
    ldlt_.analyzePattern(S);
    outer_.assign(S.outerIndexPtr(), S.outerIndexPtr() + n + 1);
    inner_.assign(S.innerIndexPtr(), S.innerIndexPtr() + nnz);
  }
  ldlt_.factorize(S);
  return ldlt_.info() == Eigen::Success;
}

JointSystem::JointSystem(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                         const std::vector<Joint>& joints, const ActuationRows* extra,
                         JointFactorization* cache) {
  std::vector<double> phi;
  jointJacobian(bodies, inv_i, joints, &rows_, &phi, &first_);
  max_error_ = maxAbs(phi);
  holonomic_ = (int)rows_.size();
  if (extra) rows_.insert(rows_.end(), extra->rows.begin(), extra->rows.end());
  nbodies_ = (int)bodies.size();
  jointed_.assign(bodies.size(), 0);
  for (const JRow& J : rows_) {
    if (J.ba >= 0) jointed_[J.ba] = 1;
    if (J.bb >= 0) jointed_[J.bb] = 1;
  }
  base_bias_ = Eigen::VectorXd::Zero(rows());
  for (int k = holonomic_; k < rows(); ++k) base_bias_[k] = extra->bias[k - holonomic_];
  bias_ = base_bias_;
  if (rows_.empty()) return;
  if (cache) factor_ = cache;
  ok_ = factorization().factorize(jointMatrix(rows_, (int)bodies.size()));
}

// mu = S^-1 r with one step of iterative refinement against S without the compliance (the compliance's
// relative impulse error eps cond(S), 2e-7 on a chain with a 1e4 end load, becomes (eps cond(S))^2); du: the
// body velocities M^-1 G^T mu.
Eigen::VectorXd JointSystem::solveRefined(const Eigen::VectorXd& r, V6s* du) const {
  Eigen::VectorXd mu = factorization().solve(r);
  *du = bodyImpulseVelocities(rows_, mu, nbodies_);
  Eigen::VectorXd res(rows());
  for (int k = 0; k < rows(); ++k) res[k] = r[k] - rowVelocity(rows_[k], *du);
  mu += factorization().solve(res);
  *du = bodyImpulseVelocities(rows_, mu, nbodies_);
  return mu;
}

void JointSystem::project(std::vector<Vec3>* v, std::vector<Vec3>* w, Eigen::VectorXd* lambda) const {
  const int m = rows();
  if (m == 0) return;
  Eigen::VectorXd r(m);
  for (int k = 0; k < m; ++k) { // -G u
    const JRow& J = rows_[k];
    double s = 0.0;
    if (J.ba >= 0) s += J.ja.head<3>().dot((*v)[J.ba]) + J.ja.tail<3>().dot((*w)[J.ba]);
    if (J.bb >= 0) s += J.jb.head<3>().dot((*v)[J.bb]) + J.jb.tail<3>().dot((*w)[J.bb]);
    r[k] = -s - bias_[k];
  }
  V6s du;
  const Eigen::VectorXd mu = solveRefined(r, &du);
  for (size_t i = 0; i < v->size(); ++i) (*v)[i] += du[i].head<3>(), (*w)[i] += du[i].tail<3>();
  if (lambda->size() != m) *lambda = Eigen::VectorXd::Zero(m);
  *lambda += mu;
}

V6s JointSystem::respond(const V6s& du) const {
  V6s out(nbodies_, V6::Zero());
  if (rows() == 0) return out;
  Eigen::VectorXd r(rows());
  for (int k = 0; k < rows(); ++k) r[k] = -rowVelocity(rows_[k], du);
  solveRefined(r, &out);
  return out;
}

int JointSystem::shake(const std::vector<Body>& bodies, const std::vector<Joint>& joints, double dt,
                       double tol, int max_it, double energy_bound, std::vector<Vec3>* v,
                       std::vector<Vec3>* w, Eigen::VectorXd* lambda) {
  std::vector<Body> next = bodies;
  std::vector<JRow> rows;
  std::vector<double> phi;
  std::vector<int> first;
  const std::vector<Mat3> none(bodies.size(), Mat3::Zero()); // Phi only: the M^-1 parts are not used
  const std::vector<Vec3> v0 = *v, w0 = *w;
  const Eigen::VectorXd lambda0 = *lambda;
  double last = kInfinity;
  int it = 0;
  for (; it < max_it; ++it) {
    for (size_t i = 0; i < next.size(); ++i) {
      next[i].x = bodies[i].x, next[i].q = bodies[i].q;
      if (!next[i].is_static) advancePose(&next[i], (*v)[i], (*w)[i], dt);
    }
    jointJacobian(next, none, joints, &rows, &phi, &first);
    const double err = maxAbs(phi);
    if (err <= tol && kineticEnergy(bodies, *v, *w) <= energy_bound) break;
    if (err <= tol || !(err < kShakeContraction * last) || it + 1 == max_it) { // a spurious root (energy),
      // not contracting, or not converged: the velocity step alone
      *v = v0, *w = w0, *lambda = lambda0;
      bias_ = base_bias_;
      return -1;
    }
    last = err;
    // G v + beta = 0 holds: the new bias changes it by Phi / dt, which project removes
    for (int k = 0; k < holonomic_; ++k) bias_[k] += phi[k] / dt;
    project(v, w, lambda);
  }
  return it;
}

void JointSystem::correctDelassus(DelassusSystem* sys, const std::vector<int>* global) const {
  const int m = rows(), n = (int)sys->rows.size();
  auto to_global = [&](int b) { return b < 0 || !global ? b : (*global)[b]; };
  std::vector<int> cols;   // the contact rows on jointed bodies: the others have X = 0
  std::vector<JRow> jcols; // ... with global body indices
  for (int r = 0; r < n; ++r) {
    JRow q = sys->rows[r];
    q.ba = to_global(q.ba), q.bb = to_global(q.bb);
    if (touches(q.ba) || touches(q.bb)) cols.push_back(r), jcols.push_back(q);
  }
  if (m == 0 || cols.empty()) return;
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(m, (Eigen::Index)cols.size());
  for (int k = 0; k < m; ++k)
    for (size_t c = 0; c < cols.size(); ++c) X(k, (Eigen::Index)c) = rowCoupling(rows_[k], jcols[c]);
  const Eigen::MatrixXd Y = factorization().solve(X);
  const Eigen::MatrixXd C = X.transpose() * Y;
  for (size_t p = 0; p < cols.size(); ++p)
    for (size_t q = 0; q < cols.size(); ++q) sys->A(cols[p], cols[q]) -= C((Eigen::Index)p, (Eigen::Index)q);
}

namespace {
// The projection's metric (joint_system.hpp): per body the factor on M^-1 that makes a jointed body heavier
// than kMetricMassRatio times the lightest jointed body that heavy; empty when no body is.
std::vector<double> metricScales(const std::vector<Body>& bodies, const std::vector<Joint>& joints) {
  double lightest = kInfinity;
  for (const Joint& j : joints)
    for (int b : {j.a, j.b})
      if (b >= 0 && !bodies[b].is_static) lightest = std::min(lightest, bodies[b].mass);
  std::vector<double> f(bodies.size(), 1.0);
  bool any = false;
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].is_static && bodies[i].mass > kMetricMassRatio * lightest)
      f[i] = bodies[i].mass / (kMetricMassRatio * lightest), any = true;
  return any ? f : std::vector<double>();
}
} // namespace

int projectPositions(const std::vector<Joint>& joints, double tol, int max_it, std::vector<Body>* bodies,
                     double* error, JointFactorization* cache) {
  std::vector<JRow> rows;
  std::vector<double> phi;
  std::vector<int> first;
  JointFactorization own;
  JointFactorization& ldlt = cache ? *cache : own;
  const std::vector<double> lighten = metricScales(*bodies, joints);
  std::vector<Body> metric; // the poses with the metric's masses (only when a body is lightened)
  int it = 0;
  for (;; ++it) {
    if (!lighten.empty()) {
      metric = *bodies;
      for (size_t i = 0; i < metric.size(); ++i)
        metric[i].inv_mass *= lighten[i], metric[i].inv_inertia *= lighten[i];
    }
    const std::vector<Body>& m = lighten.empty() ? *bodies : metric;
    jointJacobian(m, worldInverseInertia(m), joints, &rows, &phi, &first);
    *error = maxAbs(phi);
    if (*error <= tol || it == max_it || rows.empty()) return it;
    if (!ldlt.factorize(jointMatrix(rows, (int)bodies->size()))) return it;
    const Eigen::VectorXd mu =
        ldlt.solve(-Eigen::Map<const Eigen::VectorXd>(phi.data(), (Eigen::Index)phi.size()));
    const V6s dq = bodyImpulseVelocities(rows, mu, (int)bodies->size());
    // backtracking on max |Phi| (a drift of the order of a link, dt |w| ~ 1, is outside Newton's basin)
    const std::vector<Body> start = *bodies;
    for (double step = 1.0;; step *= 0.5) {
      V6s part = dq;
      for (V6& d : part) d *= step;
      moveBodies(part, bodies);
      if (step < kMinNewtonStep || maxError(*bodies, joints) < *error) break;
      *bodies = start;
    }
  }
}

} // namespace suite::contact
