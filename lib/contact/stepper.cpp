// Velocity-level contact time stepping with the friction models none / box / scaled_box / splitting /
// polyhedral. References: Stewart & Trinkle 1996; Anitescu & Potra 1997; Lacoursiere, SIGRAD 2003
// (box MLCP, Eq. 6 linearised cone, operator splitting). See stepper.hpp for the formulation.
#include "contact/stepper.hpp"

#include "contact/lemke_rf.hpp"
#include "lcp/solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace suite::contact {

const char* frictionName(FrictionModel m) {
  switch (m) {
  case FrictionModel::None:
    return "none";
  case FrictionModel::Box:
    return "box";
  case FrictionModel::ScaledBox:
    return "scaled_box";
  case FrictionModel::Splitting:
    return "splitting";
  case FrictionModel::Polyhedral:
    return "polyhedral";
  }
  return "?";
}

std::vector<std::string> frictionNames() {
  return {"none", "box", "scaled_box", "splitting", "polyhedral"};
}

bool frictionFromName(const std::string& name, FrictionModel* m) {
  for (int i = 0; i < 5; ++i)
    if (name == frictionName(FrictionModel(i))) {
      *m = FrictionModel(i);
      return true;
    }
  return false;
}

const char* splitStartName(SplitStart s) {
  switch (s) {
  case SplitStart::Zero:
    return "zero";
  case SplitStart::Infinite:
    return "infinite";
  case SplitStart::Previous:
    return "previous";
  }
  return "?";
}

bool splitStartFromName(const std::string& name, SplitStart* s) {
  for (int i = 0; i < 3; ++i)
    if (name == splitStartName(SplitStart(i))) {
      *s = SplitStart(i);
      return true;
    }
  return false;
}

double mechanicalEnergy(const std::vector<Body>& bodies, const Vec3& gravity) {
  double e = 0.0;
  for (const Body& b : bodies)
    if (!b.is_static) e += b.kineticEnergy() - b.mass * gravity.dot(b.x);
  return e;
}

namespace {

using V6 = Eigen::Matrix<double, 6, 1>;
using lcp::kInf;
using lcp::Mat;
using LVec = lcp::Vec;

// One constraint row: J = [ja for body ba, jb for body bb], with M^-1 J^T parts ma, mb (-1: static).
struct JRow {
  int ba = -1, bb = -1;
  V6 ja = V6::Zero(), jb = V6::Zero(), ma = V6::Zero(), mb = V6::Zero();
};

V6 jacobian(const Body& B, const Vec3& p, const Vec3& dir, double sign) {
  V6 j;
  j.head<3>() = sign * dir;
  j.tail<3>() = sign * (p - B.x).cross(dir);
  return j;
}

V6 applyInvMass(const Body& B, const Mat3& inv_i, const V6& j) {
  V6 m;
  m.head<3>() = B.inv_mass * j.head<3>();
  m.tail<3>() = inv_i * j.tail<3>();
  return m;
}

struct System {
  std::vector<JRow> rows;
  Mat A;
  LVec b;
};

// Rows for the given (contact, direction) list; A = J M^-1 J^T, b = J v* + stabilisation (normal rows).
System buildSystem(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                   const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                   const std::vector<std::pair<int, Vec3>>& dirs, const std::vector<bool>& is_normal,
                   const StepperOptions& o) {
  System s;
  const int n = (int)dirs.size();
  s.rows.resize(n);
  s.b.resize(n);
  for (int r = 0; r < n; ++r) {
    const Contact& c = cs[dirs[r].first];
    const Vec3& d = dirs[r].second;
    JRow& J = s.rows[r];
    const Body& A = bodies[c.a];
    const Body& B = bodies[c.b];
    J.ja = jacobian(A, c.p, d, 1.0);
    J.jb = jacobian(B, c.p, d, -1.0);
    if (!A.is_static) J.ba = c.a, J.ma = applyInvMass(A, inv_i[c.a], J.ja);
    if (!B.is_static) J.bb = c.b, J.mb = applyInvMass(B, inv_i[c.b], J.jb);
    V6 va, vb;
    va << vstar[c.a], A.w;
    vb << vstar[c.b], B.w;
    double rhs = J.ja.dot(va) + J.jb.dot(vb);
    if (is_normal[r]) rhs += (c.phi >= 0 ? c.phi : o.baumgarte * c.phi) / o.dt;
    s.b[r] = rhs;
  }
  s.A = Mat::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    const JRow& R = s.rows[r];
    for (int q = r; q < n; ++q) {
      const JRow& Q = s.rows[q];
      double v = 0.0;
      if (R.ba >= 0 && R.ba == Q.ba) v += R.ja.dot(Q.ma);
      if (R.ba >= 0 && R.ba == Q.bb) v += R.ja.dot(Q.mb);
      if (R.bb >= 0 && R.bb == Q.ba) v += R.jb.dot(Q.ma);
      if (R.bb >= 0 && R.bb == Q.bb) v += R.jb.dot(Q.mb);
      s.A(r, q) = s.A(q, r) = v;
    }
  }
  for (int r = 0; r < n; ++r) s.A(r, r) *= 1.0 + (is_normal[r] ? o.regularisation : o.regularisation_t);
  return s;
}

// Index of the contact of the previous step matching c (same pair, nearest point within tol), or -1.
int matchPrevious(const std::vector<Contact>& prev, const Contact& c, double tol) {
  int best = -1;
  double bd = tol;
  for (int i = 0; i < (int)prev.size(); ++i) {
    if (prev[i].a != c.a || prev[i].b != c.b) continue;
    const double d = (prev[i].p - c.p).norm();
    if (d <= bd) bd = d, best = i;
  }
  return best;
}

// Sum over body pairs of |sum of tangential impulse vectors| / sum of normal impulses; cone violation.
void forceMeasures(const std::vector<Contact>& cs, const std::vector<Vec3>& lam, double mu, double* ratio,
                   double* violation, double* normal) {
  std::map<std::pair<int, int>, Vec3> ft;
  double fn = 0.0, viol = 0.0;
  for (size_t i = 0; i < cs.size(); ++i) {
    const Vec3 t = lam[i][1] * cs[i].t1 + lam[i][2] * cs[i].t2;
    auto it = ft.emplace(std::make_pair(cs[i].a, cs[i].b), Vec3::Zero()).first;
    it->second += t;
    fn += lam[i][0];
    viol += std::max(0.0, std::hypot(lam[i][1], lam[i][2]) - mu * lam[i][0]);
  }
  double tsum = 0.0;
  for (auto& e : ft) tsum += e.second.norm();
  *normal = fn;
  *ratio = fn > 0 ? tsum / fn : 0.0;
  *violation = fn > 0 ? viol / fn : 0.0;
}

} // namespace

lcp::Problem polyhedralLcp(const lcp::Mat& A, const lcp::Vec& b, int nc, int d, double mu) {
  const int m = nc * (2 + d), k = nc * (1 + d);
  Mat M = Mat::Zero(m, m);
  LVec q = LVec::Zero(m);
  M.topLeftCorner(k, k) = A;
  q.head(k) = b;
  for (int i = 0; i < nc; ++i) {
    M(k + i, i) = mu;
    for (int j = 0; j < d; ++j) {
      M(nc + i * d + j, k + i) = 1.0;
      M(k + i, nc + i * d + j) = -1.0;
    }
  }
  return lcp::makeLcp(M, q, "polyhedral");
}

lcp::Vec polyhedralScaling(const lcp::Problem& p, int nc, int d) {
  const int k = nc * (1 + d);
  LVec s(p.size());
  for (int r = 0; r < k; ++r) s[r] = p.M(r, r) > 0 ? 1.0 / std::sqrt(p.M(r, r)) : 1.0;
  for (int i = 0; i < nc; ++i) {
    double a = 0.0; // gamma_i couples to beta_ij with unit entries: scale it by the mean sqrt(A_bb)
    for (int j = 0; j < d; ++j) a += 1.0 / s[nc + i * d + j];
    s[k + i] = a / d;
  }
  return s;
}

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

StepStats Stepper::stepBodies(std::vector<Body>* bodies_ptr) {
  std::vector<Body>& bodies = *bodies_ptr;
  StepStats st;
  problems_.clear();
  solution_.resize(0);
  const int nb = (int)bodies.size();
  contacts_ = findContacts(bodies, o_.margin, o_.gravity, o_.dt);
  const std::vector<Contact>& cs = contacts_;
  const int nc = (int)cs.size();
  st.contacts = nc;
  std::vector<Mat3> inv_i(nb);
  std::vector<Vec3> vstar(nb);
  for (int i = 0; i < nb; ++i) {
    inv_i[i] = bodies[i].is_static ? Mat3::Zero() : bodies[i].invInertiaWorld();
    vstar[i] = bodies[i].is_static ? bodies[i].v : Vec3(bodies[i].v + o_.dt * o_.gravity);
  }
  std::vector<Vec3> wnew(nb);
  for (int i = 0; i < nb; ++i) wnew[i] = bodies[i].w;
  std::vector<Vec3> lam(nc, Vec3::Zero());
  const bool friction = o_.friction != FrictionModel::None && o_.mu > 0;

  // previous-step impulses of the matching contacts (warm start, scaled_box / splitting estimates)
  std::vector<Vec3> prev(nc, Vec3::Zero());
  std::vector<bool> has_prev(nc, false);
  for (int i = 0; i < nc; ++i) {
    const double tol = 0.1 * std::min(bodies[cs[i].a].boundingRadius(), bodies[cs[i].b].boundingRadius());
    const int k = matchPrevious(prev_contacts_, cs[i], tol);
    if (k >= 0) prev[i] = prev_impulses_[k], has_prev[i] = true;
  }
  // weight estimate of the normal impulse (box model)
  std::vector<int> count(nb, 0);
  for (const Contact& c : cs) ++count[c.a], ++count[c.b];
  auto weightEstimate = [&](const Contact& c) {
    double e = 0.0;
    int k = 0;
    for (int id : {c.a, c.b})
      if (!bodies[id].is_static) e += bodies[id].mass / count[id], ++k;
    return k ? o_.gravity.norm() * o_.dt * e / k : 0.0;
  };

  // Tries the solvers in turn on p (or on its scaled form diag(scale) M diag(scale), diag(scale) q when
  // scale is given: z = diag(scale) z'); an answer is accepted when its natural-map residual on the
  // ORIGINAL problem meets lcp_tol, after at most two active-set refinements (exact solves on the index sets
  // read off the answer, which repair the round-off a long pivot sequence leaves).
  auto solveWith = [&](const lcp::Problem& p, const std::vector<std::string>& names, const LVec* scale,
                       const LVec* warm, lcp::Result* res) -> bool {
    if (keep_problems_ || problems_.empty())
      problems_.push_back(p);
    else
      problems_.back() = p; // always keep the last one (dumped on failure)
    lcp::Problem ps;
    if (scale) {
      ps = p;
      ps.M = scale->asDiagonal() * p.M * scale->asDiagonal();
      ps.q = scale->cwiseProduct(p.q);
      ps.l = p.l.cwiseQuotient(*scale);
      ps.u = p.u.cwiseQuotient(*scale);
    }
    const double tol = lcp::acceptanceTolerance(p, o_.lcp_tol);
    std::ostringstream why;
    // each solver on the scaled problem, then (if that failed) on the original one
    for (size_t att = 0; att < names.size() * (scale ? 2 : 1); ++att) {
      const size_t k = scale ? att / 2 : att;
      const LVec* sc = scale && att % 2 == 0 ? scale : nullptr;
      const lcp::Problem& solved = sc ? ps : p;
      auto s = makeContactSolver(names[k]);
      if (!s) {
        why << names[k] << ": unknown solver; ";
        continue;
      }
      lcp::SolverOptions so;
      // the natural-map residual is not scale invariant: the scaled problem is solved 1000x tighter so that
      // the unscaled answer meets lcp_tol (the methods converge fast near a solution; verified below)
      so.rel_tol = sc ? 1e-3 * o_.lcp_tol : o_.lcp_tol;
      if (k == 0) so.max_iterations = o_.lcp_max_iterations; // the cap is for the primary solver only
      LVec warm_s;
      if (o_.warm_start && warm && warm->size() == p.size() && warm->allFinite()) {
        warm_s = sc ? LVec(warm->cwiseQuotient(*sc)) : *warm;
        so.warm_start = &warm_s;
      }
      *res = lcp::solve(*s, solved, so);
      st.iterations += res->iterations;
      st.pivots += res->pivots;
      const lcp::Status status = res->status;
      if (res->z.size() == p.size() && res->z.allFinite()) {
        if (sc) res->z = sc->cwiseProduct(res->z);
        lcp::evaluate(p, res); // residual on the original problem
        for (int r = 0; r < 2 && !(res->residual <= tol); ++r) {
          lcp::Result t = *res;
          if (!lcp::solveStates(p, lcp::statesFromSolution(p, res->z, res->w), &t.z)) break;
          lcp::evaluate(p, &t);
          if (!(t.residual < res->residual)) break;
          *res = t;
          ++st.refinements;
        }
      }
      // Adapter: a z whose verified natural-map residual meets the acceptance rule is a solution even when
      // the method reported another status (seen: Lemke 'ray_termination' with residual 1e-14).
      const bool verified = res->z.size() == p.size() && res->z.allFinite() && res->residual <= tol;
      if (verified) {
        res->status = lcp::Status::Solved;
        solution_ = res->z;
        st.solver = names[k];
        st.residual = std::max(st.residual, res->residual);
        return true;
      }
      ++st.fallbacks;
      why << names[k] << (scale ? (sc ? " (scaled)" : " (unscaled)") : "") << ": " << lcp::statusName(status)
          << " (residual " << res->residual << (res->message.empty() ? "" : ", " + res->message) << "); ";
    }
    st.failed = true;
    st.message = "contact problem of size " + std::to_string(p.size()) + " not solved: " + why.str();
    return false;
  };
  auto solveOne = [&](const lcp::Problem& p, const LVec* warm, lcp::Result* res) -> bool {
    std::vector<std::string> names{o_.lcp_solver};
    for (const auto& f : o_.fallback_solvers)
      if (f != o_.lcp_solver) names.push_back(f);
    return solveWith(p, names, nullptr, warm, res);
  };

  if (nc > 0 && o_.friction == FrictionModel::Polyhedral && friction) {
    // Stewart-Trinkle LCP: [lambda_n (nc), beta (nc d), gamma (nc)]
    const int d = o_.polyhedral_directions;
    std::vector<std::pair<int, Vec3>> dirs;
    std::vector<bool> isn;
    for (int i = 0; i < nc; ++i) dirs.push_back({i, cs[i].n}), isn.push_back(true);
    for (int i = 0; i < nc; ++i)
      for (int j = 0; j < d; ++j) {
        const double a = 2 * M_PI * j / d;
        dirs.push_back({i, std::cos(a) * cs[i].t1 + std::sin(a) * cs[i].t2});
        isn.push_back(false);
      }
    System sys = buildSystem(bodies, inv_i, vstar, cs, dirs, isn, o_);
    const int m = nc * (2 + d), k = nc * (1 + d);
    lcp::Problem p = polyhedralLcp(sys.A, sys.b, nc, d, o_.mu);
    if (o_.polyhedral_gamma_reg > 0)
      for (int i = 0; i < nc; ++i) {
        double abb = 0.0;
        for (int j = 0; j < d; ++j) abb += sys.A(nc + i * d + j, nc + i * d + j) / d;
        p.M(k + i, k + i) = o_.polyhedral_gamma_reg / abb;
      }
    lcp::Result res;
    std::vector<std::string> names = o_.polyhedral_solvers;
    if (names.empty()) names = {o_.lcp_solver};
    LVec scale;
    if (o_.polyhedral_scaling) scale = polyhedralScaling(p, nc, d);
    if (!solveWith(p, names, o_.polyhedral_scaling ? &scale : nullptr, nullptr, &res)) return st;
    st.rows = m;
    for (int i = 0; i < nc; ++i) {
      lam[i][0] = res.z[i];
      for (int j = 0; j < d; ++j) {
        const double a = 2 * M_PI * j / d;
        lam[i][1] += res.z[nc + i * d + j] * std::cos(a);
        lam[i][2] += res.z[nc + i * d + j] * std::sin(a);
      }
    }
    // apply
    std::vector<Vec3> dv(nb, Vec3::Zero()), dw(nb, Vec3::Zero());
    for (int r = 0; r < k; ++r) {
      const JRow& J = sys.rows[r];
      const double z = res.z[r];
      if (J.ba >= 0) dv[J.ba] += J.ma.head<3>() * z, dw[J.ba] += J.ma.tail<3>() * z;
      if (J.bb >= 0) dv[J.bb] += J.mb.head<3>() * z, dw[J.bb] += J.mb.tail<3>() * z;
    }
    for (int i = 0; i < nb; ++i) vstar[i] += dv[i], wnew[i] += dw[i];
  } else if (nc > 0) {
    // box-friction rows interleaved per contact: (n, t1, t2) or n only
    const int per = friction ? 3 : 1;
    std::vector<std::pair<int, Vec3>> dirs;
    std::vector<bool> isn;
    for (int i = 0; i < nc; ++i) {
      dirs.push_back({i, cs[i].n}), isn.push_back(true);
      if (friction) {
        dirs.push_back({i, cs[i].t1}), isn.push_back(false);
        dirs.push_back({i, cs[i].t2}), isn.push_back(false);
      }
    }
    System sys = buildSystem(bodies, inv_i, vstar, cs, dirs, isn, o_);
    // initial normal-impulse estimate nu
    std::vector<double> nu(nc, 0.0);
    for (int i = 0; i < nc; ++i) {
      switch (o_.friction) {
      case FrictionModel::Box:
        nu[i] = weightEstimate(cs[i]);
        break;
      case FrictionModel::ScaledBox:
        nu[i] = has_prev[i] ? prev[i][0] : weightEstimate(cs[i]);
        break;
      case FrictionModel::Splitting:
        nu[i] = o_.split_start == SplitStart::Zero       ? 0.0
                : o_.split_start == SplitStart::Infinite ? kInf
                                                         : (has_prev[i] ? prev[i][0] : weightEstimate(cs[i]));
        break;
      default:
        break;
      }
    }
    LVec full = LVec::Zero(nc * per);
    for (int i = 0; i < nc; ++i)
      for (int k = 0; k < per; ++k) full[i * per + k] = prev[i][k];
    const int max_pass = o_.friction == FrictionModel::Splitting ? std::max(1, o_.splitting_max_it) : 1;
    for (int pass = 0; pass < max_pass; ++pass) {
      std::vector<int> active;
      bool any_t = false;
      for (int i = 0; i < nc; ++i) {
        active.push_back(i * per);
        if (friction && o_.mu * nu[i] > 0) {
          active.push_back(i * per + 1), active.push_back(i * per + 2);
          any_t = true;
        }
      }
      const int n = (int)active.size();
      Mat M(n, n);
      LVec q(n), l(n), u(n), warm(n);
      for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) M(r, c) = sys.A(active[r], active[c]);
        q[r] = sys.b[active[r]];
        warm[r] = full[active[r]];
        const bool normal = active[r] % per == 0;
        const double bound = normal ? kInf : o_.mu * nu[active[r] / per];
        l[r] = normal ? 0.0 : -bound;
        u[r] = bound;
      }
      lcp::Problem p = any_t ? lcp::makeBox(M, q, l, u, "contact") : lcp::makeLcp(M, q, "contact");
      lcp::Result res;
      if (!solveOne(p, &warm, &res)) return st;
      st.rows = n;
      LVec next = LVec::Zero(nc * per);
      for (int r = 0; r < n; ++r) next[active[r]] = res.z[r];
      // change of the normal impulses (the fixed point of the splitting is in nu = lambda_n)
      double err = 0.0, nmax = 0.0;
      for (int i = 0; i < nc; ++i) {
        err = std::max(err, std::abs(next[i * per] - (pass == 0 ? 0.0 : full[i * per])));
        nmax = std::max(nmax, std::abs(next[i * per]));
      }
      full = next;
      for (int i = 0; i < nc; ++i)
        for (int k = 0; k < per; ++k) lam[i][k] = full[i * per + k];
      st.splitting_iterations = pass + 1;
      st.splitting_error = err;
      if (o_.friction == FrictionModel::Splitting) {
        double ratio, viol, fn;
        forceMeasures(cs, lam, o_.mu, &ratio, &viol, &fn);
        st.split_errors.push_back(err);
        st.split_ratios.push_back(ratio);
        if (pass > 0 && err <= o_.splitting_tol * (1.0 + nmax)) break;
        for (int i = 0; i < nc; ++i) nu[i] = lam[i][0];
      }
    }
    std::vector<Vec3> dv(nb, Vec3::Zero()), dw(nb, Vec3::Zero());
    for (int r = 0; r < nc * per; ++r) {
      const JRow& J = sys.rows[r];
      const double z = full[r];
      if (J.ba >= 0) dv[J.ba] += J.ma.head<3>() * z, dw[J.ba] += J.ma.tail<3>() * z;
      if (J.bb >= 0) dv[J.bb] += J.mb.head<3>() * z, dw[J.bb] += J.mb.tail<3>() * z;
    }
    for (int i = 0; i < nb; ++i) vstar[i] += dv[i], wnew[i] += dw[i];
  }
  // new state
  std::vector<Body> next = bodies;
  for (int i = 0; i < nb; ++i) {
    Body& B = next[i];
    if (B.is_static) continue;
    B.v = vstar[i];
    B.w = wnew[i];
    B.x += o_.dt * B.v;
    const double ang = B.w.norm() * o_.dt;
    if (ang > 0) B.q = (Quat(Eigen::AngleAxisd(ang, B.w.normalized())) * B.q).normalized();
    if (!B.x.allFinite() || !B.v.allFinite() || !B.w.allFinite() || !B.q.coeffs().allFinite()) {
      st.failed = true;
      st.message = "non-finite state of body '" + B.name + "' after the contact solve";
      return st;
    }
  }
  bodies.swap(next);
  impulses_ = lam;
  forceMeasures(cs, lam, o_.mu, &st.force_ratio, &st.cone_violation, &st.normal_impulse);
  prev_contacts_ = contacts_;
  prev_impulses_ = impulses_;
  return st;
}

} // namespace suite::contact
