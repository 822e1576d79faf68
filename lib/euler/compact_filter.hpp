// Sixth-order compact (tridiagonal) low-pass filter of Gaikwad & Visbal (D. V. Gaitonde & M. R. Visbal, AIAA J.
// 38 (2000) 2103; M. R. Visbal & D. V. Gaitonde, J. Comput. Phys. 181 (2002) 155, eq. (9) and Table 1; the
// Lele (1992) family), applied line by line to the conserved state after each step (-filter_alpha):
//     alpha fh_{i-1} + fh_i + alpha fh_{i+1} = sum_{n=0..3} a_n / 2 (f_{i+n} + f_{i-n}),
//     a0 = 11/16 + 5 alpha / 8, a1 = 15/32 + 17 alpha / 16, a2 = -3/16 + 3 alpha / 8, a3 = 1/32 - alpha / 16.
// Transfer function T(w) = (a0 + a1 cos w + a2 cos 2w + a3 cos 3w) / (1 + 2 alpha cos w): T(pi) = 0 (the 2-dx
// mode is removed in one application), 1 - T = O(w^6), and T = 1 identically at alpha = 1/2 (no filtering);
// -1/2 < alpha <= 1/2, the usual range 0.4 .. 0.49 (closer to 1/2: only the highest wavenumbers are damped).
// Conservative (flux) form, used here: (1 - T(w)) (1 + 2 alpha cos w) = (1 - 2 alpha) (1 - cos w)^3 / 8, and
// (1 - cos w)^3 is the symbol of -delta^6 / 8, so fh = f + c (I + alpha T)^-1 delta^6 f with c = (1 - 2 alpha) / 64
// and T the tridiagonal (1, 0, 1). With delta^6 f_i = G_{i+1/2} - G_{i-1/2}, G = delta^5 f at the faces (6
// cells), the filter is
//     alpha g_{k-1} + g_k + alpha g_{k+1} = c G_k   (one row per face k),   fh_i = f_i + g_{i+1/2} - g_{i-1/2},
// on a periodic line exactly the filter above (the face solve commutes with the difference), and conservative
// on every line: the sum of fh equals the sum of f, whatever faces are switched off. A face is switched off
// (g_k = 0: identity row, zero right-hand side)
//   - when its stencil (cells k-3 .. k+2) leaves a non-periodic line (the domain-end faces are zero fluxes, so
//     a closed domain keeps its mass and energy to round-off; the 2 end cells stay as they are);
//   - when the stencil holds a discontinuity: Jameson's relative second difference
//     |g_{j+1} - 2 g_j + g_{j-1}| / (g_{j+1} + 2 g_j + g_{j-1}) of density or pressure above `jump` at some
//     j = k-2 .. k+1 (from the stencil's own cells: the same decision at any rank count). The cells next to a
//     jump are then left as they are and the filter never smooths across it.
#pragma once

#include <array>

namespace suite::euler {

// Right-hand-side coefficients a0..a3 of the sixth-order filter for `alpha`.
void compactFilterCoefficients(double alpha, double a[4]);

// Transfer function T(w) of the filter (tests, documentation).
double compactFilterTransfer(double alpha, double w);

// Face rows of one line for the tridiagonal solve (linalg::SubstructuredBlockLines::solveScalar layout): q holds
// xm + 6 cells of NV conserved components (cells xs-3 .. xs+xm+2, ghosts filled; the line's first component is
// density, its last total energy, the ones between momenta), n global cells along the line. Writes abc[3 m ..
// 3 m + 2] = (a, b, c) and rhs[NV m + c] for the nface faces xs + m, m = 0 .. nface-1 (nface = xm, or xm + 1 for
// the last rank of a non-periodic line, which owns face n).
template <int NV>
void compactFilterFaceRows(const std::array<double, NV>* q, long long n, long long xs, int nface,
                           bool periodic, double alpha, double gamma, double jump, double* abc, double* rhs);

// fh_i = f_i + g_{i+1/2} - g_{i-1/2} for the xm cells of a line: g holds the xm + 1 face values xs .. xs+xm, f the
// stored line (cells xs-3 ..), out the xm filtered cells.
template <int NV>
void compactFilterApply(const std::array<double, NV>* q, int xm, const double* g,
                        std::array<double, NV>* out);

} // namespace suite::euler
