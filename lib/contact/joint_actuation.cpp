// Joint limits and motors by an active-set outer loop (see joint_actuation.hpp).
#include "contact/joint_actuation.hpp"

#include <cmath>

namespace suite::contact {

namespace {
V6 invMassPart(const Body& B, const Mat3& inv_i, const V6& j) {
  V6 m;
  m.head<3>() = B.inv_mass * j.head<3>();
  m.tail<3>() = inv_i * j.tail<3>();
  return m;
}

double rowRate(const JRow& J, const std::vector<Vec3>& v, const std::vector<Vec3>& w) {
  double s = 0.0;
  if (J.ba >= 0) s += J.ja.head<3>().dot(v[J.ba]) + J.ja.tail<3>().dot(w[J.ba]);
  if (J.bb >= 0) s += J.jb.head<3>().dot(v[J.bb]) + J.jb.tail<3>().dot(w[J.bb]);
  return s;
}

JRow negated(JRow J) {
  J.ja = -J.ja, J.jb = -J.jb, J.ma = -J.ma, J.mb = -J.mb;
  return J;
}

bool sameActuation(const Joint& x, const Joint& y) {
  return x.limited == y.limited && x.motor == y.motor && x.lower == y.lower && x.upper == y.upper &&
         x.target_speed == y.target_speed && x.max_force == y.max_force && x.a == y.a && x.b == y.b;
}
} // namespace

void JointActuation::reset(const std::vector<Joint>& joints) {
  bool same = joints.size() == spec_.size();
  for (size_t k = 0; same && k < joints.size(); ++k) same = sameActuation(joints[k], spec_[k]);
  if (same) return;
  spec_ = joints;
  idx_.clear();
  for (int k = 0; k < (int)joints.size(); ++k)
    if (joints[k].limited || joints[k].motor) idx_.push_back(k);
  const size_t n = joints.size();
  limit_.assign(n, 0), motor_.assign(n, 0);
  rate_row_.assign(n, JRow{-1, -1, V6::Zero(), V6::Zero(), V6::Zero(), V6::Zero()});
  coord_.assign(n, 0.0), rate_.assign(n, 0.0), mass_.assign(n, 0.0);
  limit_impulse_.assign(n, 0.0), motor_impulse_.assign(n, 0.0);
}

void JointActuation::prepare(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Joint>& joints, double dt) {
  dt_ = dt;
  for (int k : idx_) {
    const Joint& j = joints[k];
    const JointRow r = jointCoordinate(j, bodies);
    JRow J;
    const bool a_dyn = !bodies[j.a].is_static, b_dyn = j.b >= 0 && !bodies[j.b].is_static;
    J.ba = a_dyn ? j.a : -1;
    J.bb = b_dyn ? j.b : -1;
    J.ja = r.ja, J.jb = r.jb;
    J.ma = a_dyn ? invMassPart(bodies[j.a], inv_i[j.a], r.ja) : V6::Zero().eval();
    J.mb = b_dyn ? invMassPart(bodies[j.b], inv_i[j.b], r.jb) : V6::Zero().eval();
    rate_row_[k] = J;
    coord_[k] = r.phi;
    const double d = J.ja.dot(J.ma) + J.jb.dot(J.mb); // J M^-1 J^T
    mass_[k] = d > 0 ? 1.0 / d : 0.0;
  }
}

ActuationRows JointActuation::rows() const {
  ActuationRows out;
  for (int k : idx_) {
    const Joint& j = spec_[k];
    if (limit_[k] != 0) {
      const bool lower = limit_[k] < 0;
      out.rows.push_back(lower ? rate_row_[k] : negated(rate_row_[k]));
      out.bias.push_back((lower ? coord_[k] - j.lower : j.upper - coord_[k]) / dt_);
      out.joint.push_back(k);
    }
    if (j.motor && motor_[k] == 0) {
      out.rows.push_back(rate_row_[k]);
      out.bias.push_back(-j.target_speed);
      out.joint.push_back(k);
    }
  }
  return out;
}

void JointActuation::applyFixed(std::vector<Vec3>* v, std::vector<Vec3>* w) const {
  for (int k : idx_) {
    if (!spec_[k].motor || motor_[k] == 0) continue;
    const JRow& J = rate_row_[k];
    const double z = motor_[k] * spec_[k].max_force * dt_;
    if (J.ba >= 0) (*v)[J.ba] += z * J.ma.head<3>(), (*w)[J.ba] += z * J.ma.tail<3>();
    if (J.bb >= 0) (*v)[J.bb] += z * J.mb.head<3>(), (*w)[J.bb] += z * J.mb.tail<3>();
  }
}

// The checks in the order of idx_ (limit, then motor, per joint); each violator's switch is applied to the
// guess when all (attempt <= kBlockSwitches) or only the first is taken.
bool JointActuation::update(const Eigen::VectorXd& lambda, const std::vector<Vec3>& v,
                            const std::vector<Vec3>& w, int attempt) {
  std::vector<std::pair<int, signed char>> limit_switch, motor_switch; // (joint, new state)
  std::vector<int> order;                                              // 0 limit, 1 motor, in check order
  int row = 0;
  for (int k : idx_) {
    const Joint& j = spec_[k];
    rate_[k] = rowRate(rate_row_[k], v, w);
    const double tol_v = kActuationTol * (1.0 + std::abs(j.target_speed));
    const double tol_z = tol_v * mass_[k];
    double lz = 0.0, mz = 0.0;
    if (j.limited) {
      const double end = coord_[k] + dt_ * rate_[k];
      if (limit_[k] != 0) {
        lz = lambda[row++];
        if (lz < -tol_z) limit_switch.push_back({k, 0}), order.push_back(0);
      } else if (end < j.lower - dt_ * tol_v) {
        limit_switch.push_back({k, -1}), order.push_back(0);
      } else if (end > j.upper + dt_ * tol_v) {
        limit_switch.push_back({k, +1}), order.push_back(0);
      }
      limit_impulse_[k] = limit_[k] < 0 ? lz : -lz;
    }
    if (j.motor) {
      const double bound = j.max_force * dt_, err = rate_[k] - j.target_speed;
      if (motor_[k] == 0) {
        mz = lambda[row++];
        if (std::abs(mz) > bound + tol_z) motor_switch.push_back({k, mz > 0 ? 1 : -1}), order.push_back(1);
      } else {
        mz = motor_[k] * bound;
        if (motor_[k] * err > tol_v) motor_switch.push_back({k, 0}), order.push_back(1);
      }
      motor_impulse_[k] = mz;
    }
  }
  if (order.empty()) return true;
  const bool block = attempt <= kBlockSwitches;
  size_t li = 0, mi = 0;
  for (size_t n = 0; n < order.size() && (block || n == 0); ++n) {
    if (order[n] == 0)
      limit_[limit_switch[li].first] = limit_switch[li].second, ++li;
    else
      motor_[motor_switch[mi].first] = motor_switch[mi].second, ++mi;
  }
  return false;
}

} // namespace suite::contact
