// The Delassus system of the contact constraints (see delassus.hpp).
#include "contact/delassus.hpp"

#include "contact/body_space_solve.hpp"
#include "contact/delassus_sparse.hpp"
#include "contact/stepper.hpp"

namespace suite::contact {

namespace {

V6 jacobian(const Body& B, const Vec3& p, const Vec3& dir, double sign) {
  V6 j;
  j.head<3>() = sign * dir;
  j.tail<3>() = sign * (p - B.x).cross(dir);
  return j;
}

// (J M^-1 J^T)_rr of one row, without the compliance.
double bareDiagonal(const JRow& J) {
  return (J.ba >= 0 ? J.ja.dot(J.ma) : 0.0) + (J.bb >= 0 ? J.jb.dot(J.mb) : 0.0);
}

V6 applyInvMass(const Body& B, const Mat3& inv_i, const V6& j) {
  V6 m;
  m.head<3>() = B.inv_mass * j.head<3>();
  m.tail<3>() = inv_i * j.tail<3>();
  return m;
}

// A = J M^-1 J^T from the rows (only the bodies the two rows share contribute), upper triangle mirrored.
lcp::Mat delassusMatrix(const std::vector<JRow>& rows) {
  const int n = (int)rows.size();
  lcp::Mat A = lcp::Mat::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    const JRow& R = rows[r];
    for (int q = r; q < n; ++q) {
      const JRow& Q = rows[q];
      double v = 0.0;
      if (R.ba >= 0 && R.ba == Q.ba) v += R.ja.dot(Q.ma);
      if (R.ba >= 0 && R.ba == Q.bb) v += R.ja.dot(Q.mb);
      if (R.bb >= 0 && R.bb == Q.ba) v += R.jb.dot(Q.ma);
      if (R.bb >= 0 && R.bb == Q.bb) v += R.jb.dot(Q.mb);
      A(r, q) = A(q, r) = v;
    }
  }
  return A;
}

} // namespace

DelassusSystem buildDelassus(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o) {
  return buildDelassus(bodies, inv_i, vstar, cs, rows, o, false);
}

DelassusSystem buildDelassus(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o, bool sparse,
                             bool defer_S) {
  DelassusSystem s;
  s.sparse = sparse;
  s.nbodies = (int)bodies.size();
  const int n = (int)rows.size();
  s.rows.resize(n);
  s.b.resize(n);
  for (int r = 0; r < n; ++r) {
    const Contact& c = cs[rows[r].contact];
    const Vec3& d = rows[r].dir;
    JRow& J = s.rows[r];
    const Body& A = bodies[c.a];
    const Body& B = bodies[c.b];
    J.ja = jacobian(A, c.p, d, 1.0);
    J.jb = jacobian(B, c.p, d, -1.0);
    J.ba = A.is_static ? -1 : c.a, J.bb = B.is_static ? -1 : c.b;
    J.ma = A.is_static ? V6::Zero().eval() : applyInvMass(A, inv_i[c.a], J.ja);
    J.mb = B.is_static ? V6::Zero().eval() : applyInvMass(B, inv_i[c.b], J.jb);
    V6 va, vb;
    va << vstar[c.a], A.w;
    vb << vstar[c.b], B.w;
    double rhs = J.ja.dot(va) + J.jb.dot(vb);
    if (rows[r].normal) rhs += (c.phi >= 0 ? c.phi : o.baumgarte * c.phi) / o.dt;
    s.b[r] = rhs;
  }
  std::vector<double> scale(n);
  for (int r = 0; r < n; ++r) scale[r] = rows[r].normal ? o.regularisation : o.regularisation_t;
  if (sparse) {
    s.reg.resize(n);
    for (int r = 0; r < n; ++r) { // as A_ii - (J M^-1 J^T)_ii from S (the same rounding)
      const double d = bareDiagonal(s.rows[r]);
      s.reg[r] = d * (1.0 + scale[r]) - d;
    }
    s.scale = std::move(scale);
    s.S_deferred = defer_S;
    if (!defer_S) s.S = sparseDelassus(s.rows, s.nbodies, s.scale);
    s.mass = bodyMassMatrices(bodies, inv_i);
    return s;
  }
  s.A = delassusMatrix(s.rows);
  for (int r = 0; r < n; ++r) s.A(r, r) *= 1.0 + scale[r];
  return s;
}

double delassusDiagonal(const DelassusSystem& sys, int r) {
  return sys.sparse ? bareDiagonal(sys.rows[r]) + sys.reg[r] : sys.A(r, r);
}

const SpMat& sparseMatrix(const DelassusSystem& sys) {
  if (sys.S_deferred) sys.S = sparseDelassus(sys.rows, sys.nbodies, sys.scale), sys.S_deferred = false;
  return sys.S;
}

lcp::Mat denseDelassus(const DelassusSystem& sys) {
  return sys.sparse ? lcp::Mat(sparseMatrix(sys)) : sys.A;
}

void applyImpulses(const DelassusSystem& sys, const lcp::Vec& z, std::vector<Vec3>* v, std::vector<Vec3>* w) {
  const size_t nb = v->size();
  std::vector<Vec3> dv(nb, Vec3::Zero()), dw(nb, Vec3::Zero());
  for (size_t r = 0; r < sys.rows.size(); ++r) {
    const JRow& J = sys.rows[r];
    if (J.ba >= 0) dv[J.ba] += J.ma.head<3>() * z[r], dw[J.ba] += J.ma.tail<3>() * z[r];
    if (J.bb >= 0) dv[J.bb] += J.mb.head<3>() * z[r], dw[J.bb] += J.mb.tail<3>() * z[r];
  }
  for (size_t i = 0; i < nb; ++i) (*v)[i] += dv[i], (*w)[i] += dw[i];
}

} // namespace suite::contact
