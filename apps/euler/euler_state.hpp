// Conversions of one cell's state for -dim 1|2|3: conserved q = (rho, m_x[, m_y[, m_z]], E) <-> primitive
// PrimN, the wave speeds |u_d| + c, the directions across a grid line. In 1D they are gas.hpp's line formulas
// (the exact floating-point expressions the 1D results were produced with); in 2D/3D the formulas of the
// direction-split grid.
#pragma once

#include "euler/gas.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace euler_app {

using suite::euler::PrimN;

inline PrimN primitive(const double* q, int dim, double gamma) {
  PrimN w{q[0], {0, 0, 0}, 0};
  double ke = 0.0; // for dim 1 this is gas.hpp's toPrim bit for bit
  for (int d = 0; d < dim; ++d) {
    w.u[d] = q[1 + d] / q[0];
    ke += 0.5 * q[1 + d] * w.u[d];
  }
  w.p = (gamma - 1.0) * (q[dim + 1] - ke);
  return w;
}

inline void conservative(const PrimN& w, int dim, double gamma, double* q) {
  if (dim == 1) {
    const suite::euler::Vec3 c = suite::euler::toCons({w.rho, w.u[0], w.p}, gamma);
    q[0] = c[0], q[1] = c[1], q[2] = c[2];
    return;
  }
  double v2 = 0.0;
  q[0] = w.rho;
  for (int d = 0; d < dim; ++d) {
    q[1 + d] = w.rho * w.u[d];
    v2 += w.u[d] * w.u[d];
  }
  q[dim + 1] = w.p / (gamma - 1.0) + 0.5 * w.rho * v2;
}

// s[d] = |u_d| + c for d < dim.
inline void waveSpeeds(const double* q, int dim, double gamma, double s[3]) {
  if (dim == 1) {
    s[0] = suite::euler::maxWaveSpeed({q[0], q[1], q[2]}, gamma);
    return;
  }
  const PrimN w = primitive(q, dim, gamma);
  const double cs = std::sqrt(std::abs(gamma * w.p / w.rho));
  for (int d = 0; d < dim; ++d) s[d] = std::abs(w.u[d]) + cs;
}

// The two directions other than d (b = 2 with one cell when the grid has fewer dimensions): the lines of
// direction d are ordered by (b, a), a fastest.
inline void otherDirections(int dim, int d, int* a, int* b) {
  *a = d == 0 ? 1 : 0;
  *b = dim == 3 ? (d == 2 ? 1 : 2) : 2;
}

// Component c of the line frame of direction d -> component of the global frame.
inline int frameComponent(int dim, int d, int c) {
  if (c == 0 || c == dim + 1) return c;
  if (c == 1) return 1 + d;
  int t = c - 2, other = -1; // t-th direction other than d, in increasing order
  for (int e = 0; e < dim; ++e)
    if (e != d && t-- == 0) other = e;
  return 1 + other;
}

} // namespace euler_app
