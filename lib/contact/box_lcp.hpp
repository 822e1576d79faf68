// The box LCP of the contact rows shared by the none, box, scaled_box and splitting formulations (Lacoursiere,
// SIGRAD 2003, box MLCPs): rows interleaved per contact, (n, t1, t2) with friction, n alone without;
//   normal rows 0 <= lambda_n _|_ w_n >= 0,  tangent rows -mu nu <= lambda_t <= mu nu,
// nu an estimate of the normal impulse chosen by the formulation. Tangent rows with zero bound (mu nu = 0)
// are left out of the problem. Warm start: the previous step's impulses of the matching contacts.
#pragma once

#include "contact/friction_formulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace suite::contact {

class BodySpaceSolver;

// The impulses of every row and the estimates of one box-LCP formulation in a step.
struct BoxRows {
  int nc = 0, per = 1;                   // contacts, rows per contact (3 with friction, 1 without)
  std::vector<double> nu;                // normal-impulse estimate per contact (the bounds are mu nu)
  lcp::Vec full;                         // impulse per row: the warm start before a pass, its answer after it
  std::shared_ptr<BodySpaceSolver> body; // sparse path: the body-space solver of the step, kept across passes
  std::vector<double> an; // A_nn per contact (the step's normal diagonals), set by the first pass
};

// (n, t1, t2) per contact with friction, n alone without.
std::vector<ConstraintRow> boxRows(const std::vector<Contact>& cs, bool friction);
// The solver chain of the box formulations: -lcp_solver, then the -fallback_solvers other than it.
std::vector<std::string> boxChain(const StepperOptions& o);
// Rows per contact `per`, full = the previous step's impulses of the matching contacts, nu = 0.
BoxRows initialBoxRows(const ContactStep& step, int per);
// Estimate of the normal impulse from the weight: |g| dt times the mean over the contact's dynamic bodies
// of mass / (contacts of the body).
std::vector<double> weightEstimates(const ContactStep& step, const StepperOptions& o);
// Sparse systems only: the normal impulses of the answer with every row free and unbounded (max(0, lambda_n);
// one body-space factorisation), the exact load of a structure at rest with every contact pressed and sticking.
std::vector<double> stickingEstimates(const DelassusSystem& sys, int nc, int per);
// One pass: the box LCP with bounds mu nu, warm-started from s->full, solved; s->full <- its answer.
// err: max A_nn |change of lambda_n| (first pass: max A_nn lambda_n), nmax: max A_nn |lambda_n|, over the
// contacts' normal rows n: velocities (m/s), so that the splitting's stop rule does not change when every mass
// is scaled. s->an is set on the first call. false: not solved.
bool solveBoxPass(const DelassusSystem& sys, double mu, const std::vector<std::string>& chain, bool first,
                  ChainSolve& solver, BoxRows* s, double* err, double* nmax, StepStats* st);
// The impulses of s (z = full, lambda per contact).
void boxImpulses(const BoxRows& s, Impulses* out);
// One pass with the estimates nu (none, box, scaled_box): splitting_iterations 1, splitting_error its err.
bool solveSingleBoxPass(const ContactStep& step, const DelassusSystem& sys, int per, std::vector<double> nu,
                        double mu, const std::vector<std::string>& chain, ChainSolve& solver, Impulses* out,
                        StepStats* st);

} // namespace suite::contact
