// Contact generation: sweep-and-prune broad phase and signed-distance narrow phase (plane-*, sphere-*,
// capsule-capsule with two points for parallel line contact, box-box by face-axis SAT + clipping).
// References: see collision.hpp.
#include "contact/collision.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace suite::contact {

namespace {

using Cs = std::vector<Contact>;

void push(Cs* out, int a, int b, const Vec3& p, const Vec3& n, double phi, int feature) {
  Contact c;
  c.a = a;
  c.b = b;
  c.p = p;
  c.n = n.normalized();
  c.phi = phi;
  c.feature = feature;
  out->push_back(c);
}

// a: any finite body, b: plane.
void planeContacts(const Body& A, int a, const Body& P, int b, double margin, Cs* out) {
  const Vec3 n = P.planeNormal();
  const double d = P.planeOffset();
  const Mat3 R = A.R();
  switch (A.shape.type) {
  case ShapeType::Sphere: {
    const double phi = n.dot(A.x) - d - A.shape.radius;
    if (phi < margin) push(out, a, b, A.x - A.shape.radius * n, n, phi, 0);
    break;
  }
  case ShapeType::Box: {
    std::array<std::pair<double, int>, 8> corners;
    int nk = 0;
    for (int k = 0; k < 8; ++k) {
      const Vec3 s((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      const Vec3 c = A.x + R * s.cwiseProduct(A.shape.half);
      const double phi = n.dot(c) - d;
      if (phi < margin) { // kept sorted by (phi, k) as they come (std::sort on the first nk made GCC 12 warn)
        const std::pair<double, int> corner{phi, k};
        int i = nk++;
        for (; i > 0 && corner < corners[(size_t)i - 1]; --i) corners[(size_t)i] = corners[(size_t)i - 1];
        corners[(size_t)i] = corner;
      }
    }
    for (int i = 0; i < std::min(nk, 4); ++i) {
      const auto [phi, k] = corners[i];
      const Vec3 s((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      push(out, a, b, A.x + R * s.cwiseProduct(A.shape.half), n, phi, k);
    }
    break;
  }
  case ShapeType::Capsule: {
    const Vec3 ax = R.col(2);
    for (int k = 0; k < 2; ++k) {
      const Vec3 e = A.x + (k ? 1.0 : -1.0) * A.shape.half_length * ax;
      const double phi = n.dot(e) - d - A.shape.radius;
      if (phi < margin) push(out, a, b, e - A.shape.radius * n, n, phi, k);
    }
    break;
  }
  case ShapeType::Cylinder: {
    const Vec3 ax = R.col(2);
    const Vec3 np = n - n.dot(ax) * ax;
    for (int k = 0; k < 2; ++k) {
      const Vec3 e = A.x + (k ? 1.0 : -1.0) * A.shape.half_length * ax;
      if (np.norm() > 1e-6) {
        const Vec3 p = e - A.shape.radius * np.normalized();
        const double phi = n.dot(p) - d;
        if (phi < margin) push(out, a, b, p, n, phi, k);
      } else { // axis along the normal: four rim points of the cap
        for (int j = 0; j < 4; ++j) {
          const Vec3 p = e + A.shape.radius * R.col(j % 2) * (j < 2 ? 1.0 : -1.0);
          const double phi = n.dot(p) - d;
          if (phi < margin) push(out, a, b, p, n, phi, 2 + 4 * k + j);
        }
      }
    }
    break;
  }
  case ShapeType::Plane:
    break;
  }
}

// Two spheres (centres ca, cb, radii ra, rb); n from b to a. fallback_n when the centres coincide.
void sphereSphere(int a, int b, const Vec3& ca, double ra, const Vec3& cb, double rb, double margin,
                  const Vec3& fallback_n, int feature, Cs* out) {
  const Vec3 d = ca - cb;
  const double dist = d.norm();
  const double phi = dist - ra - rb;
  if (phi >= margin) return;
  const Vec3 n = dist > 1e-12 ? Vec3(d / dist) : fallback_n;
  push(out, a, b, ca - ra * n, n, phi, feature);
}

// Closest point of segment [p0, p1] to x.
Vec3 closestOnSegment(const Vec3& p0, const Vec3& p1, const Vec3& x) {
  const Vec3 d = p1 - p0;
  const double l2 = d.squaredNorm();
  double t = l2 > 0 ? (x - p0).dot(d) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return p0 + t * d;
}

// Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9).
void closestSegmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, Vec3* c1,
                           Vec3* c2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  const double c = d1.dot(r), b = d1.dot(d2), den = a * e - b * b;
  if (den > 1e-14 * a * e) s = std::clamp((b * f - c * e) / den, 0.0, 1.0);
  t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  *c1 = p1 + s * d1;
  *c2 = p2 + t * d2;
}

// Capsule (or cylinder treated as capsule) pair: one point, or two at the ends of the overlap of nearly
// parallel axes (line contact).
void capsuleCapsule(const Body& A, int a, const Body& B, int b, double margin, Cs* out) {
  const Vec3 da = A.axis(), db = B.axis();
  const double ha = A.shape.half_length, hb = B.shape.half_length;
  const Vec3 a0 = A.x - ha * da, a1 = A.x + ha * da, b0 = B.x - hb * db, b1 = B.x + hb * db;
  Vec3 fallback = A.x - B.x;
  fallback = fallback.norm() > 1e-12 ? Vec3(fallback.normalized()) : Vec3::UnitZ();
  if (std::abs(da.dot(db)) > 1 - 1e-6) {
    // parameters of b's ends along a's axis, clipped to a's segment
    double t0 = (b0 - A.x).dot(da), t1 = (b1 - A.x).dot(da);
    if (t0 > t1) std::swap(t0, t1);
    t0 = std::max(t0, -ha);
    t1 = std::min(t1, ha);
    if (t1 - t0 > 1e-9 * (ha + hb)) {
      int f = 0;
      for (double t : {t0, t1}) {
        const Vec3 pa = A.x + t * da;
        const Vec3 pb = closestOnSegment(b0, b1, pa);
        sphereSphere(a, b, pa, A.shape.radius, pb, B.shape.radius, margin, fallback, f++, out);
      }
      return;
    }
  }
  Vec3 pa, pb;
  closestSegmentSegment(a0, a1, b0, b1, &pa, &pb);
  Vec3 fb = da.cross(db);
  if (fb.norm() > 1e-12)
    fb = fb.dot(A.x - B.x) >= 0 ? Vec3(fb.normalized()) : Vec3(-fb.normalized());
  else
    fb = fallback;
  sphereSphere(a, b, pa, A.shape.radius, pb, B.shape.radius, margin, fb, 0, out);
}

// Sphere (centre c, radius r, index a) against box B (index b).
void sphereBox(int a, const Vec3& c, double r, const Body& B, int b, double margin, int feature, Cs* out) {
  const Mat3 R = B.R();
  const Vec3 local = R.transpose() * (c - B.x);
  const Vec3 h = B.shape.half;
  const Vec3 cl = local.cwiseMax(-h).cwiseMin(h);
  if ((cl - local).squaredNorm() > 0) { // centre outside the box
    const Vec3 d = local - cl;
    const double dist = d.norm();
    const double phi = dist - r;
    if (phi < margin) {
      const Vec3 n = R * (d / dist);
      push(out, a, b, c - r * n, n, phi, feature);
    }
    return;
  }
  int k = 0;
  double best = INFINITY;
  for (int j = 0; j < 3; ++j) {
    const double pen = h[j] - std::abs(local[j]);
    if (pen < best) best = pen, k = j;
  }
  Vec3 nl = Vec3::Zero();
  nl[k] = local[k] >= 0 ? 1.0 : -1.0;
  const Vec3 n = R * nl;
  push(out, a, b, c - r * n, n, -best - r, feature);
}

// Face axes of the box-box SAT: the largest separation s over the three face normals of each box (a later axis
// only when clearly larger); *owner: 0 for A's faces, 1 for B's.
double faceAxis(const Body& A, const Body& B, const Mat3& Ra, const Mat3& Rb, const Vec3& d, int* owner,
                int* axis) {
  double best = -INFINITY;
  for (int o = 0; o < 2; ++o) {
    const Mat3& Ro = o == 0 ? Ra : Rb;
    for (int k = 0; k < 3; ++k) {
      const Vec3 L = Ro.col(k);
      double ra = 0, rb = 0;
      for (int j = 0; j < 3; ++j) {
        ra += A.shape.half[j] * std::abs(L.dot(Ra.col(j)));
        rb += B.shape.half[j] * std::abs(L.dot(Rb.col(j)));
      }
      const double s = std::abs(d.dot(L)) - ra - rb;
      const double bias = 1e-9 * (A.shape.half.norm() + B.shape.half.norm());
      if (s > best + bias) best = s, *owner = o, *axis = k;
    }
  }
  return best;
}

// The nine edge-edge axes (Gottschalk, Lin & Manocha 1996): taken only when clearly better than every face
// axis (best), so that face contacts (several points) are kept for resting and stacked boxes. Returns the
// largest separation (best if no edge axis is taken, *ei = -1).
double edgeAxis(const Body& A, const Body& B, const Mat3& Ra, const Mat3& Rb, const Vec3& d, double best,
                int* ei, int* ej) {
  const double scale = A.shape.half.norm() + B.shape.half.norm();
  double ebest = best;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Vec3 L = Ra.col(i).cross(Rb.col(j));
      const double ln = L.norm();
      if (ln < 1e-6) continue; // parallel edges: a face axis separates as well
      L /= ln;
      double ra = 0, rb = 0;
      for (int k = 0; k < 3; ++k) {
        ra += A.shape.half[k] * std::abs(L.dot(Ra.col(k)));
        rb += B.shape.half[k] * std::abs(L.dot(Rb.col(k)));
      }
      const double s = std::abs(d.dot(L)) - ra - rb;
      if (s > ebest + 1e-4 * scale) ebest = s, *ei = i, *ej = j;
    }
  return ebest;
}

// Edge-edge contact: one point between edge ei of A and edge ej of B.
void edgeEdge(const Body& A, int a, const Body& B, int b, const Mat3& Ra, const Mat3& Rb, const Vec3& d,
              int ei, int ej, Cs* out) {
  Vec3 L = Ra.col(ei).cross(Rb.col(ej)).normalized();
  if (L.dot(d) < 0) L = -L; // from A towards B
  Vec3 pa = A.x, pb = B.x;  // centres of the nearest edges
  for (int k = 0; k < 3; ++k) {
    if (k != ei) pa += (L.dot(Ra.col(k)) > 0 ? 1.0 : -1.0) * A.shape.half[k] * Ra.col(k);
    if (k != ej) pb -= (L.dot(Rb.col(k)) > 0 ? 1.0 : -1.0) * B.shape.half[k] * Rb.col(k);
  }
  // closest points of the two edge lines pa + s ua, pb + t ub, clamped to the edges
  const Vec3 ua = Ra.col(ei), ub = Rb.col(ej), w = pa - pb;
  const double bb = ua.dot(ub), dd = ua.dot(w), ee = ub.dot(w), den = 1.0 - bb * bb;
  double sa = den > 1e-12 ? (bb * ee - dd) / den : 0.0;
  sa = std::clamp(sa, -A.shape.half[ei], A.shape.half[ei]);
  double tb = std::clamp(ee + bb * sa, -B.shape.half[ej], B.shape.half[ej]);
  sa = std::clamp(bb * tb - dd, -A.shape.half[ei], A.shape.half[ei]);
  const Vec3 ca = pa + sa * ua, cb = pb + tb * ub;
  push(out, a, b, 0.5 * (ca + cb), -L, (cb - ca).dot(L), 0); // normal from b into a
}

// A convex polygon of at most 8 vertices (a quad clipped by 4 planes gains at most one vertex per plane), and
// the contact points taken from it: fixed capacity, nothing allocated per pair.
struct Poly {
  std::array<Vec3, 8> v;
  int n = 0;
};
struct Points {
  std::array<std::pair<Vec3, double>, 8> v;
  int n = 0;
};

// Sutherland-Hodgman: poly clipped against the four side planes s . (p - fc) <= e of the reference face
// (false: nothing left).
bool clipToFace(const Vec3& fc, const Vec3& u1, double e1, const Vec3& u2, double e2, Poly* poly) {
  const std::array<std::pair<Vec3, double>, 4> planes = {
      std::make_pair(u1, e1), std::make_pair(Vec3(-u1), e1), std::make_pair(u2, e2),
      std::make_pair(Vec3(-u2), e2)};
  for (const auto& [s, e] : planes) {
    Poly next;
    for (int i = 0; i < poly->n; ++i) {
      const Vec3& P = poly->v[i];
      const Vec3& Q = poly->v[(i + 1) % poly->n];
      const double dp = s.dot(P - fc) - e, dq = s.dot(Q - fc) - e;
      if (dp <= 0 && next.n < 8) next.v[next.n++] = P;
      if (((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) && next.n < 8)
        next.v[next.n++] = P + (Q - P) * (dp / (dp - dq));
    }
    *poly = next;
    if (poly->n == 0) return false;
  }
  return true;
}

// More than 4 points: keep the extreme points along the diagonals of the reference face (axes u1, u2).
void keepFour(const Vec3& u1, const Vec3& u2, Points* pts) {
  Points keep;
  for (const Vec3& dir : {Vec3(u1 + u2), Vec3(u1 - u2), Vec3(-u1 - u2), Vec3(-u1 + u2)}) {
    int bi = 0;
    for (int i = 1; i < pts->n; ++i)
      if (pts->v[i].first.dot(dir) > pts->v[bi].first.dot(dir)) bi = i;
    bool dup = false;
    for (int k = 0; k < keep.n; ++k) dup = dup || (keep.v[k].first - pts->v[bi].first).norm() < 1e-12;
    if (!dup) keep.v[keep.n++] = pts->v[bi];
  }
  *pts = keep;
}

// Face contact: the incident face of the other box clipped by face `axis` of the reference box (owner 0: A,
// 1: B), up to 4 points.
void faceContact(const Body& A, int a, const Body& B, int b, const Mat3& Ra, const Mat3& Rb, int owner,
                 int axis, double margin, Cs* out) {
  const Body& Rf = owner == 0 ? A : B;
  const Body& In = owner == 0 ? B : A;
  const Mat3& Rr = owner == 0 ? Ra : Rb;
  const Mat3& Ri = owner == 0 ? Rb : Ra;
  Vec3 nr = Rr.col(axis);
  if (nr.dot(In.x - Rf.x) < 0) nr = -nr; // from reference to incident
  const Vec3 fc = Rf.x + Rf.shape.half[axis] * nr;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Vec3 u1 = Rr.col(u), u2 = Rr.col(v);
  const double e1 = Rf.shape.half[u], e2 = Rf.shape.half[v];
  int j = 0;
  double most = -1;
  for (int k = 0; k < 3; ++k)
    if (std::abs(Ri.col(k).dot(nr)) > most) most = std::abs(Ri.col(k).dot(nr)), j = k;
  const double sgn = Ri.col(j).dot(nr) > 0 ? -1.0 : 1.0;
  const Vec3 ic = In.x + sgn * In.shape.half[j] * Ri.col(j);
  const int iu = (j + 1) % 3, iv = (j + 2) % 3;
  const Vec3 w1 = Ri.col(iu) * In.shape.half[iu], w2 = Ri.col(iv) * In.shape.half[iv];
  Poly poly;
  poly.v = {ic + w1 + w2, ic - w1 + w2, ic - w1 - w2, ic + w1 - w2}, poly.n = 4;
  if (!clipToFace(fc, u1, e1, u2, e2, &poly)) return;
  Points pts;
  for (int i = 0; i < poly.n; ++i) {
    const double phi = (poly.v[i] - fc).dot(nr);
    if (phi < margin) pts.v[pts.n++] = {poly.v[i], phi};
  }
  if (pts.n > 4) keepFour(u1, u2, &pts);
  const Vec3 n = (&In == &A) ? nr : Vec3(-nr); // from b into a
  for (int f = 0; f < pts.n; ++f) push(out, a, b, pts.v[f].first, n, pts.v[f].second, f);
}

// Box-box: separating axis over the six face axes and the nine edge-edge axes; a face axis gives the incident
// face clipped by the reference face (up to 4 points), an edge-edge axis one point between the two edges.
void boxBox(const Body& A, int a, const Body& B, int b, double margin, Cs* out) {
  const Mat3 Ra = A.R(), Rb = B.R();
  const Vec3 d = B.x - A.x;
  int owner = 0, axis = 0, ei = -1, ej = -1;
  const double best = faceAxis(A, B, Ra, Rb, d, &owner, &axis);
  const double ebest = edgeAxis(A, B, Ra, Rb, d, best, &ei, &ej);
  if (std::max(best, ebest) >= margin) return;
  if (ei >= 0)
    edgeEdge(A, a, B, b, Ra, Rb, d, ei, ej, out);
  else
    faceContact(A, a, B, b, Ra, Rb, owner, axis, margin, out);
}

bool roundish(ShapeType t) {
  return t == ShapeType::Capsule || t == ShapeType::Cylinder;
}

} // namespace

void collide(const std::vector<Body>& bodies, int ia, int ib, double margin, std::vector<Contact>* out) {
  const Body& A = bodies[ia];
  const Body& B = bodies[ib];
  const ShapeType ta = A.shape.type, tb = B.shape.type;
  if (ta == ShapeType::Plane && tb == ShapeType::Plane) return;
  if (tb == ShapeType::Plane) return planeContacts(A, ia, B, ib, margin, out);
  if (ta == ShapeType::Plane) return planeContacts(B, ib, A, ia, margin, out);
  if (ta == ShapeType::Sphere && tb == ShapeType::Sphere)
    return sphereSphere(ia, ib, A.x, A.shape.radius, B.x, B.shape.radius, margin, Vec3::UnitZ(), 0, out);
  if (ta == ShapeType::Sphere && tb == ShapeType::Box)
    return sphereBox(ia, A.x, A.shape.radius, B, ib, margin, 0, out);
  if (ta == ShapeType::Box && tb == ShapeType::Sphere)
    return sphereBox(ib, B.x, B.shape.radius, A, ia, margin, 0, out);
  if (ta == ShapeType::Box && tb == ShapeType::Box) return boxBox(A, ia, B, ib, margin, out);
  if (roundish(ta) && roundish(tb)) return capsuleCapsule(A, ia, B, ib, margin, out);
  if (ta == ShapeType::Sphere && roundish(tb)) {
    const Vec3 c =
        closestOnSegment(B.x - B.shape.half_length * B.axis(), B.x + B.shape.half_length * B.axis(), A.x);
    return sphereSphere(ia, ib, A.x, A.shape.radius, c, B.shape.radius, margin, Vec3::UnitZ(), 0, out);
  }
  if (roundish(ta) && tb == ShapeType::Sphere) return collide(bodies, ib, ia, margin, out);
  if (roundish(ta) && tb == ShapeType::Box) { // the two end spheres of the capsule against the box
    for (int k = 0; k < 2; ++k)
      sphereBox(ia, A.x + (k ? 1.0 : -1.0) * A.shape.half_length * A.axis(), A.shape.radius, B, ib, margin, k,
                out);
    return;
  }
  if (ta == ShapeType::Box && roundish(tb)) return collide(bodies, ib, ia, margin, out);
  throw SceneError(std::string("no contact generator for the pair ") + shapeName(ta) + "-" + shapeName(tb));
}

double stepReach(const Body& b, double dt, const Vec3& gravity) {
  if (b.is_static) return 0.0;
  const double r = b.boundingRadius();
  return dt * (b.v.norm() + b.w.norm() * r + gravity.norm() * dt);
}

std::vector<std::pair<int, int>> broadPhase(const std::vector<Body>& bodies, double margin,
                                            bool include_static_pairs, const std::vector<double>* reach) {
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> finite, planes;
  for (int i = 0; i < (int)bodies.size(); ++i)
    (bodies[i].shape.type == ShapeType::Plane ? planes : finite).push_back(i);
  for (int p : planes)
    for (int i : finite)
      if (!bodies[i].is_static || include_static_pairs) pairs.push_back({i, p});
  struct Box {
    Vec3 lo, hi;
    int id;
  };
  std::vector<Box> boxes;
  boxes.reserve(finite.size());
  for (int i : finite) {
    const double r = bodies[i].boundingRadius() + margin + (reach ? (*reach)[i] : 0.0);
    boxes.push_back({bodies[i].x.array() - r, bodies[i].x.array() + r, i});
  }
  std::sort(boxes.begin(), boxes.end(), [](const Box& x, const Box& y) { return x.lo.x() < y.lo.x(); });
  for (size_t i = 0; i < boxes.size(); ++i) {
    for (size_t j = i + 1; j < boxes.size() && boxes[j].lo.x() <= boxes[i].hi.x(); ++j) {
      const Box &p = boxes[i], &q = boxes[j];
      if (p.lo.y() > q.hi.y() || q.lo.y() > p.hi.y() || p.lo.z() > q.hi.z() || q.lo.z() > p.hi.z()) continue;
      if (bodies[p.id].is_static && bodies[q.id].is_static && !include_static_pairs) continue;
      pairs.push_back({std::min(p.id, q.id), std::max(p.id, q.id)});
    }
  }
  return pairs;
}

Vec3 relativeVelocity(const std::vector<Body>& bodies, const Contact& c) {
  const Body& A = bodies[c.a];
  const Body& B = bodies[c.b];
  const Vec3 va = A.v + A.w.cross(c.p - A.x);
  const Vec3 vb = B.v + B.w.cross(c.p - B.x);
  return va - vb;
}

std::vector<Contact> findContacts(const std::vector<Body>& bodies, double margin, const Vec3& gravity,
                                  double dt, double slip_eps) {
  std::vector<Contact> cs;
  cs.reserve(4 * bodies.size()); // a resting box: about 4 points
  std::vector<double> reach(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) reach[i] = stepReach(bodies[i], dt, gravity);
  for (auto& [i, j] : broadPhase(bodies, margin, false, &reach))
    collide(bodies, i, j, margin + reach[i] + reach[j], &cs);
  for (Contact& c : cs) {
    const Vec3 vr = relativeVelocity(bodies, c);
    Vec3 vt = vr - vr.dot(c.n) * c.n;
    const Vec3 gt = gravity - gravity.dot(c.n) * c.n;
    Vec3 t;
    if (vt.norm() > slip_eps)
      t = vt.normalized();
    else if (gt.norm() > 1e-9 * (1 + gravity.norm()))
      t = -gt.normalized(); // uphill: friction direction at rest
    else
      t = std::abs(c.n.x()) < 0.9 ? Vec3(Vec3::UnitX() - c.n.x() * c.n) : Vec3(Vec3::UnitY() - c.n.y() * c.n);
    c.t1 = t.normalized();
    c.t2 = c.n.cross(c.t1);
  }
  return cs;
}

} // namespace suite::contact
