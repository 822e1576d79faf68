// Block projected Gauss-Seidel over contact manifolds: the rows of all contacts between the same two bodies
// (a box face on a box face: 4 corner points, nearly dependent rows) are one block, solved together in each
// sweep instead of row by row. Per block and sweep, for the normal rows' small LCP  w = D z + q >= 0, z >= 0,
// z'w = 0 (D the block of the Delassus matrix, regularised diagonal included, q from the current body
// velocities): one proximal step x = z0 - (D + P)^-1 w(z0) (P = 1e-2 diag(D); (D + P)^-1 formed once per step),
// taken when it stays within the bounds, else 2 projected Gauss-Seidel iterations on (D + P) x = P z0 - q from
// the clamped z0; then the tangent rows the same way on their box |z_t| <= mu z_n (bounds read from the new
// normal impulses). Its fixed points are the block LCP's (x = z0 iff the block is solved); the proximal term
// (Rockafellar, SIAM J. Control Optim. 14 (1976)) keeps the step off the corners' nearly dependent directions. Point-by-point PGS spreads the load of a face over
// its corners slowly (the corners' torques overshoot one another) and leaves tilting errors that accumulate into
// drift; the block answer balances the face's force and torques in one update.
// References: Erleben, "Numerical methods for linear complementarity problems in physics-based animation",
// SIGGRAPH 2013 course notes (blocked Gauss-Seidel, per-contact and per-body-pair blocks); Catto, "Iterative
// dynamics with temporal coherence", GDC 2005 (sequential impulses, warm starting); the two-point block solver of
// Box2D (Catto, Box2D b2ContactSolver, 2009) generalised to a manifold of any size.
#pragma once

#include "contact/sparse_box_lcp.hpp"

namespace suite::contact {

// Up to max_sweeps block sweeps from z (blocks: the contacts of cs grouped by body pair, in the order their
// first rows appear in p.order; per = rows per contact, 1 or 3 (n, t1, t2)); every other sweep backwards when
// p.symmetric. Stops after a sweep that changes no row velocity by more than tol. Returns the sweeps made.
// before_sweep (may be null): called with z before each sweep, it may change p.b (the joint block's answer to z,
// contact_accuracy.hpp); the stop test then also needs the change of b below tol.
int blockPgsSweeps(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per, int max_sweeps, double tol,
                   lcp::Vec* z, const std::function<double(const lcp::Vec&)>* before_sweep = nullptr);

} // namespace suite::contact
