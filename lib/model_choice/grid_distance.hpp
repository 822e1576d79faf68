// The L1 distance between two solutions of one problem on two uniform cell-centred grids of the same box
// (1D/2D/3D, resolutions in any ratio): the finer solution is interpolated to the coarser grid's cell centres
// axis by axis, and the mean over the coarse cells of |coarse - interpolated fine| is returned (the L1 norm
// divided by the box volume, as the apps report their errors).
//
// Interpolation: six-point Lagrange (sixth order, so that the distance between two runs of a sixth-order
// scheme on smooth flow is not swamped by the transfer), limited near discontinuities to the range of the two
// nearest values widened by half the minmod of the four nearest second differences (the bound of Suresh &
// Huynh's monotonicity-preserving schemes, J. Comput. Phys. 136 (1997) 83-99): smooth extrema keep their
// curvature, a jump is not overshot.
#pragma once

#include <array>
#include <vector>

namespace suite::model_choice {

struct GridField {
  int dim = 1;
  std::array<long long, 3> n = {1, 1, 1};               // cells per axis (1 beyond dim)
  std::array<double, 3> lo = {0, 0, 0}, hi = {1, 1, 1}; // the box
  std::vector<double> values;                           // x fastest: i + n0 (j + n1 k)
  long long cells() const { return n[0] * n[1] * n[2]; }
};

// f's values (centres lo + (i + 1/2) (hi - lo) / nf) interpolated to x.
double interpolateLine(const double* f, long long nf, double lo, double hi, double x);

// Mean over the coarser grid's cells of |a - b|; the grids must have the same dim and box.
double l1Distance(const GridField& a, const GridField& b);

} // namespace suite::model_choice
