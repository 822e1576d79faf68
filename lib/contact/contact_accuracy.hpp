// -contact_accuracy: where a contact step sits on the speed/accuracy trade.
//   exact     every problem solved to the acceptance rule (residual <= lcp_tol (1 + |b|_inf)) by the
//             friction formulation's solver chain (sparse first above StepperOptions::dense_max_rows, see
//             box_lcp.cpp), with its fallbacks; a step no solver answers ends the run.
//   balanced  one box LCP per step with the Coulomb bounds |lambda_t| <= mu lambda_n read from the current
//             normal impulse during the sweeps (splitting; box / scaled_box: their estimates), solved by at
//             most -contact_sweeps (default max(40, H^2 / 10), below) symmetric block projected Gauss-Seidel sweeps over the contact
//             manifolds (block_pgs.hpp) in height order, matrix-free, warm-started from the previous step's
//             matching contacts (tangential impulses turned into the new frames), then one splitting pass: the
//             bounds frozen at mu lambda_n and 1 sparse active-set factorisation (its answer kept when it solves
//             that pass or lowers the residual; it makes a stack exact, on a pyramid it is never kept).
//   fast      at most max(10, H^2 / 10) block sweeps (-contact_sweeps), no factorisation, no Delassus matrix formed (the
//             deferred S of delassus.hpp is never asked for).
// Both use Baumgarte factor -contact_budget_baumgarte (0.05) instead of -baumgarte (0.2): the penetration an
// unconverged answer leaves (~1e-3 m) biases the next step's b by beta phi / dt, 0.02 m/s at 0.2, more than the
// sweeps remove; measured on the base-10 pyramid (200 steps): drift 7.7e-3 m (fast) / 4.0e-3 (balanced) at
// 0.2, 3.3e-4 / 1.1e-4 at 0.05.
// Point-by-point PGS (pgsSweeps) left a base-10 pyramid drifting 1.4e-2 (fast) / 1.8e-2 m (balanced) in 2 s.
// balanced and fast never end the run for accuracy: the step goes on and its natural-map residual
// (complementarity error, of the box LCP with the bounds mu lambda_n of the answer), cone violation and
// penetration are recorded (StepStats, /steps in the output). Sequential impulses with warm starting: Catto,
// "Iterative dynamics with temporal coherence", GDC 2005; Erleben, ACM TOG 26 (2007) 12.
// The sweeps stop early after one that changes no row velocity by more than lcp_tol (1 + |b|_inf).
// The default budget grows with the square of the pile height H (body layers above the ground): Gauss-Seidel
// on a chain of H coupled bodies reduces the error per sweep by about 1 - pi^2 / H^2 (the 1D model problem;
// Saad, "Iterative methods for sparse linear systems", 2nd ed. 2003, sec. 4.2), so H^2 / 10 sweeps keep each
// warm-started step's reduction the same at any height. Measured (fast, resting pyramids, 200 steps): base 10 at
// 10 sweeps drifts 3.3e-4 m, base 20 at 40 4.6e-4 m, base 30 at 90 4.3e-4 m; at 10 sweeps base 20 and 30 drift
// 4.3e-2 and 0.10 m. An explicit -contact_sweeps is a fixed budget.
// With joints, the joint block is one more block of the Gauss-Seidel iteration, solved exactly: before each
// sweep over the contact manifolds, the joint impulses that answer the current contact impulses (the sparse
// LDL^T of S = G M^-1 G^T, linear in the bodies on chains) shift the contact rows' velocities b (block
// Gauss-Seidel on the MLCP of stepper.hpp with the G block: Cottle, Pang & Stone, "The Linear Complementarity
// Problem", 1992, sec. 5.2). The stepper projects the end velocities onto the joints exactly afterwards
// (joint_system.hpp). balanced then leaves out its splitting pass, whose factorisation has no joint rows.
#pragma once

#include "contact/friction_formulation.hpp"

#include <functional>

namespace suite::contact {

// The pile height of a problem: the deepest body layer reached breadth-first through the contacts from the
// static bodies it touches (a resting stack of 10 boxes: 10; 0 without a static body).
int pileHeight(const std::vector<Contact>& cs, const std::vector<Body>& bodies);
// The sweep budget of a mode: StepperOptions::contact_sweeps when set, else max(mode default, ceil(H^2 / 10))
// for a pile of height H (see above).
int sweepBudget(const StepperOptions& o, int height);
// With joints (joint_system.hpp): the change of the contact rows' velocities from the joint impulses that answer
// the contact impulses z, J (-M^-1 G^T S^-1 G M^-1 J^T z).
using JointCoupling = std::function<lcp::Vec(const lcp::Vec& z)>;
// The impulses of a balanced / fast step (see above); always true (never a failed step). joints: the coupling
// of contacts on jointed bodies (nullptr: none), see below.
bool budgetImpulses(const ContactStep& step, const DelassusSystem& sys, const StepperOptions& o,
                    Impulses* out, StepStats* st, const JointCoupling* joints = nullptr);

} // namespace suite::contact
