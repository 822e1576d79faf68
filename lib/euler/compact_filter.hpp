// Sixth-order compact (tridiagonal) low-pass filter of Gaikwad & Visbal (D. V. Gaitonde & M. R. Visbal, AIAA J.
// 38 (2000) 2103; M. R. Visbal & D. V. Gaitonde, J. Comput. Phys. 181 (2002) 155, eq. (9) and Table 1; the
// Lele (1992) family), applied line by line to the conserved state after each step (-filter_alpha):
//     alpha fh_{i-1} + fh_i + alpha fh_{i+1} = sum_{n=0..3} a_n / 2 (f_{i+n} + f_{i-n}),
//     a0 = 11/16 + 5 alpha / 8, a1 = 15/32 + 17 alpha / 16, a2 = -3/16 + 3 alpha / 8, a3 = 1/32 - alpha / 16.
// Transfer function T(w) = (a0 + a1 cos w + a2 cos 2w + a3 cos 3w) / (1 + 2 alpha cos w): T(pi) = 0 (the 2-dx
// mode is removed in one application), 1 - T = O(w^6), and T = 1 identically at alpha = 1/2 (no filtering);
// -1/2 < alpha <= 1/2, the usual range 0.4 .. 0.49 (closer to 1/2: only the highest wavenumbers are damped).
// On a periodic line the filter conserves the sum of f (T(0) = 1 and the row sums agree).
// Rows left unfiltered (fh_i = f_i, identity rows of the tridiagonal system), so that the filter never reaches
// across what it must not smooth and needs no boundary closure:
//   - the 3 cells next to a non-periodic domain end (the 7-point stencil would need boundary ghosts; Visbal &
//     Gaitonde use one-sided lower-order filters there instead);
//   - cells whose stencil i-3 .. i+3 holds a discontinuity: Jameson's relative second difference
//     |g_{j+1} - 2 g_j + g_{j-1}| / (g_{j+1} + 2 g_j + g_{j-1}) of density or pressure above `jump` at some
//     j = i-2 .. i+2 (computed from the stencil's own cells, so the decision is the same at any rank count).
// Next to an identity row the filter is not exactly conservative (the row sums no longer telescope).
#pragma once

#include <array>

namespace suite::euler {

// Right-hand-side coefficients a0..a3 of the sixth-order filter for `alpha`.
void compactFilterCoefficients(double alpha, double a[4]);

// Transfer function T(w) of the filter (tests, documentation).
double compactFilterTransfer(double alpha, double w);

// Rows of one line for the tridiagonal solve (linalg::SubstructuredBlockLines::solveScalar layout): q holds
// xm + 6 cells of NV conserved components (cells xs-3 .. xs+xm+2, ghosts filled; the line's first component is
// density and its last total energy, the ones between momenta), n global cells along the line. Writes
// abc[3 k .. 3 k + 2] = (a, b, c) and rhs[NV k + c] for the owned cells k = 0 .. xm-1.
template <int NV>
void compactFilterRows(const std::array<double, NV>* q, long long n, long long xs, int xm, bool periodic,
                       double alpha, double gamma, double jump, double* abc, double* rhs);

} // namespace suite::euler
