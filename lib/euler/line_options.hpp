// Options and counters of the line schemes (DirectionSweep), shared by the 1D and 2D/3D Euler runs:
// rf-char upwinding (rf_char.hpp) or Lax-Friedrichs flux splitting f+- = (f +- alpha U)/2 (local alpha:
// max |u|+c over the row's stencil; global:
// over the direction; compact schemes always use the global alpha: a compact row couples h+- of its neighbours,
// which must be split with the same alpha, otherwise the alpha U parts of f+ and f- no longer cancel and the
// scheme is inconsistent — measured: Sod N = 200 L1(rho) 5.5e-3 with per-row alpha vs 2.4e-3 with the global
// one), characteristic-wise or component-wise rows, the ENO-Pade shock sensor's amplitude threshold and
// resolution (points per wavelength; enopade6.hpp), the positivity limiter.
#pragma once

#include <cstddef>

namespace suite::euler {

constexpr int kLineGhost = 3; // stencil half-width: ghost cells needed on each side of a rank's cells
// The CFL number up to which the positivity limiter is proven with SSP-RK3 (direction_sweep.hpp).
constexpr double kPositivityCfl = 0.5;

struct LineOptions {
  double gamma = 1.4;
  bool characteristic = true; // false: component-wise rows
  bool local_lf = true;       // false: global Lax-Friedrichs alpha
  // rf-char upwinding of the characteristic fields (rf_char.hpp; characteristic rows only): Lax-Friedrichs only
  // for the fields whose speed changes sign at a face. false: Lax-Friedrichs splitting of every field. The
  // Euler app's default comes from the scheme (SchemeInfo::rf_char_default).
  bool rf_char = true;
  double shock_threshold = 0.02; // ENO-Pade sensor: amplitude test (Jameson phi)
  double shock_ppw = 8.0;        // ENO-Pade sensor: resolution test, points per wavelength (0: off)
  bool positivity = true;
  bool gather_lines = false; // true: gather each line to every rank (DistributedTridiag), for comparison
  // Compact schemes, lines split over the ranks of a line communicator with at least as many lines as ranks:
  // true: pencil transpose (LineTranspose), each rank solves whole lines serially; false: substructured solve
  // of the split lines (SubstructuredBlockLines).
  bool transpose_lines = true;
  size_t batch_bytes = size_t(256) << 20; // memory of one batch of block lines (DirectionSweep)
  // A solid obstacle cuts the lines (line_segments.hpp): cells with density kSolidSentinel are solid; every line
  // is moved whole to one rank (the pencil transpose, also for explicit schemes and for fewer lines than ranks)
  // and each of its fluid segments is solved as a bounded line.
  bool segmented = false;
};

struct LineStats {
  // shock_rows of the rows the ENO-Pade sensor examined (sensor_rows: every row of every line, hybrid schemes)
  long long shock_rows = 0, sensor_rows = 0, limited_faces = 0, evaluations = 0;
  // Faces the positivity limiter could not make safe: their Lax-Friedrichs sides are not positive, which happens
  // only above the limiter's CFL bound (direction_sweep.hpp); the Euler run retries such a step at half dt.
  long long unattainable_faces = 0;
  // Face evaluations treated component-wise because their characteristic basis is ill-conditioned
  // (characteristic_conditioning.hpp; characteristic rows only).
  long long componentwise_faces = 0;
};

} // namespace suite::euler
