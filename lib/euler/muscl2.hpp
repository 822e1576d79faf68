// Second-order MUSCL interface flux, the `muscl2` comparator: piecewise-linear reconstruction of the
// primitive variables with the van Leer limiter, HLLC approximate Riemann solver at each interface (time
// integration by the TS SSP-RK3, i.e. MUSCL + Runge-Kutta rather than MUSCL-Hancock). References: van Leer,
// J. Comput. Phys. 32 (1979) 101; Toro (2009) sec. 10.4 (HLLC, eqs. 10.37-10.39) with the Davis wave-speed
// estimates (eq. 10.48).
#pragma once

#include "euler/gas.hpp"

namespace suite::euler {

// HLLC flux between conserved states qL and qR.
Vec3 hllcFlux(const Vec3& qL, const Vec3& qR, double gamma);
// MUSCL flux at x_{j+1/2} from conserved states q[0..3] at cells j-1 .. j+2.
Vec3 muscl2Flux(const Vec3* q, double gamma);

} // namespace suite::euler
