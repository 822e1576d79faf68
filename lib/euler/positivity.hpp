// Positivity-preserving flux limiter for finite-difference WENO-type schemes: each high-order interface flux
// is blended with the first-order Lax-Friedrichs flux so that the one-sided updates U_j - 2 lambda h_{j+1/2}
// and U_{j+1} + 2 lambda h_{j+1/2} keep density and pressure above a small epsilon. Reference: Hu, Adams &
// Shu, J. Comput. Phys. 242 (2013) 169, sec. 3, eqs. (3.6)-(3.12) (theta for density, then for pressure using
// its concavity). Guaranteed for lambda * alpha <= 1/2 with alpha >= max(|u| + c) at j, j+1.
#pragma once

#include "euler/gas.hpp"

namespace suite::euler {

// Lax-Friedrichs flux 0.5 (f(qa) + f(qb) - alpha (qb - qa)).
Vec3 laxFriedrichsFlux(const Vec3& qa, const Vec3& qb, double alpha, double gamma);
// Limits h (interface between cells with states qa = U_j and qb = U_{j+1}); lambda = dt / dx. Returns the
// blend factor theta in [0, 1] (1 = high-order flux kept).
double limitPositivity(const Vec3& qa, const Vec3& qb, double alpha, double lambda, double gamma, Vec3* h);

} // namespace suite::euler
