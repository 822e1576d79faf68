// Friction models "box" and "scaled_box" (Lacoursiere, SIGRAD 2003, box MLCP): one box LCP per step with
// tangent bounds mu nu, nu an estimate of the normal impulse (estimate policy):
//   box         nu = |g| dt m / (contacts of the body): a fixed estimate from the weight;
//   scaled_box  nu = the normal impulse of the same contact at the previous step (else the weight estimate).
#include "contact/box_lcp.hpp"

namespace suite::contact {

namespace {
class BoxFriction : public FrictionFormulation {
public:
  BoxFriction(const StepperOptions& o, bool scaled) : o_(o), scaled_(scaled), chain_(boxChain(o)) {}
  std::vector<ConstraintRow> rows(const std::vector<Contact>& cs) const override {
    return boxRows(cs, o_.mu > 0);
  }
  bool impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver, Impulses* out,
                StepStats* st) const override {
    std::vector<double> nu = weightEstimates(step, o_);
    if (scaled_)
      for (size_t i = 0; i < nu.size(); ++i)
        if (step.has_prev[i]) nu[i] = step.prev[i][0];
    return solveSingleBoxPass(step, sys, o_.mu > 0 ? 3 : 1, nu, o_.mu, chain_, solver, out, st);
  }

private:
  const StepperOptions o_;
  const bool scaled_; // the estimate policy: previous normal impulse (scaled_box) or weight (box)
  const std::vector<std::string> chain_;
};
} // namespace

std::unique_ptr<FrictionFormulation> makeBoxFriction(const StepperOptions& o, bool scaled) {
  return std::make_unique<BoxFriction>(o, scaled);
}

} // namespace suite::contact
