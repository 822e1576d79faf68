// Friction model "none": the plain LCP of the normal rows, 0 <= lambda_n _|_ w_n >= 0 (Stewart & Trinkle
// 1996 without friction directions); also what every model reduces to with mu = 0 (no tangent rows).
#include "contact/box_lcp.hpp"

namespace suite::contact {

namespace {
class NoFriction : public FrictionFormulation {
public:
  explicit NoFriction(const StepperOptions& o) : o_(o), chain_(boxChain(o)) {}
  std::vector<ConstraintRow> rows(const std::vector<Contact>& cs) const override {
    return boxRows(cs, false);
  }
  bool impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver, Impulses* out,
                StepStats* st) const override {
    const std::vector<double> nu(step.contacts.size(), 0.0);
    return solveSingleBoxPass(step, sys, 1, nu, o_.mu, chain_, solver, out, st);
  }

private:
  const StepperOptions o_;
  const std::vector<std::string> chain_;
};
} // namespace

std::unique_ptr<FrictionFormulation> makeNoFriction(const StepperOptions& o) {
  return std::make_unique<NoFriction>(o);
}

} // namespace suite::contact
