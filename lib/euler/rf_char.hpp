// "rf-char" upwinding of the characteristic fields at a face (Roe-Fixed, characteristic-wise), the flux
// upwinding of HyPar's Euler solvers (-upwinding rf-char; Ghosh & Baeder, SIAM J. Sci. Comput. 34 (2012) A1678,
// sec. 4; HyPar documentation, "Euler1DUpwindRF"), after the Roe-fixed (RF) scheme of Fedkiw, Merriman, Donat &
// Osher (UCLA CAM report 96-18, 1996) and Shu, ICASE report 97-65 (1997), sec. 2.3 (characteristic-wise local
// Lax-Friedrichs with a per-field alpha_k = max |lambda_k| over the stencil).
//
// Field k at face j+1/2 (Roe eigenvectors of cells j, j+1) is upwinded by the sign of its eigenvalue lambda_k
// at the face (Roe average) and at the two cells j and j+1: where the three are > 0 the field's face flux is the
// left-biased reconstruction of its characteristic flux l_k f (no splitting: no dissipation beyond that of the
// upwind-biased reconstruction itself, in particular none on contacts and rarefactions away from sonic
// points); where all are < 0, the right-biased one; only where they differ (sonic points, stagnant contacts)
// the field falls back to local Lax-Friedrichs, l_k (f +- alpha_k U) / 2, with alpha_k = (1 + 1e-12) max
// |lambda_k| over the stencil's cells and the face (-local_lf false: the direction's global alpha).
// DirectionSweep applies it characteristic-wise (component-wise rows have no fields to upwind: LLF there).
#pragma once

#include "euler/gas_nd.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace suite::euler {

template <int NV> struct RfChar {
  using G = LineGas<NV>;
  using V = typename G::V;

  // Eigenvalues of state q in field order (u - c, u (NV - 2 times), u + c); NaN-propagating.
  static void cellSpeeds(const V& q, double g, double lam[NV]) {
    const double u = q[1] / q[0], c = std::sqrt(std::abs(g * G::pressure(q, g) / q[0]));
    lam[0] = u - c;
    for (int k = 1; k < NV - 1; ++k) lam[k] = u;
    lam[NV - 1] = u + c;
  }
  // The Roe-averaged eigenvalues of the face, as LineGas::roeInto computed them (row 1 of R: u - c, u, u + c).
  static void roeSpeeds(const typename G::Eigen& e, double lam[NV]) {
    lam[0] = e.R[NV];
    for (int k = 1; k < NV - 1; ++k) lam[k] = e.R[NV + 1];
    lam[NV - 1] = e.R[NV + NV - 1];
  }
  // +1 / -1 when the three speeds are all > 0 / all < 0, otherwise 0 (Lax-Friedrichs; NaN gives 0).
  static int sign(double a, double b, double c) {
    if (a > 0.0 && b > 0.0 && c > 0.0) return 1;
    if (a < 0.0 && b < 0.0 && c < 0.0) return -1;
    return 0;
  }
  // Signs and Lax-Friedrichs speeds of the fields of the face between cells 2 and 3 of the six-cell stencil
  // lam[0..5] (cellSpeeds), roe: the face's roeSpeeds. local false: alpha_k = alpha_global.
  static void face(const std::array<double, NV>* lam, const double roe[NV], double alpha_global, bool local,
                   int sgn[NV], double alpha[NV]) {
    for (int k = 0; k < NV; ++k) {
      sgn[k] = sign(lam[2][k], roe[k], lam[3][k]);
      double a = std::abs(roe[k]);
      for (int m = 0; m < 6; ++m) a = std::max(a, std::abs(lam[m][k]));
      alpha[k] = local ? a * (1.0 + 1e-12) : alpha_global;
    }
  }
};

} // namespace suite::euler
