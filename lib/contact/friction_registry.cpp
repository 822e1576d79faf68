// Registry of the friction formulations: one line per model (name, one-line description, factory); -friction
// is documented and validated from it (frictionChoices).
#include "contact/friction_formulation.hpp"

#include <functional>

namespace suite::contact {

namespace {
struct FrictionEntry {
  FrictionModel model;
  const char* name;
  const char* description;
  std::function<std::unique_ptr<FrictionFormulation>(const StepperOptions&)> make;
};

const std::vector<FrictionEntry>& registry() {
  static const std::vector<FrictionEntry> r = {
      {FrictionModel::None, "none", "no friction: the plain LCP of the normal rows", makeNoFriction},
      {FrictionModel::Box, "box", "box LCP, bounds mu nu with nu estimated from the weight",
       [](const StepperOptions& o) { return makeBoxFriction(o, false); }},
      {FrictionModel::ScaledBox, "scaled_box", "box LCP, nu the previous step's normal impulse",
       [](const StepperOptions& o) { return makeBoxFriction(o, true); }},
      {FrictionModel::Splitting, "splitting",
       "box LCPs with nu <- lambda_n until converged (Lacoursiere 2003)", makeSplittingFriction},
      {FrictionModel::Polyhedral, "polyhedral", "linearised cone LCP, -polyhedral_directions per contact",
       makePolyhedralFriction},
      {FrictionModel::Auto, "auto",
       "per problem the cheapest of none/box/scaled_box/splitting/polyhedral meeting -target_error "
       "(friction_auto.hpp)",
       [](const StepperOptions&) { return std::unique_ptr<FrictionFormulation>(); }},
  };
  return r;
}
} // namespace

const char* frictionName(FrictionModel m) {
  for (const FrictionEntry& e : registry())
    if (e.model == m) return e.name;
  return "?";
}

std::vector<std::string> frictionNames() {
  std::vector<std::string> v;
  for (const FrictionEntry& e : registry()) v.push_back(e.name);
  return v;
}

bool frictionFromName(const std::string& name, FrictionModel* m) {
  for (const FrictionEntry& e : registry())
    if (name == e.name) {
      *m = e.model;
      return true;
    }
  return false;
}

std::vector<Choice> frictionChoices() {
  return choicesOf(registry());
}

std::unique_ptr<FrictionFormulation> makeFrictionFormulation(const StepperOptions& o) {
  for (const FrictionEntry& e : registry())
    if (e.model == o.friction) return e.make(o);
  return nullptr;
}

} // namespace suite::contact
