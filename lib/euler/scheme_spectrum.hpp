// Resolving power of a scheme, measured: the modified (effective) wavenumber k'dx of its flux-derivative
// operator D_j = h_{j+1/2} - h_{j-1/2} (f = u, positive speed: the left-biased rows), obtained by applying the
// rows and the periodic tridiagonal solve to single Fourier modes on an n-point periodic grid and projecting
// the result on the mode: for f_j = exp(i w j), D_j = i k'dx f_j. Real part: dispersion (exact: k'dx = w);
// imaginary part: dissipation (negative for upwind schemes). Nonlinear (WENO-type) rows are applied to cos and
// sin separately and combined, as in S. Pirozzoli, J. Comput. Phys. 219 (2006) 489 ("On the spectral
// properties of shock-capturing schemes"). Reference for the linear Pade core: S. K. Lele, J. Comput. Phys. 103
// (1992) 16, eq. (2.1.7) with alpha = 1/3, a = 14/9, b = 1/9 (the conservative interface form used here is
// equivalent: subtracting neighbouring interface rows gives Lele's derivative rows).
#pragma once

#include "euler/schemes.hpp"

#include <vector>

namespace suite::euler {

struct SpectrumPoint {
  double w;      // k dx, in (0, pi]
  double re, im; // modified wavenumber k'dx
};

// Modes m = 1 .. n/2 (w = 2 pi m / n) of an n-point periodic grid (n even, >= 8). smooth: the scheme's smooth
// rows, else its shock rows. Throws std::invalid_argument for a scheme without flux rows (muscl2).
std::vector<SpectrumPoint> measureSchemeSpectrum(const SchemeInfo& scheme, bool smooth, int n);

// Lele's analytic modified wavenumber of the 6th-order alpha = 1/3 compact scheme.
double padeModifiedWavenumber(double w);

} // namespace suite::euler
