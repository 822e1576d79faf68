// The friction formulations of the contact stepper behind one interface: each one chooses the constraint
// rows of the contacts (delassus.hpp), builds its LCP / box LCP from the Delassus system A, b and reads the
// impulses back; the stepper owns the contacts, the Delassus system and the integration (stepper.hpp).
// Every problem is solved through a chain of solvers (data: the names, the scaling), each answer verified on
// the original problem with lcp::solveWithChain. The formulations (one file each, references there):
//   none        friction_none.cpp        plain LCP of the normal rows
//   box         friction_box.cpp         box LCP, bounds mu nu with nu estimated from the weight
//   scaled_box  friction_box.cpp         ... nu the previous step's normal impulse of the contact
//   splitting   friction_splitting.cpp   box LCPs with nu <- lambda_n until it stops changing
//   polyhedral  friction_polyhedral.cpp  the linearised cone LCP (Stewart & Trinkle 1996)
//   auto        friction_auto.cpp        per problem the cheapest of these meeting -target_error (no
//                                        formulation of its own: makeFrictionFormulation gives null)
// The registry (friction_registry.cpp) maps each name to its factory and a one-line description (-help).
#pragma once

#include "contact/delassus.hpp"
#include "contact/stepper.hpp"
#include "core/named_choice.hpp"

#include <memory>
#include <string>
#include <vector>

namespace suite::contact {

// What a formulation sees of the step (besides the Delassus system).
struct ContactStep {
  const std::vector<Body>& bodies;
  const std::vector<Contact>& contacts;
  const std::vector<Vec3>& prev;     // impulses (n, t1, t2) of the matching contact of the previous step
  const std::vector<bool>& has_prev; // ... whether there was one
};

// Solves the formulation's problems with a chain of solvers (lcp::solveWithChain, the contact library's
// solvers included), keeps the problems for dumping and adds the attempts to the step's statistics.
class ChainSolve {
public:
  ChainSolve(const StepperOptions& o, bool keep_all, std::vector<lcp::Problem>* problems, lcp::Vec* solution,
             StepStats* st)
      : o_(o), keep_all_(keep_all), problems_(problems), solution_(solution), st_(st) {}
  // The units of p's unknowns: impulses against velocity rows (the box LCPs), or a mix (the polyhedral LCP).
  enum class Units { Impulses, Mixed };
  // false: no solver's answer was accepted (st->failed, st->message say which and why).
  // Units::Impulses: the chain solves p in velocity units, z = s z' with s the power of two nearest
  // 1 / max_i M_ii (the impulse that moves the stiffest row by 1 m/s): the solvers' stop rules and the
  // acceptance min(z', M' z' + q) then do not depend on the scene's mass scale (every mass x 2^k: the same
  // iterations and answers bitwise; another factor: the same to round-off until round-off tips a pivoting
  // decision). The dump keeps p as given.
  bool solve(const lcp::Problem& p, const std::vector<std::string>& chain, const lcp::Vec* scale,
             const lcp::Vec* warm, lcp::Vec* z, Units units = Units::Mixed);
  const StepperOptions& options() const { return o_; }

private:
  bool solveAsGiven(const lcp::Problem& p, const std::vector<std::string>& chain, const lcp::Vec* scale,
                    const lcp::Vec* warm, lcp::Vec* z);
  const StepperOptions& o_;
  bool keep_all_;
  std::vector<lcp::Problem>* problems_;
  lcp::Vec* solution_;
  StepStats* st_;
};

// The impulses a formulation found: z per row of the Delassus system, (n, t1, t2) per contact.
struct Impulses {
  lcp::Vec z;
  std::vector<Vec3> lambda;
};

class FrictionFormulation {
public:
  virtual ~FrictionFormulation() = default;
  // The constraint rows of the contacts, in the order of the Delassus system.
  virtual std::vector<ConstraintRow> rows(const std::vector<Contact>& cs) const = 0;
  // false when a problem was not solved (st->failed, st->message).
  virtual bool impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver, Impulses* out,
                        StepStats* st) const = 0;
};

std::unique_ptr<FrictionFormulation> makeFrictionFormulation(const StepperOptions& o);
// The registered models with their one-line descriptions (the -friction choices).
std::vector<Choice> frictionChoices();

// The factories (one per file).
std::unique_ptr<FrictionFormulation> makeNoFriction(const StepperOptions& o);
std::unique_ptr<FrictionFormulation> makeBoxFriction(const StepperOptions& o, bool scaled);
std::unique_ptr<FrictionFormulation> makeSplittingFriction(const StepperOptions& o);
std::unique_ptr<FrictionFormulation> makePolyhedralFriction(const StepperOptions& o);

// The Stewart-Trinkle / Anitescu-Potra LCP (paper, Eq. 6) of nc contacts with d friction directions from
// the Delassus matrix A and right-hand side b ordered [normals (nc), directions (nc d, contact-major)]:
// unknowns [lambda_n (nc), beta (nc d), gamma (nc)],
//   M = [A_nn A_nD 0; A_Dn A_DD E; mu I -E^T 0],  q = [b_n; b_D; 0]  (E: one 1 per direction of a contact).
lcp::Problem polyhedralLcp(const lcp::Mat& A, const lcp::Vec& b, int nc, int d, double mu);
// Diagonal scaling s (z = diag(s) z') that equilibrates polyhedralLcp's matrix (see StepperOptions).
lcp::Vec polyhedralScaling(const lcp::Problem& p, int nc, int d);

} // namespace suite::contact
