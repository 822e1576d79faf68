// Contact generation: sweep-and-prune broad phase (O(n log n) plus the overlapping pairs) and
// signed-distance narrow phase for every shape pair, with contact frames (normal + two tangents).
// References: Baraff, "Physically based modeling" (SIGGRAPH 1997 course notes) for the pair tests;
// box-box by the separating-axis test on face axes and Sutherland-Hodgman clipping of the incident face
// against the reference face (as in ODE's dBoxBox); sweep and prune after Cohen et al., I-COLLIDE (1995).
#pragma once

#include "contact/body.hpp"

#include <utility>
#include <vector>

namespace suite::contact {

// One contact point between bodies a and b (b may be static). The normal n points from b into a: the
// normal impulse lambda_n >= 0 acts on a along +n and on b along -n. phi is the signed distance along n
// (< 0: penetration). t1, t2 complete an orthonormal frame.
struct Contact {
  int a = -1, b = -1;
  Vec3 p = Vec3::Zero(), n = Vec3::UnitZ(), t1 = Vec3::UnitX(), t2 = Vec3::UnitY();
  double phi = 0.0;
  int feature = 0; // index of the point within its pair (for matching between steps)
};

// Narrow phase of one pair: appends the contact points with phi < margin. Throws SceneError for a pair
// without a generator (none left: cylinders act as capsules except against planes).
void collide(const std::vector<Body>& bodies, int ia, int ib, double margin, std::vector<Contact>* out);

// Sweep and prune along x of the bounding boxes (radius + margin + reach) of the finite bodies, plus every
// (dynamic body, plane) pair. Pairs of two static bodies are skipped unless include_static_pairs.
std::vector<std::pair<int, int>> broadPhase(const std::vector<Body>& bodies, double margin,
                                            bool include_static_pairs = false,
                                            const std::vector<double>* reach = nullptr);

// How far a body can move in one step: dt (|v| + |w| r + |g| dt) (0 for static bodies). Contacts are
// generated speculatively for phi < margin + reach_a + reach_b, so no contact is missed within a step.
double stepReach(const Body& b, double dt, const Vec3& gravity);

// Broad + narrow phase, then the tangent frames: t1 along the relative tangential velocity when it is
// above slip_eps, else along the downhill direction of gravity, else any direction normal to n.
// dt > 0 enables the speculative reach.
std::vector<Contact> findContacts(const std::vector<Body>& bodies, double margin, const Vec3& gravity,
                                  double dt = 0.0, double slip_eps = 1e-9);

// Relative velocity of a with respect to b at the contact point.
Vec3 relativeVelocity(const std::vector<Body>& bodies, const Contact& c);

} // namespace suite::contact
