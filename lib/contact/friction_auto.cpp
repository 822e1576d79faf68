// -friction auto: the ladder of friction models and the per-problem escalation (see friction_auto.hpp).
#include "contact/friction_auto.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace suite::contact {

namespace {
std::vector<AutoRung> ladder(const StepperOptions& o) {
  if (o.mu == 0) return {{"none", FrictionModel::None}};
  return {{"box", FrictionModel::Box},
          {"scaled_box", FrictionModel::ScaledBox},
          {"splitting_2", FrictionModel::Splitting, 2},
          {"splitting_5", FrictionModel::Splitting, 5},
          {"polyhedral_4", FrictionModel::Polyhedral, 0, 4},
          {"polyhedral_8", FrictionModel::Polyhedral, 0, 8}};
}
} // namespace

std::vector<std::string> autoRungNames(const StepperOptions& o) {
  std::vector<std::string> v;
  for (const AutoRung& r : ladder(o)) v.push_back(r.name);
  return v;
}

AutoFriction::AutoFriction(const StepperOptions& o) : rungs_(ladder(o)) {
  for (const AutoRung& r : rungs_) {
    StepperOptions ro = o;
    ro.friction = r.model;
    if (r.passes > 0) ro.splitting_max_it = r.passes;
    if (r.directions > 0) ro.polyhedral_directions = r.directions;
    opts_.push_back(ro);
    forms_.push_back(makeFrictionFormulation(ro));
  }
}

int AutoFriction::startRung(const std::vector<int>& prev_rung, bool probe) const {
  int r = prev_rung.empty() ? -1 : *std::max_element(prev_rung.begin(), prev_rung.end());
  if (probe) r -= 1;
  return std::clamp(r, 0, size() - 1);
}

void Stepper::exportAutoState(std::vector<double>* s) const {
  s->assign(prev_contacts_.size() + 1, -1.0);
  for (size_t i = 0; i < prev_rungs_.size() && i < prev_contacts_.size(); ++i) (*s)[i] = prev_rungs_[i];
  s->back() = (double)steps_done_;
}

void Stepper::importAutoState(const std::vector<double>& s) {
  if (s.size() != prev_contacts_.size() + 1 || !(s.back() >= 0))
    throw std::runtime_error("friction auto state: does not match the contacts");
  prev_rungs_.assign(s.begin(), s.end() - 1);
  for (int r : prev_rungs_)
    if (r < -1 || r >= (auto_ ? auto_->size() : 0))
      throw std::runtime_error("friction auto state: rung out of range");
  steps_done_ = (long long)s.back();
}

namespace {
// The problem's cone violation sum_i max(0, |lambda_t,i| - mu lambda_n,i) / sum_i lambda_n,i (forceMeasures'
// measure) and +inf when friction acts without normal impulse (a box bound from the weight estimate on a
// contact that separates), so that meeting E on every problem bounds the step's violation by E.
double problemViolation(const std::vector<Contact>& cs, const std::vector<Vec3>& lam, double mu) {
  double ratio = 0.0, violation = 0.0, fn = 0.0;
  forceMeasures(cs, lam, mu, &ratio, &violation, &fn);
  if (fn > 0) return violation;
  for (const Vec3& l : lam)
    if (std::hypot(l[1], l[2]) - mu * l[0] > 0) return std::numeric_limits<double>::infinity();
  return 0.0;
}

// One rung's answer.
struct RungAnswer {
  std::vector<Vec3> v, w, lam;
  StepStats st;
  double violation = std::numeric_limits<double>::infinity();
  int rung = -1;
};
} // namespace

namespace {
// The rungs to try: from the start rung up; below it (downwards) only while no rung has solved the problem.
std::vector<int> rungOrder(int start, int size) {
  std::vector<int> order;
  for (int r = start; r < size; ++r) order.push_back(r);
  for (int r = start - 1; r >= 0; --r) order.push_back(r);
  return order;
}

// The chosen rung's statistics in st (the step's own fields, contacts and penetration, kept).
void autoStats(const RungAnswer& best, int solves, double seconds, double target, StepStats* st) {
  const int contacts = st->contacts;
  const double penetration = st->penetration;
  *st = best.st;
  st->contacts = contacts, st->penetration = penetration;
  st->friction_rung = best.rung;
  st->auto_solves = solves;
  st->target_missed = best.violation > target;
  st->problem_rungs = {(double)best.rung};
  st->problem_rows = {(double)best.st.rows};
  st->problem_times = {seconds};
  st->problem_violations = {best.violation};
}
} // namespace

// From the start rung upward until a rung's cone violation is <= target_error (below the start rung only
// when no rung above solved the problem); the best answer (smallest violation, the first tried on ties) is
// applied.
bool Stepper::solveAuto(const std::vector<Body>& bodies, const ProblemInput& in, std::vector<Vec3>* v,
                        std::vector<Vec3>* w, std::vector<Vec3>* lam, StepStats* st,
                        std::vector<lcp::Problem>* problems, lcp::Vec* solution) const {
  const auto t0 = std::chrono::steady_clock::now();
  const int start = auto_->startRung(in.prev_rung, steps_done_ % AutoFriction::kProbeEvery == 0);
  RungAnswer best;
  int solves = 0;
  std::string why;
  for (int r : rungOrder(start, auto_->size())) {
    if (best.rung >= 0 && (r < start || best.violation <= o_.target_error)) break;
    RungAnswer a{*v, *w, {}, {}, 0.0, r};
    ++solves;
    if (!solveModel(auto_->formulation(r), auto_->options(r), bodies, in, &a.v, &a.w, &a.lam, &a.st, problems,
                    solution)) {
      std::string m = a.st.message;
      while (!m.empty() && (m.back() == ' ' || m.back() == ';')) m.pop_back();
      why += (why.empty() ? "" : "; ") + auto_->rung(r).name + ": " + m;
      continue;
    }
    a.violation = problemViolation(in.cs, a.lam, o_.mu);
    if (best.rung < 0 || a.violation < best.violation) best = std::move(a);
  }
  if (best.rung < 0) {
    st->failed = true;
    st->message = "friction auto: no model of the ladder solved the problem (" + why + ")";
    return false;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  autoStats(best, solves, seconds, o_.target_error, st);
  *v = std::move(best.v), *w = std::move(best.w), *lam = std::move(best.lam);
  return true;
}

} // namespace suite::contact
