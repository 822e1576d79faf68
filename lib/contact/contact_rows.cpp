// The contact rows of a matrix-free step (see contact_rows.hpp).
#include "contact/contact_rows.hpp"

#include "contact/stepper.hpp"

namespace suite::contact {

namespace {
// sign [dir; (p - x) x dir] of body B at p (the row's Jacobian block, as in delassus.cpp).
V6 jacobianBlock(const Body& B, const Vec3& p, const Vec3& dir, double sign) {
  V6 j;
  j.head<3>() = sign * dir;
  j.tail<3>() = sign * (p - B.x).cross(dir);
  return j;
}

V6 invMassTimes(const Body& B, const Mat3& inv_i, const V6& j) {
  V6 m;
  m.head<3>() = B.inv_mass * j.head<3>();
  m.tail<3>() = inv_i * j.tail<3>();
  return m;
}
} // namespace

ContactRows buildContactRows(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o) {
  ContactRows out;
  DelassusSystem& s = out.sys;
  s.sparse = true;
  s.nbodies = (int)bodies.size();
  const int n = (int)rows.size();
  s.rows.resize(n);
  s.b.resize(n);
  out.reg.resize(n);
  for (int r = 0; r < n; ++r) {
    const Contact& c = cs[rows[r].contact];
    const Body& A = bodies[c.a];
    const Body& B = bodies[c.b];
    JRow& J = s.rows[r];
    J.ja = jacobianBlock(A, c.p, rows[r].dir, 1.0);
    J.jb = jacobianBlock(B, c.p, rows[r].dir, -1.0);
    if (!A.is_static) J.ba = c.a, J.ma = invMassTimes(A, inv_i[c.a], J.ja);
    if (!B.is_static) J.bb = c.b, J.mb = invMassTimes(B, inv_i[c.b], J.jb);
    V6 va, vb;
    va << vstar[c.a], A.w;
    vb << vstar[c.b], B.w;
    s.b[r] = J.ja.dot(va) + J.jb.dot(vb);
    if (rows[r].normal) s.b[r] += (c.phi >= 0 ? c.phi : o.baumgarte * c.phi) / o.dt;
    const double bare = (J.ba >= 0 ? J.ja.dot(J.ma) : 0.0) + (J.bb >= 0 ? J.jb.dot(J.mb) : 0.0);
    out.reg[r] = (rows[r].normal ? o.regularisation : o.regularisation_t) * bare;
  }
  return out;
}

} // namespace suite::contact
