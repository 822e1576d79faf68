// Block Thomas (block LU of a block-tridiagonal line without pivoting between blocks, partial pivoting within
// each diagonal block; Isaacson & Keller, Analysis of Numerical Methods, 1966, sec. 2.3.3) for four open
// lines of the same length at once, one line per SIMD lane (GCC vector extension; an AVX2 clone chosen at run
// time, core/kernel_clones.hpp). Each lane runs the same IEEE operations in the same order as the one-line
// solve of substructured_block_lines.cpp (lineSolve with one right-hand side, SmallLU::factor and solveFast):
// the pivot of every lane is chosen as that solve chooses it (the first largest magnitude) and its rows are
// exchanged by selects, so each line's solution is bitwise the one-line solution. The 3D Euler block lines (5 x
// 5 blocks) spent 16-20% of a step in the one-line solve.
#pragma once

namespace suite::linalg {

constexpr int kThomasLanes = 4;

// One line: block row i at A + i * ms (bs x bs, row-major), right-hand side d + i * bs, solution x + i * bs.
// xl, xr: the solution's neighbours beyond the ends (the rows of other ranks, substructured_block_lines.cpp
// pass 2), moved to the right-hand side as d_0 - A_0 xl and d_{n-1} - C_{n-1} xr; nullptr: none (then A_0,
// C_{n-1} are not read). Either is given for all four lines or for none.
struct LaneLine {
  const double *A, *B, *C, *d;
  int ms;
  double* x;
  const double *xl = nullptr, *xr = nullptr;
};

// Doubles of work that blockThomasLanes needs for lines of n block rows of size bs.
inline long long blockThomasLanesWork(int bs, int n) {
  return (long long)kThomasLanes * n * (bs * bs + bs);
}

// Solves the kThomasLanes lines (bs = 3 to 5, the Euler systems of 1D to 3D; n >= 1 block rows each). work: blockThomasLanesWork(bs, n) doubles,
// 32-byte aligned. False (x unspecified) when SmallLU::factor would reject a pivot of any of the lines (below
// 1e-14 times the block's largest entry, or not finite), or for another bs: then the caller solves them one by one.
bool blockThomasLanes(int bs, int n, const LaneLine* lines, double* work);

// Pass 1 of the substructured solve (lineEnds of substructured_block_lines.cpp: the forward sweep with the
// spikes P = -T^-1 A_0 E_0 (when hasL) and Q = -T^-1 C_{n-1} E_{n-1} (when hasR), keeping the end rows) on the
// four lines (xl, xr, x not read), bitwise lineEnds: ends[l] receives line l's [YF, YL (bs each), PF, PL, QF,
// QL (bs x bs each)]. work: blockThomasLanesWork(bs, n) doubles, 32-byte aligned. False as blockThomasLanes.
bool blockEndsLanes(int bs, int n, const LaneLine* lines, bool hasL, bool hasR, double* work,
                    double* const* ends);

} // namespace suite::linalg
