// DirectionSweep on lines cut by a solid obstacle (LineOptions::segmented; line_segments.hpp): the lines
// without a solid cell are processed together as usual, each fluid segment of the others as a bounded line of
// its own (the same code as a domain ending in a wall there), faces between solid cells carry no flux.
#include "euler/direction_sweep.hpp"
#include "euler/line_segments.hpp"

#include <stdexcept>
#include <string>

namespace suite::euler {

template <int NV>
void DirectionSweep<NV>::segmentedFaceFluxes(const V* q, int nlines, long long n, bool periodic, double alpha,
                                             double lambda, V* h) {
  const long long ncell = n + 2 * kGhost, nface = n + 1;
  struct Guard { // the nested calls below take the plain path
    bool& flag;
    explicit Guard(bool& f) : flag(f) { flag = true; }
    ~Guard() { flag = false; }
  } guard(in_segment_);
  clean_.clear();
  for (int l = 0; l < nlines; ++l)
    if (!lineHasSolid<NV>(q + l * ncell, n, kGhost)) clean_.push_back(l);
  if (!clean_.empty()) {
    const int nc = (int)clean_.size();
    seg_q_.resize((size_t)nc * ncell);
    seg_h_.resize((size_t)nc * nface);
    for (int i = 0; i < nc; ++i) std::copy_n(q + clean_[i] * ncell, ncell, seg_q_.data() + (size_t)i * ncell);
    linesFaceFluxes(MPI_COMM_SELF, seg_q_.data(), nc, n, 0, (int)n, periodic, alpha, lambda, seg_h_.data());
    for (int i = 0; i < nc; ++i) std::copy_n(seg_h_.data() + (size_t)i * nface, nface, h + clean_[i] * nface);
  }
  std::vector<LineSegment> segments;
  size_t next_clean = 0;
  for (int l = 0; l < nlines; ++l) {
    if (next_clean < clean_.size() && clean_[next_clean] == l) {
      ++next_clean;
      continue;
    }
    const V* ql = q + l * ncell;
    V* hl = h + l * nface;
    for (long long k = 0; k < nface; ++k) hl[k] = V{}; // faces between solid cells
    findSegments<NV>(ql, n, kGhost, periodic, &segments);
    for (const LineSegment& s : segments) {
      if (s.cells < kMinSegment)
        throw std::runtime_error("the solid leaves a fluid gap of " + std::to_string(s.cells) +
                                 " cell(s) (cells " + std::to_string(s.first) + " .. " +
                                 std::to_string((s.first + s.cells - 1) % n) + " of a line of " +
                                 std::to_string(n) + "): a fluid segment needs at least " +
                                 std::to_string(kMinSegment) +
                                 " cells, the schemes' bounded stencil; refine the grid or widen the gap");
      seg_q_.resize((size_t)s.cells + 2 * kGhost);
      seg_h_.resize((size_t)s.cells + 1);
      buildSegment<NV>(ql, n, kGhost, periodic, s, seg_q_.data());
      linesFaceFluxes(MPI_COMM_SELF, seg_q_.data(), 1, s.cells, 0, (int)s.cells, false, alpha, lambda,
                      seg_h_.data());
      scatterSegmentFaces<NV>(seg_h_.data(), n, periodic, s, hl);
    }
  }
}

template void DirectionSweep<3>::segmentedFaceFluxes(const V*, int, long long, bool, double, double, V*);
template void DirectionSweep<4>::segmentedFaceFluxes(const V*, int, long long, bool, double, double, V*);
template void DirectionSweep<5>::segmentedFaceFluxes(const V*, int, long long, bool, double, double, V*);

} // namespace suite::euler
