// -contact_accuracy: where a contact step sits on the speed/accuracy trade.
//   exact     every problem solved to the acceptance rule (residual <= lcp_tol (1 + |b|_inf)) by the
//             friction formulation's solver chain (sparse first above StepperOptions::dense_max_rows, see
//             box_lcp.cpp), with its fallbacks; a step no solver answers ends the run.
//   balanced  one box LCP per step with the Coulomb bounds |lambda_t| <= mu lambda_n read from the current
//             normal impulse during the sweeps (splitting; box / scaled_box: their estimates), solved by at
//             most -contact_sweeps (default 50) symmetric projected Gauss-Seidel sweeps in height order,
//             matrix-free, warm-started from the previous step's matching contacts, then one splitting pass:
//             the bounds frozen at mu lambda_n and at most 4 sparse active-set factorisations (its answer kept
//             when it solves that pass or lowers the residual).
//   fast      the same with at most 10 sweeps (-contact_sweeps) and 1 factorisation.
// balanced and fast never end the run for accuracy: the step goes on and its natural-map residual
// (complementarity error, of the box LCP with the bounds mu lambda_n of the answer), cone violation and
// penetration are recorded (StepStats, /steps in the output). Sequential impulses with warm starting: Catto,
// "Iterative dynamics with temporal coherence", GDC 2005; Erleben, ACM TOG 26 (2007) 12.
// The sweeps stop early after one that changes no impulse by more than lcp_tol (1 + |b|_inf).
#pragma once

#include "contact/friction_formulation.hpp"

namespace suite::contact {

// The sweep budget of a mode (StepperOptions::contact_sweeps, or the mode's default).
int sweepBudget(const StepperOptions& o);
// The impulses of a balanced / fast step (see above); always true (never a failed step).
// reg: the rows' compliance when sys carries no matrix (contact_rows.hpp; fast mode), else read from sys.S.
bool budgetImpulses(const ContactStep& step, const DelassusSystem& sys, const StepperOptions& o,
                    Impulses* out, StepStats* st, const lcp::Vec* reg = nullptr);

} // namespace suite::contact
