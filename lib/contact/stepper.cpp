// Velocity-level contact time stepping: contacts, the Delassus system, the friction formulation's impulses,
// integration, sleeping. References: Stewart & Trinkle 1996; Anitescu & Potra 1997; Lacoursiere, SIGRAD 2003.
// See stepper.hpp for the formulation, friction_formulation.hpp for the friction models.
#include "contact/stepper.hpp"

#include "contact/contact_accuracy.hpp"
#include "contact/delassus.hpp"
#include "contact/delassus_sparse.hpp"
#include "contact/friction_auto.hpp"
#include "contact/friction_formulation.hpp"
#include "contact/joint_system.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace suite::contact {

Stepper::Stepper(StepperOptions o) : o_(std::move(o)) {
  setDt(o_.dt);
  runner_ = [](int n, const TaskSolveFn& solve, std::vector<std::vector<double>>* out) {
    out->assign(n, {});
    for (int k = 0; k < n; ++k) (*out)[k] = solve(k);
    return std::string();
  };
}

void Stepper::setDt(double dt) {
  o_.dt = dt;
  form_ = makeFrictionFormulation(o_);
  if (o_.friction == FrictionModel::Auto) auto_ = std::make_shared<const AutoFriction>(o_);
}

double mechanicalEnergy(const std::vector<Body>& bodies, const Vec3& gravity) {
  double e = 0.0;
  for (const Body& b : bodies)
    if (!b.is_static) e += b.kineticEnergy() - b.mass * gravity.dot(b.x);
  return e;
}

std::string simplifications(const StepperOptions& o, const std::vector<Body>& bodies) {
  std::string s;
  if (o.mu == 0 || o.friction == FrictionModel::None)
    s += "no friction rows (plain LCP); ";
  else if (o.friction == FrictionModel::Auto)
    s += "per problem the cheapest friction model with cone violation <= -target_error; ";
  else if (o.friction != FrictionModel::Polyhedral)
    s += "box friction (per-direction bounds, not a cone); ";
  bool cyl = false;
  for (const Body& b : bodies) cyl = cyl || b.shape.type == ShapeType::Cylinder;
  if (cyl) s += "cylinders act as capsules except against planes; ";
  s += "zero-bound tangent rows left out; ";
  s += o.sleep ? "sleeping on (bodies at rest are frozen, contacts among them not solved)"
               : "sleeping off (every contact is solved each step)";
  return s;
}

void forceMeasures(const std::vector<Contact>& cs, const std::vector<Vec3>& lam, double mu, double* ratio,
                   double* violation, double* normal) {
  std::vector<std::array<int, 3>> by_pair(cs.size()); // (a, b, index): each pair's contacts together
  double fn = 0.0, viol = 0.0;
  for (size_t i = 0; i < cs.size(); ++i) {
    by_pair[i] = {cs[i].a, cs[i].b, (int)i};
    fn += lam[i][0];
    viol += std::max(0.0, std::hypot(lam[i][1], lam[i][2]) - mu * lam[i][0]);
  }
  std::sort(by_pair.begin(), by_pair.end());
  double tsum = 0.0;
  Vec3 ft = Vec3::Zero(); // the tangential impulse of the current pair
  for (size_t k = 0; k < by_pair.size(); ++k) {
    const int i = by_pair[k][2];
    ft += lam[i][1] * cs[i].t1 + lam[i][2] * cs[i].t2;
    const bool last =
        k + 1 == by_pair.size() || by_pair[k + 1][0] != by_pair[k][0] || by_pair[k + 1][1] != by_pair[k][1];
    if (last) tsum += ft.norm(), ft.setZero();
  }
  *normal = fn;
  *ratio = fn > 0 ? tsum / fn : 0.0;
  *violation = fn > 0 ? viol / fn : 0.0;
}

namespace {
// Index of the contact of the previous step matching c (same pair, nearest point within tol), or -1;
// candidates: the previous contacts of the pair, in increasing index order.
int matchPrevious(const std::vector<Contact>& prev, const std::vector<int>& candidates, const Contact& c,
                  double tol) {
  int best = -1;
  double bd = tol;
  for (int i : candidates) {
    const double d = (prev[i].p - c.p).norm();
    if (d <= bd) bd = d, best = i;
  }
  return best;
}

// The impulse (n, t1, t2) of the previous step's contact pc carried to its match c: balanced / fast turn the
// tangential part into c's frame (the world vector lt1 pt1 + lt2 pt2 projected on c.t1, c.t2), since their
// frames, read from gravity, point anywhere in the tangent plane once a normal tilts by round-off; exact keeps
// the components (its frames follow the slip, and its answers do not depend on the start).
Vec3 carriedImpulse(const Contact& pc, const Vec3& l, const Contact& c, const StepperOptions& o) {
  if (o.accuracy == ContactAccuracy::Exact) return l;
  const Vec3 ft = l[1] * pc.t1 + l[2] * pc.t2;
  return Vec3(l[0], ft.dot(c.t1), ft.dot(c.t2));
}

// x += dt v, q <- exp(dt w / 2) q with the new velocities; false (and the body's name) on a non-finite state.
bool integrate(const std::vector<Vec3>& v, const std::vector<Vec3>& w, double dt, std::vector<Body>* bodies,
               std::string* bad) {
  for (size_t i = 0; i < bodies->size(); ++i) {
    Body& B = (*bodies)[i];
    if (B.is_static) continue;
    B.v = v[i];
    B.w = w[i];
    advancePose(&B, B.v, B.w, dt);
    if (!B.x.allFinite() || !B.v.allFinite() || !B.w.allFinite() || !B.q.coeffs().allFinite()) {
      *bad = B.name;
      return false;
    }
  }
  return true;
}
} // namespace

void Stepper::exportState(int nb, std::vector<double>* bs, std::vector<double>* cs) const {
  bs->assign(2 * (size_t)nb, 0.0);
  for (int i = 0; i < nb && i < (int)still_.size(); ++i) (*bs)[2 * i] = still_[i];
  for (int i = 0; i < nb && i < (int)asleep_.size(); ++i) (*bs)[2 * i + 1] = asleep_[i];
  cs->clear();
  for (size_t i = 0; i < prev_contacts_.size(); ++i) {
    const Contact& c = prev_contacts_[i];
    const Vec3& l = prev_impulses_[i];
    cs->insert(cs->end(), {(double)c.a, (double)c.b, c.p.x(), c.p.y(), c.p.z(), l.x(), l.y(), l.z()});
  }
}

void Stepper::importState(int nb, const std::vector<double>& bs, const std::vector<double>& cs) {
  if (bs.size() != 2 * (size_t)nb || cs.size() % 8 != 0)
    throw std::runtime_error("stepper state: inconsistent sizes");
  still_.assign(nb, 0);
  asleep_.assign(nb, 0);
  for (int i = 0; i < nb; ++i) {
    still_[i] = (int)bs[2 * i];
    asleep_[i] = bs[2 * i + 1] != 0.0;
  }
  prev_contacts_.clear();
  prev_impulses_.clear();
  prev_ids_.clear();
  prev_rungs_.clear(); // -friction auto starts over at the bottom rung (see friction_auto.hpp)
  for (size_t k = 0; k < cs.size(); k += 8) {
    Contact c;
    c.a = (int)cs[k];
    c.b = (int)cs[k + 1];
    if (c.a < 0 || c.a >= nb || c.b < 0 || c.b >= nb || c.a != cs[k] || c.b != cs[k + 1])
      throw std::runtime_error("stepper state: contact body index out of range");
    c.p = Vec3(cs[k + 2], cs[k + 3], cs[k + 4]);
    prev_contacts_.push_back(c);
    prev_impulses_.push_back(Vec3(cs[k + 5], cs[k + 6], cs[k + 7]));
  }
}

StepStats Stepper::step(std::vector<Body>* bodies_ptr) {
  if (!o_.sleep) return stepBodies(bodies_ptr);
  std::vector<Body>& real = *bodies_ptr;
  const size_t nb = real.size();
  still_.resize(nb, 0);
  asleep_.resize(nb, 0);
  // wake sleeping bodies touched by an awake dynamic body (repeat: a woken body may touch another)
  std::vector<Body> view;
  for (bool changed = true; changed;) {
    changed = false;
    view = real;
    for (size_t i = 0; i < nb; ++i)
      if (asleep_[i]) view[i].is_static = true, view[i].v.setZero(), view[i].w.setZero();
    for (const Contact& c : findContacts(view, o_.margin, o_.gravity, o_.dt)) {
      const int ids[2] = {c.a, c.b};
      for (int k = 0; k < 2; ++k) {
        const int s = ids[k], o = ids[1 - k];
        if (asleep_[s] && !real[o].is_static && !asleep_[o]) asleep_[s] = 0, still_[s] = 0, changed = true;
      }
    }
  }
  StepStats st = stepBodies(&view);
  if (st.failed) return st;
  for (size_t i = 0; i < nb; ++i) {
    if (real[i].is_static || asleep_[i]) continue;
    real[i].x = view[i].x, real[i].q = view[i].q, real[i].v = view[i].v, real[i].w = view[i].w;
    const double speed = real[i].v.norm() + real[i].w.norm() * real[i].boundingRadius();
    still_[i] = speed < o_.sleep_velocity ? still_[i] + 1 : 0;
    if (still_[i] >= o_.sleep_steps) asleep_[i] = 1, real[i].v.setZero(), real[i].w.setZero();
  }
  for (size_t i = 0; i < nb; ++i) st.sleeping += asleep_[i];
  return st;
}

// Previous-step impulses of the matching contacts (warm start, scaled_box / splitting estimates) and the
// persistent identities: a matched contact keeps its predecessor's id, a new one gets the next free id. The
// previous contacts are bucketed by body pair (O(contacts) for a bounded number of points per pair).
void Stepper::matchPreviousImpulses(const std::vector<Body>& bodies, std::vector<Vec3>* prev,
                                    std::vector<bool>* has_prev, std::vector<int>* prev_rung) {
  const int nc = (int)contacts_.size();
  prev->assign(nc, Vec3::Zero());
  has_prev->assign(nc, false);
  prev_rung->assign(nc, -1);
  // the previous contacts sorted by (pair, index): a pair's candidates are one contiguous, increasing range
  std::vector<std::array<int, 3>> by_pair(prev_contacts_.size());
  for (int i = 0; i < (int)prev_contacts_.size(); ++i)
    by_pair[i] = {prev_contacts_[i].a, prev_contacts_[i].b, i};
  std::sort(by_pair.begin(), by_pair.end());
  std::vector<long long> ids(nc);
  std::vector<int> candidates;
  for (int i = 0; i < nc; ++i) {
    const Contact& c = contacts_[i];
    const double tol = 0.1 * std::min(bodies[c.a].boundingRadius(), bodies[c.b].boundingRadius());
    candidates.clear();
    for (auto it = std::lower_bound(by_pair.begin(), by_pair.end(), std::array<int, 3>{c.a, c.b, -1});
         it != by_pair.end() && (*it)[0] == c.a && (*it)[1] == c.b; ++it)
      candidates.push_back((*it)[2]);
    const int k = matchPrevious(prev_contacts_, candidates, c, tol);
    if (k >= 0)
      (*prev)[i] = carriedImpulse(prev_contacts_[k], prev_impulses_[k], c, o_), (*has_prev)[i] = true;
    if (k >= 0 && k < (int)prev_rungs_.size()) (*prev_rung)[i] = prev_rungs_[k];
    ids[i] = k >= 0 && k < (int)prev_ids_.size() ? prev_ids_[k] : next_id_++;
  }
  ids_ = std::move(ids);
}

// The impulses of the step's contacts, applied to v*, w: one problem, or one per island.
bool Stepper::solveContacts(const std::vector<Body>& bodies, std::vector<Vec3>* v, std::vector<Vec3>* w,
                            std::vector<Vec3>* lam, StepStats* st) {
  std::vector<Vec3> prev;
  std::vector<bool> has_prev;
  std::vector<int> prev_rung;
  auto t = std::chrono::steady_clock::now();
  matchPreviousImpulses(bodies, &prev, &has_prev, &prev_rung);
  rungs_.assign(contacts_.size(), -1);
  phases_.match += lap(&t);
  if (o_.islands) return solveIslands(bodies, prev, has_prev, prev_rung, v, w, lam, st);
  const bool ok =
      solveProblem(bodies, {contacts_, prev, has_prev, prev_rung}, v, w, lam, st, &problems_, &solution_);
  if (ok) rungs_.assign(contacts_.size(), st->friction_rung);
  return ok;
}

// The impulses of the problem's contacts, applied to v*, w: the friction formulation, or -friction auto's.
bool Stepper::solveProblem(const std::vector<Body>& bodies, const ProblemInput& in, std::vector<Vec3>* v,
                           std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st,
                           std::vector<lcp::Problem>* problems, lcp::Vec* solution) const {
  if (auto_) return solveAuto(bodies, in, v, w, lam, st, problems, solution);
  return solveModel(*form_, o_, bodies, in, v, w, lam, st, problems, solution);
}

// The impulses of contacts in.cs (formulation form on the Delassus system), applied to v*, w.
bool Stepper::solveModel(const FrictionFormulation& form, const StepperOptions& o,
                         const std::vector<Body>& bodies, const ProblemInput& in, std::vector<Vec3>* v,
                         std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st,
                         std::vector<lcp::Problem>* problems, lcp::Vec* solution) const {
  const int nb = (int)bodies.size();
  std::vector<Mat3> inv_i(nb);
  for (int i = 0; i < nb; ++i) inv_i[i] = bodies[i].is_static ? Mat3::Zero() : bodies[i].invInertiaWorld();
  const std::vector<ConstraintRow> rows = form.rows(in.cs);
  const bool exact = o.accuracy == ContactAccuracy::Exact;
  auto jointed = [&](int b) { return joint_sys_->touches(in.global ? (*in.global)[b] : b); };
  bool on_joints = false; // contacts on jointed bodies: the dense A with the joint block's Schur complement
  for (const ConstraintRow& r : rows)
    on_joints = on_joints || (joint_sys_ && (jointed(in.cs[r.contact].a) || jointed(in.cs[r.contact].b)));
  // exact: the dense A with the joint block's Schur complement; balanced / fast: the joint block in the sweeps
  const bool sparse = !(on_joints && exact) && o.friction != FrictionModel::Polyhedral &&
                      (!exact || (int)rows.size() > o.dense_max_rows);
  StepperOptions ob = o; // balanced / fast: their own Baumgarte factor (contact_accuracy.hpp)
  if (!exact) ob.baumgarte = o.budget_baumgarte;
  // S deferred (sparseMatrix()): the block PGS sweeps of fast and balanced and the exact path's body-space
  // solves need only the rows, masses and compliance; a fallback builds it when it needs it
  DelassusSystem sys = buildDelassus(bodies, inv_i, *v, in.cs, rows, ob, sparse, true);
  if (on_joints && exact) joint_sys_->correctDelassus(&sys, in.global);
  const ContactStep step{bodies, in.cs, in.prev, in.has_prev};
  Impulses imp;
  if (!exact) {
    const JointCoupling coupling = [&](const lcp::Vec& z) { return jointCoupling(sys, z, in.global); };
    budgetImpulses(step, sys, o, &imp, st, on_joints ? &coupling : nullptr);
  } else {
    ChainSolve solver(o, keep_problems_, problems, solution, st);
    if (!form.impulses(step, sys, solver, &imp, st)) return false;
  }
  applyImpulses(sys, imp.z, v, w);
  *lam = imp.lambda;
  return true;
}

// The contact rows' velocity change from the joint impulses answering contact impulses z (JointCoupling).
lcp::Vec Stepper::jointCoupling(const DelassusSystem& sys, const lcp::Vec& z,
                                const std::vector<int>* global) const {
  const V6s du = bodyImpulseVelocities(sys.rows, z, sys.nbodies);
  V6s dg(joint_sys_->bodies(), V6::Zero()); // du over the whole scene
  for (int i = 0; i < sys.nbodies; ++i) dg[global ? (*global)[i] : i] = du[i];
  const V6s rg = joint_sys_->respond(dg);
  V6s r(sys.nbodies);
  for (int i = 0; i < sys.nbodies; ++i) r[i] = rg[global ? (*global)[i] : i];
  lcp::Vec db(sys.rows.size());
  for (size_t k = 0; k < sys.rows.size(); ++k) db[(Eigen::Index)k] = rowVelocity(sys.rows[k], r);
  return db;
}

void Stepper::setJoints(std::vector<Joint> joints) {
  if (!joints.empty() && o_.sleep)
    throw std::runtime_error("joints need sleeping off (-sleep: a sleeping body would freeze its joints)");
  for (const Joint& j : joints) {
    const bool axial = j.type == JointType::Hinge || j.type == JointType::Slider;
    if ((j.limited || j.motor) && !axial)
      throw std::runtime_error("joint '" + j.name + "': limits and motors need a hinge or a slider");
    if (j.limited && !(j.lower < j.upper && std::isfinite(j.lower) && std::isfinite(j.upper)))
      throw std::runtime_error("joint '" + j.name + "': its limit needs lower < upper (finite)");
    if (j.limited && j.type == JointType::Hinge && !(j.lower > -M_PI && j.upper < M_PI))
      throw std::runtime_error("joint '" + j.name + "': hinge limits must lie in (-pi, pi) (the angle is " +
                               "measured in (-pi, pi])");
    if (j.motor && !(j.max_force > 0 && std::isfinite(j.max_force) && std::isfinite(j.target_speed)))
      throw std::runtime_error("joint '" + j.name +
                               "': a motor needs 0 < max_force < inf and a finite speed");
  }
  joined_.clear();
  for (const Joint& j : joints)
    if (j.b >= 0) joined_.push_back({std::min(j.a, j.b), std::max(j.a, j.b)});
  std::sort(joined_.begin(), joined_.end());
  joints_ = std::move(joints);
  actuation_.reset(joints_);
}

double Stepper::motorPower(int k) const {
  if (actuation_.empty() || !joints_[k].motor) return 0.0;
  return actuation_.motorImpulse(k) / o_.dt * actuation_.rate(k);
}

void Stepper::jointReaction(int k, const std::vector<Body>& bodies, Vec3* force, Vec3* torque) const {
  *force = *torque = Vec3::Zero();
  if (joint_impulse_.size() == 0) return;
  const int end = k + 1 < (int)joint_first_.size() ? joint_first_[k + 1] : (int)joint_rows_.size();
  for (int r = joint_first_[k]; r < end; ++r) {
    *force += joint_rows_[r].ja.head<3>() * joint_impulse_[r] / o_.dt;
    *torque += joint_rows_[r].ja.tail<3>() * joint_impulse_[r] / o_.dt;
  }
  if (!actuation_.empty()) { // the limit's and the motor's impulse along the rate row
    const double z = actuation_.limitImpulse(k) + actuation_.motorImpulse(k);
    *force += actuation_.rateRow(k).ja.head<3>() * z / o_.dt;
    *torque += actuation_.rateRow(k).ja.tail<3>() * z / o_.dt;
  }
  const Body& A = bodies[joints_[k].a];
  *torque -= (A.R() * joints_[k].ra).cross(*force); // about the anchor instead of the centre of mass
}

namespace {
// The contacts the collision bits (body.hpp) and the joints (no contact between two bodies a joint connects)
// allow.
std::vector<Contact> allowedContacts(std::vector<Contact> cs, const std::vector<Body>& bodies,
                                     const std::vector<std::pair<int, int>>& joined) {
  std::vector<Contact> out;
  out.reserve(cs.size());
  for (Contact& c : cs) {
    const Body &A = bodies[c.a], &B = bodies[c.b];
    if (!(A.contype & B.conaffinity) && !(B.contype & A.conaffinity)) continue;
    const std::pair<int, int> p{std::min(c.a, c.b), std::max(c.a, c.b)};
    if (!joined.empty() && std::binary_search(joined.begin(), joined.end(), p)) continue;
    out.push_back(std::move(c));
  }
  return out;
}
} // namespace

// The joint part of a step's end: the poses projected onto the joints, the errors recorded. False (with the
// message) on a non-finite state.
bool Stepper::finishJoints(std::vector<Body>* next, const JointSystem& js, StepStats* st) {
  st->joint_rows = js.rows();
  const std::vector<Body> drifted = *next;
  st->projection_iterations = projectPositions(joints_, o_.joint_tol, o_.joint_max_projections, next,
                                               &st->joint_error, &projection_factor_);
  if (o_.joint_max_projections > 0 && !(st->joint_error <= StepperOptions::kJointFailure * o_.joint_tol)) {
    st->failed = st->retry_smaller_dt = true;
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "the joints' position projection ended at max |Phi| = %.3g after %d Newton iterations "
                  "(-joint_tol %g, -joint_max_projections %d)",
                  st->joint_error, st->projection_iterations, o_.joint_tol, o_.joint_max_projections);
    st->message = msg;
    return false;
  }
  if (st->shake_iterations < 0) // without SHAKE the velocities follow the projected poses (as SHAKE's would)
    for (size_t i = 0; i < next->size(); ++i) {
      Body& B = (*next)[i];
      if (B.is_static) continue;
      B.v += (B.x - drifted[i].x) / o_.dt;
      const Eigen::AngleAxisd turn(B.q * drifted[i].q.conjugate());
      B.w += turn.angle() * turn.axis() / o_.dt;
    }
  std::vector<Vec3> v(next->size()), w(next->size());
  for (size_t i = 0; i < next->size(); ++i) v[i] = (*next)[i].v, w[i] = (*next)[i].w;
  std::vector<JRow> rows;
  std::vector<double> phi;
  std::vector<int> first;
  std::vector<Mat3> inv_i(next->size(), Mat3::Zero());
  jointJacobian(*next, inv_i, joints_, &rows, &phi, &first);
  for (const JRow& J : rows) {
    double s = 0.0;
    if (J.ba >= 0) s += J.ja.head<3>().dot(v[J.ba]) + J.ja.tail<3>().dot(w[J.ba]);
    if (J.bb >= 0) s += J.jb.head<3>().dot(v[J.bb]) + J.jb.tail<3>().dot(w[J.bb]);
    st->joint_velocity_error = std::max(st->joint_velocity_error, std::abs(s));
  }
  for (const Body& B : *next)
    if (!B.x.allFinite() || !B.q.coeffs().allFinite()) {
      st->failed = true;
      st->message = "non-finite state of body '" + B.name + "' after the joint projection";
      return false;
    }
  return true;
}

// The step's velocities from v*: the joint block with SHAKE (joint_system.hpp), the contacts, the joint block
// again; with limits or motors, once per guess of their active set until it holds (joint_actuation.hpp). js,
// jlam: the accepted solve's joint block and its impulses. False: a solve failed (st->message).
bool Stepper::solveVelocities(const std::vector<Body>& bodies, std::vector<Vec3>* v, std::vector<Vec3>* w,
                              std::vector<Vec3>* lam, StepStats* st, std::unique_ptr<JointSystem>* js,
                              Eigen::VectorXd* jlam) {
  const int nb = (int)bodies.size(), nc = (int)contacts_.size();
  if (nc == 0) ids_.clear();
  if (joints_.empty()) return nc == 0 || solveContacts(bodies, v, w, lam, st);
  std::vector<Mat3> inv_i(nb);
  for (int i = 0; i < nb; ++i) inv_i[i] = bodies[i].is_static ? Mat3::Zero() : bodies[i].invInertiaWorld();
  actuation_.prepare(bodies, inv_i, joints_, o_.dt);
  const std::vector<Vec3> v0 = *v, w0 = *w;
  const int max_solves = JointActuation::kBlockSwitches + 4 * (int)joints_.size() + 10;
  for (int attempt = 1;; ++attempt) {
    *v = v0, *w = w0;
    lam->assign(nc, Vec3::Zero());
    jlam->resize(0);
    actuation_.applyFixed(v, w);
    const double free_energy = kineticEnergy(bodies, *v, *w); // the joint impulses do no work
    const ActuationRows extra = actuation_.rows();
    js->reset(); // before the next system factorises into joint_factor_
    *js = std::make_unique<JointSystem>(bodies, inv_i, joints_, &extra, &joint_factor_);
    if (!(*js)->ok()) {
      st->failed = true;
      st->message = "the joint block G M^-1 G^T did not factorise (dependent joint rows)";
      return false;
    }
    (*js)->project(v, w, jlam);
    // free motors do work: the bound is the larger of the free and the projected energy
    const double bound = std::max(free_energy, kineticEnergy(bodies, *v, *w)) * (1 + 1e-12);
    st->shake_iterations =
        (*js)->shake(bodies, joints_, o_.dt, o_.joint_tol, o_.joint_max_projections, bound, v, w, jlam);
    joint_sys_ = js->get();
    const bool solved = nc == 0 || solveContacts(bodies, v, w, lam, st);
    joint_sys_ = nullptr;
    if (!solved) return false;
    if (nc > 0) (*js)->project(v, w, jlam);
    st->actuation_solves = attempt;
    if (actuation_.empty()) return true;
    const int h = (*js)->holonomicRows();
    if (actuation_.update(jlam->tail(jlam->size() - h), *v, *w, attempt)) return true;
    if (attempt == max_solves) {
      st->failed = true;
      st->message = "joint limits and motors: the active set did not settle in " +
                    std::to_string(max_solves) + " solves";
      return false;
    }
  }
}

StepStats Stepper::stepBodies(std::vector<Body>* bodies_ptr) {
  std::vector<Body>& bodies = *bodies_ptr;
  StepStats st;
  problems_.clear();
  solution_.resize(0);
  const int nb = (int)bodies.size();
  // balanced / fast: tangent frames from gravity only (never along the slip), so that the carried tangential
  // impulses of a PGS answer, which always slips a little, keep their directions from step to step
  const double slip_eps = o_.accuracy == ContactAccuracy::Exact ? 1e-9 : lcp::kInf;
  auto t = std::chrono::steady_clock::now();
  const double cpu0 = threadCpu();
  contacts_ = allowedContacts(findContacts(bodies, o_.margin, o_.gravity, o_.dt, slip_eps), bodies, joined_);
  phases_.collision += lap(&t);
  const int nc = (int)contacts_.size();
  st.contacts = nc;
  for (const Contact& c : contacts_) st.penetration = std::max(st.penetration, -c.phi);
  std::vector<Vec3> vstar(nb), wnew(nb), lam(nc, Vec3::Zero());
  for (int i = 0; i < nb; ++i) {
    vstar[i] = bodies[i].is_static ? bodies[i].v : Vec3(bodies[i].v + o_.dt * o_.gravity);
    wnew[i] = bodies[i].w;
  }
  std::unique_ptr<JointSystem> js; // the joint block: v* projected, then v* + M^-1 N^T z (joint_system.hpp)
  Eigen::VectorXd jlam;
  if (!solveVelocities(bodies, &vstar, &wnew, &lam, &st, &js, &jlam)) return st;
  lap(&t); // solveContacts timed its phases
  std::vector<Body> next = bodies;
  std::string bad;
  if (!integrate(vstar, wnew, o_.dt, &next, &bad)) {
    st.failed = true;
    st.message = "non-finite state of body '" + bad + "' after the contact solve";
    return st;
  }
  if (js && !finishJoints(&next, *js, &st)) return st;
  if (js) {
    joint_rows_.assign(js->jacobian().begin(), js->jacobian().begin() + js->holonomicRows());
    joint_impulse_ = jlam.head(js->holonomicRows());
    joint_first_.clear();
    for (int k = 0; k < (int)joints_.size(); ++k) joint_first_.push_back(js->firstRow(k));
  }
  bodies.swap(next);
  impulses_ = lam;
  forceMeasures(contacts_, lam, o_.mu, &st.force_ratio, &st.cone_violation, &st.normal_impulse);
  prev_contacts_ = contacts_;
  prev_impulses_ = impulses_;
  prev_ids_ = ids_;
  prev_rungs_ = nc > 0 ? rungs_ : std::vector<int>();
  ++steps_done_;
  phases_.integration += lap(&t);
  phases_.cpu_steps += threadCpu() - cpu0;
  ++phases_.steps;
  return st;
}

} // namespace suite::contact
