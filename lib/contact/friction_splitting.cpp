// Friction model "splitting" (Lacoursiere, SIGRAD 2003, sec. 4, operator splitting): repeat { solve the box
// LCP with bounds mu nu; nu <- lambda_n } until max A_nn |delta lambda_n| <= tol (1 m/s + max A_nn lambda_n)
// (velocities: the normal velocity the change of impulse makes, A_nn the normal row's diagonal of the Delassus
// matrix; the rule is the same for any scaling of the masses, where one in impulses with an absolute 1 N s
// is 1,000 times stricter on 1,000 kg bodies than on 1 kg ones: 5 to 50 passes a step instead of 4) or the pass
// cap, starting from nu = 0 (zero friction), +inf (infinite friction) or the previous step's normal impulses
// (without them: the weight estimate, or on the sparse path the sticking estimate of box_lcp.hpp)
// (-splitting_start). Each pass's change and force ratio are kept (StepStats::split_errors / split_ratios).
// On the sparse path the change is the fixed-point residual max A_nn |lambda_n - nu| of the pass (the same number
// while nu <- lambda_n), and from the third pass on nu is extrapolated (Aitken) while the passes contract by
// rho <= 0.5 per pass: an answer is accepted by the same rule, its bounds mu nu within tol of mu lambda_n.
// After two passes in a row without a new lowest residual (a cycle: the pass map jumps where rows change
// state) the estimates are damped instead.
#include "contact/box_lcp.hpp"

#include <algorithm>
#include <cmath>

namespace suite::contact {

const char* splitStartName(SplitStart s) {
  switch (s) {
  case SplitStart::Zero:
    return "zero";
  case SplitStart::Infinite:
    return "infinite";
  case SplitStart::Previous:
    return "previous";
  }
  return "?";
}

bool splitStartFromName(const std::string& name, SplitStart* s) {
  for (int i = 0; i < 3; ++i)
    if (name == splitStartName(SplitStart(i))) {
      *s = SplitStart(i);
      return true;
    }
  return false;
}

std::vector<Choice> splitStartChoices() {
  return {
      {"zero", "nu = 0: the first pass without friction"},
      {"infinite", "nu = +inf: the first pass with sticking friction"},
      {"previous", "nu = the previous step's normal impulse (else the weight / sparse: sticking estimate)"}};
}

namespace {
// After two passes in a row without a new lowest fixed-point residual the estimates are damped by this
// factor for the rest of the step.
constexpr double kDamping = 0.5;

// max_i A_nn,i |lambda_n,i - nu_i|: how far the pass's estimates were from its answer (as a velocity).
double fixedPointResidual(const BoxRows& s, const std::vector<double>& nu) {
  double e = 0.0;
  for (int i = 0; i < s.nc; ++i) e = std::max(e, s.an[i] * std::abs(s.full[i * s.per] - nu[i]));
  return e;
}

// The sparse path's update of the estimates from pass to pass.
struct EstimateUpdate {
  double last_err = 0.0, best_err = lcp::kInf;
  int stalled = 0;     // passes in a row without a new lowest residual
  bool damped = false; // after two stalled passes: nu <- nu + kDamping (lambda_n - nu) (breaks the cycles of
                       // a non-smooth pass map; Krasnosel'skii-Mann iteration)
  // The next estimate of each contact from the pass's answer (s->full) and estimates nu (pass >= 1): Aitken's
  // extrapolation ln + rho / (1 - rho) (ln - nu) while the passes contract by rho in (0, 0.5] (Brezinski &
  // Redivo Zaglia, "Extrapolation methods", North-Holland 1991), else ln, or the damped step.
  void next(const std::vector<double>& nu, double err, int pass, BoxRows* s) {
    const double rho = pass > 1 ? err / last_err : 0.0;
    stalled = err < best_err ? 0 : stalled + 1;
    damped = damped || stalled >= 2;
    last_err = err, best_err = std::min(best_err, err);
    for (int i = 0; i < s->nc; ++i) {
      const double ln = s->full[i * s->per];
      s->nu[i] = damped                  ? nu[i] + kDamping * (ln - nu[i])
                 : rho > 0 && rho <= 0.5 ? std::max(0.0, ln + rho / (1 - rho) * (ln - nu[i]))
                                         : ln;
    }
  }
};

class SplittingFriction : public FrictionFormulation {
public:
  explicit SplittingFriction(const StepperOptions& o) : o_(o), chain_(boxChain(o)) {}
  std::vector<ConstraintRow> rows(const std::vector<Contact>& cs) const override {
    return boxRows(cs, o_.mu > 0);
  }
  bool impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver, Impulses* out,
                StepStats* st) const override;

private:
  std::vector<double> startEstimates(const ContactStep& step, const DelassusSystem& sys) const;
  const StepperOptions o_;
  const std::vector<std::string> chain_;
};

std::vector<double> SplittingFriction::startEstimates(const ContactStep& step,
                                                      const DelassusSystem& sys) const {
  // contacts without a previous impulse: the weight estimate; on the sparse path (large problems, where a
  // poor first estimate makes a first pass of thousands of pivots) the sticking estimate
  bool all_prev = true;
  for (bool h : step.has_prev) all_prev = all_prev && h;
  const bool sticking = sys.sparse && o_.split_start == SplitStart::Previous && !all_prev && o_.mu > 0;
  std::vector<double> nu =
      sticking ? stickingEstimates(sys, (int)step.contacts.size(), 3) : weightEstimates(step, o_);
  for (size_t i = 0; i < nu.size(); ++i)
    nu[i] = o_.split_start == SplitStart::Zero       ? 0.0
            : o_.split_start == SplitStart::Infinite ? lcp::kInf
                                                     : (step.has_prev[i] ? step.prev[i][0] : nu[i]);
  return nu;
}

bool SplittingFriction::impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver,
                                 Impulses* out, StepStats* st) const {
  BoxRows s = initialBoxRows(step, o_.mu > 0 ? 3 : 1);
  s.nu = startEstimates(step, sys);
  const int max_pass = std::max(1, o_.splitting_max_it);
  EstimateUpdate update;
  for (int pass = 0; pass < max_pass; ++pass) {
    double err = 0.0, nmax = 0.0, ratio = 0.0, viol = 0.0, fn = 0.0;
    const std::vector<double> nu = s.nu;
    if (!solveBoxPass(sys, o_.mu, chain_, pass == 0, solver, &s, &err, &nmax, st)) return false;
    if (pass > 0 && sys.sparse) err = fixedPointResidual(s, nu);
    boxImpulses(s, out);
    st->splitting_iterations = pass + 1;
    st->splitting_error = err;
    forceMeasures(step.contacts, out->lambda, o_.mu, &ratio, &viol, &fn);
    st->split_errors.push_back(err);
    st->split_ratios.push_back(ratio);
    if (pass > 0 && err <= o_.splitting_tol * (1.0 + nmax)) break;
    if (sys.sparse && pass > 0) {
      update.next(nu, err, pass, &s);
    } else {
      for (int i = 0; i < s.nc; ++i) s.nu[i] = out->lambda[i][0];
    }
  }
  return true;
}
} // namespace

std::unique_ptr<FrictionFormulation> makeSplittingFriction(const StepperOptions& o) {
  return std::make_unique<SplittingFriction>(o);
}

} // namespace suite::contact
