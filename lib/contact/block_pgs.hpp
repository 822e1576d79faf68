// Block projected Gauss-Seidel over contact manifolds: the rows of all contacts between the same two bodies
// (a box face on a box face: 4 corner points, nearly dependent rows) are one block, solved together in each
// sweep instead of row by row. Per block and sweep: the normal rows' small LCP  D z + q = w >= 0, z >= 0, z'w = 0
// (D the block of the Delassus matrix, regularised diagonal included, q from the current body velocities) is
// solved by its all-pressed answer z = -D^-1 q (LDL^T of D, factored once per step) when that is >= 0, else by
// inner projected Gauss-Seidel iterations on D; then the tangent rows the same way on their box
// |z_t| <= mu z_n (bounds read from the new normal impulses). Point-by-point PGS spreads the load of a face over
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
// p.symmetric. Stops after a sweep whose max |change| <= tol. Returns the sweeps made.
int blockPgsSweeps(const SparseBoxLcp& p, const std::vector<Contact>& cs, int per, int max_sweeps, double tol,
                   lcp::Vec* z);

} // namespace suite::contact
