// Exact solution of the Riemann problem for the 1D Euler equations of an ideal gas.
// Reference: Toro (2009), ch. 4: pressure function (4.5)-(4.7), Newton iteration (4.44) with the
// two-rarefaction initial guess (4.46), sampling (sec. 4.5, fig. 4.14), and the vacuum cases of sec. 4.6,
// eqs. (4.76)-(4.83): an initial vacuum on the right (rho = p = 0: a left rarefaction whose tail, the vacuum
// front, moves at uL + 2 cL / (gamma - 1)), on the left (mirror image, front at uR - 2 cR / (gamma - 1)), and
// vacuum generated between two rarefactions when uR - uL >= 2 (cL + cR) / (gamma - 1) (4.40).
#pragma once

#include "euler/gas.hpp"

namespace suite::euler {

class ExactRiemann {
public:
  enum class Vacuum { None, Generated, Left, Right };
  // States need rho > 0 and p >= 0, or rho = p = 0 (vacuum) on one side; gamma > 1 (std::invalid_argument).
  ExactRiemann(const Prim& left, const Prim& right, double gamma);
  // State at similarity coordinate s = (x - x0) / t. Vacuum is (0, front speed, 0).
  Prim sample(double s) const;
  double pStar() const { return p_star_; } // 0 with vacuum
  double uStar() const { return u_star_; } // with vacuum: the mean of the two vacuum-front speeds
  bool vacuum() const { return vacuum_ != Vacuum::None; }
  Vacuum vacuumKind() const { return vacuum_; }

private:
  double pressureFunction(double p, const Prim& w, double c, double* dfdp) const;
  Prim leftFan(double s) const;  // inside the left rarefaction (4.56)
  Prim rightFan(double s) const; // inside the right rarefaction (4.63)
  Prim sampleVacuum(double s) const;
  Prim L_, R_;
  double g_, cL_ = 0.0, cR_ = 0.0, p_star_ = 0.0, u_star_ = 0.0;
  Vacuum vacuum_ = Vacuum::None;
};

} // namespace suite::euler
