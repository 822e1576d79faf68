// Exact solution of the Riemann problem for the 1D Euler equations of an ideal gas.
// Reference: Toro (2009), ch. 4: pressure function (4.5)-(4.7), Newton iteration (4.44) with the
// two-rarefaction initial guess (4.46), sampling (sec. 4.5, fig. 4.14), including vacuum generation
// (sec. 4.6).
#pragma once

#include "euler/gas.hpp"

namespace suite::euler {

class ExactRiemann {
public:
  ExactRiemann(const Prim& left, const Prim& right, double gamma);
  // State at similarity coordinate s = (x - x0) / t.
  Prim sample(double s) const;
  double pStar() const { return p_star_; }
  double uStar() const { return u_star_; }
  bool vacuum() const { return vacuum_; }

private:
  double pressureFunction(double p, const Prim& w, double c, double* dfdp) const;
  Prim L_, R_;
  double g_, cL_, cR_, p_star_ = 0.0, u_star_ = 0.0;
  bool vacuum_ = false;
};

} // namespace suite::euler
