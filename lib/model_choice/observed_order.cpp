// Observed order of convergence and Richardson error estimates (see observed_order.hpp for the reference).
#include "model_choice/observed_order.hpp"

#include <algorithm>
#include <cmath>

namespace suite::model_choice {

double ObservedOrder::errorAt(double n) const {
  return valid ? a * std::pow(n, -p) : INFINITY;
}

namespace {
double differenceRatio(double a, double b, double c, double p) {
  return (std::pow(a, -p) - std::pow(b, -p)) / (std::pow(b, -p) - std::pow(c, -p));
}
} // namespace

ObservedOrder fitObservedOrder(double a, double b, double c, double d_ab, double d_bc) {
  ObservedOrder f;
  if (!(std::isfinite(d_ab) && std::isfinite(d_bc)) || d_ab < 0 || d_bc < 0) {
    f.why = "a pilot difference is not finite";
    return f;
  }
  if (d_bc == 0.0) { // the two finer runs agree exactly: as converged as the arithmetic allows
    f.p_observed = f.p = kMaxOrder, f.a = 0.0, f.valid = true;
    return f;
  }
  const double ratio = d_ab / d_bc;
  double lo = kMinOrder, hi = kMaxOrder;
  if (!(ratio >= differenceRatio(a, b, c, lo))) {
    f.p_observed = std::log(ratio) / std::log(b / a); // (exact for b/a = c/b)
    f.why = "runs not converging (observed order " + std::to_string(f.p_observed) + ")";
    return f;
  }
  if (ratio >= differenceRatio(a, b, c, hi))
    lo = hi;
  else
    for (int it = 0; it < 100 && hi - lo > 1e-12; ++it) {
      const double mid = 0.5 * (lo + hi);
      (differenceRatio(a, b, c, mid) < ratio ? lo : hi) = mid;
    }
  f.p_observed = f.p = lo;
  f.a = d_bc / (std::pow(b, -f.p) - std::pow(c, -f.p));
  f.valid = true;
  return f;
}

ObservedOrder atMostFirstOrderWithJumps(ObservedOrder f, double b, double c, double d_bc) {
  if (f.valid && f.p > 1.0 && f.p < kJumpOrderBound) f.p = 1.0, f.a = d_bc / (1.0 / b - 1.0 / c);
  return f;
}

double pairEstimate(double n_other, double n, double d, double p) {
  if (n == n_other) return INFINITY;
  return d * std::pow(n, -p) / std::abs(std::pow(n, -p) - std::pow(n_other, -p));
}

} // namespace suite::model_choice
