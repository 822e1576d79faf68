// Geometric-nonlinearity estimate of a displacement field for the linear (small-strain) law: the quadratic
// part of the Green-Lagrange strain E = sym(H) + 1/2 H^T H (H = grad u) against the linear part of the
// kinematics, volume-weighted over the body (Bonet & Wood 2008, sec. 4.5 for E; the estimate below is this
// suite's, calibrated on the cantilever, see nonlinearity_estimate.cpp).
//
//   ratio eta = sqrt( int ||1/2 H^T H||_F^2 dV / int ||H||_F^2 dV )     (0 for u = 0)
//
// H includes the rotation (skew) part, so a rigid rotation by theta gives eta = sin(theta/2) even where
// sym(H) is small -- the linear law's error is the error of linearised rotations, cos(theta) ~ 1 and
// sin(theta) ~ theta, relative O(theta^2) on the displacement along the load. The relative error of the
// linear law's displacement is estimated as linearLawError(eta) = 0.07 eta + 1.5 eta^2 (calibrated).
#pragma once

#include "fem/assembly.hpp"

#include <petscsys.h>

namespace suite::fem {

struct NonlinearityEstimate {
  double quadratic2 = 0; // int ||1/2 H^T H||_F^2 dV
  double linear2 = 0;    // int ||H||_F^2 dV
  double ratio() const;  // eta (0 when linear2 == 0)
};

// The integrals at u_full (3 per node, fixed DOFs zero) over the model's quadrature points; with a partial
// model (distributed assembly) over this rank's elements, summed over comm (collective then).
PetscErrorCode estimateNonlinearity(MPI_Comm comm, const ElasticModel& model, const double* u_full,
                                    NonlinearityEstimate* est);

// Calibration (nonlinearity_estimate.cpp): the relative error of the linear law's tip-deflection history
// against St. Venant-Kirchhoff, measured on the clamped cantilever, as a function of eta.
double linearLawError(double ratio);

} // namespace suite::fem
