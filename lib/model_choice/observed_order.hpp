// A-posteriori error estimate of a family of runs that differ only in resolution n: Richardson / two-grid
// extrapolation with the order of convergence OBSERVED on this problem (never the scheme's formal order, never
// the exact solution). With e(n) = A n^-p, three runs at n, 2n, 4n give
//   p = log2(|u_n - u_2n| / |u_2n - u_4n|),   A = |u_2n - u_4n| / ((2n)^-p - (4n)^-p)
// (Roache, Verification and Validation in Computational Science and Engineering, 1998, ch. 5; Richardson
// 1911). Smooth flow then shows the scheme's order, flow with shocks first order or below in L1. A later run at
// Three runs at any a < b < c: p solves |u_a - u_b| / |u_b - u_c| = (a^-p - b^-p) / (b^-p - c^-p) (bisection;
// the ratio grows with p), A = |u_b - u_c| / (b^-p - c^-p). A run at
// n checked against another run at n_o of the same family: e(n) = |u_n - u_o| n^-p / |n^-p - n_o^-p| (for
// n > n_o: |u_n - u_o| / ((n/n_o)^p - 1)).
#pragma once

#include <string>

namespace suite::model_choice {

struct ObservedOrder {
  double p_observed = 0.0; // log2 of the ratio of the pilot differences (may be <= 0: not converging)
  double p = 0.0;          // the order used: p_observed clipped to [kMinOrder, kMaxOrder]
  double a = 0.0;          // e(n) = a n^-p
  bool valid = false;      // false: the pilots do not converge (p_observed < kMinOrder or not finite)
  std::string why;         // the reason when not valid
  double errorAt(double n) const;
};

constexpr double kMinOrder = 0.25; // below: the pilots are not in the asymptotic range
constexpr double kMaxOrder = 10.0; // above: a difference at round-off; the fit would promise too much

// From the differences d_ab = |u_a - u_b| and d_bc = |u_b - u_c| of runs at a < b < c (pilots: n, 2n, 4n).
ObservedOrder fitObservedOrder(double a, double b, double c, double d_ab, double d_bc);

// Orders observed below this are taken for a flow with jumps (shocks, contacts), whose L1 error converges at
// first order or below whatever the scheme (shocks O(h), contacts O(h^(r/(r+1))) for a scheme of order r; Harten,
// Engquist, Osher & Chakravarthy 1987); smooth flow shows the scheme's order, 3 and above here.
constexpr double kJumpOrderBound = 2.0;

// f (a valid fit from runs at b < c with distance d_bc) with an order between 1 and kJumpOrderBound refitted
// at order 1 through the same distance: e(c) = d_bc c^-1 / (b^-1 - c^-1). Such an order, from runs of a flow
// with jumps, is pre-asymptotic: their differences shrink faster than their errors while the jumps' smearing
// narrows (Lax-Liu 6, weno5: pilots at 16 / 32 / 64 give 1.15 and e(64) = 1.8e-2; the true error is 3.6e-2,
// and 0.9 is observed between 64 and 128). p_observed keeps what was observed.
ObservedOrder atMostFirstOrderWithJumps(ObservedOrder f, double b, double c, double d_bc);

// The error of the run at n estimated from its distance d to a run at n_other != n, with order p.
double pairEstimate(double n_other, double n, double d, double p);

} // namespace suite::model_choice
