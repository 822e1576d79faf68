// The fluid segments of a grid line cut by a solid obstacle (solid_body.hpp). The app marks a solid cell of a
// line by kSolidSentinel in its density; DirectionSweep (LineOptions::segmented) then solves each maximal run
// of fluid cells as a line of its own, with the scheme's boundary closures at both ends: where the run meets
// the solid, reflecting-wall ghost cells (the fluid mirrored across the wall face, normal momentum negated:
// the app's wall face, euler_rhs.cpp), where it meets the domain's end, the line's own ghosts. A periodic line
// with a solid cell is cut there: its runs may wrap around the end. Faces between two solid cells carry no
// flux (0). So a solid half-domain aligned with the grid is exactly a domain ending in a wall there.
// Ghost-free staircase walls: the solid boundary is the cell faces between fluid and solid cells.
#pragma once

#include <array>
#include <cfloat>
#include <string>
#include <vector>

namespace suite::euler {

constexpr double kSolidSentinel = -DBL_MAX;
constexpr int kMinSegment = 6; // the stencil width of a bounded line (2 x 3 ghost cells)

struct LineSegment {
  long long first; // first fluid cell (0 .. n-1)
  long long cells; // fluid cells (>= 1), first .. first + cells - 1 modulo n (periodic lines may wrap)
};

// q: ncell = n + 2 ghost states of a whole line (cells -ghost .. n + ghost - 1).
template <int NV> bool lineHasSolid(const std::array<double, NV>* q, long long n, int ghost) {
  for (long long i = 0; i < n; ++i)
    if (q[i + ghost][0] == kSolidSentinel) return true;
  return false;
}

// The maximal fluid runs of a whole line that has a solid cell.
template <int NV>
void findSegments(const std::array<double, NV>* q, long long n, int ghost, bool periodic,
                  std::vector<LineSegment>* out) {
  out->clear();
  auto solid = [&](long long i) { return q[i + ghost][0] == kSolidSentinel; };
  long long start = 0;
  if (periodic) // begin after a solid cell, so that a run across the end is one run
    while (!solid(start)) ++start;
  for (long long t = 0; t < n;) {
    const long long i = (start + t) % n;
    if (solid(i)) {
      ++t;
      continue;
    }
    long long len = 0;
    while (t + len < n && !solid((start + t + len) % n)) ++len;
    out->push_back({i, len});
    t += len;
  }
}

// The segment as a bounded line of s.cells cells and `ghost` ghosts on each side (seg: s.cells + 2 ghost states):
// reflecting ghosts at solid ends, the line's ghosts at the domain's ends of a non-periodic line.
template <int NV>
void buildSegment(const std::array<double, NV>* q, long long n, int ghost, bool periodic,
                  const LineSegment& s, std::array<double, NV>* seg) {
  const long long L = s.cells;
  auto cell = [&](long long i) { return q[(periodic ? ((i % n) + n) % n : i) + ghost]; };
  const bool domain_lo = !periodic && s.first == 0, domain_hi = !periodic && s.first + L == n;
  for (long long t = -ghost; t < L + ghost; ++t) {
    std::array<double, NV>& g = seg[t + ghost];
    if (t >= 0 && t < L) {
      g = cell(s.first + t);
    } else if (t < 0) {
      if (domain_lo) {
        g = q[t + ghost];
      } else {
        g = cell(s.first + (-1 - t));
        g[1] = -g[1];
      }
    } else {
      if (domain_hi) {
        g = q[n + (t - L) + ghost];
      } else {
        g = cell(s.first + L - 1 - (t - L));
        g[1] = -g[1];
      }
    }
  }
}

// Faces 0 .. s.cells of the segment's fluxes into the line's faces (n + 1 of them; on a periodic line face n
// is face 0).
template <int NV>
void scatterSegmentFaces(const std::array<double, NV>* hs, long long n, bool periodic, const LineSegment& s,
                         std::array<double, NV>* h) {
  for (long long k = 0; k <= s.cells; ++k) {
    long long f = s.first + k;
    if (periodic) {
      f %= n;
      h[f] = hs[k];
      if (f == 0) h[n] = hs[k];
    } else {
      h[f] = hs[k];
    }
  }
}

} // namespace suite::euler
