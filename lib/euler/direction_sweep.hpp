// Interface fluxes of ALL grid lines of one direction of a 2D/3D grid (the 1D scheme of line_operator.hpp
// applied direction by direction): Lax-Friedrichs flux splitting, characteristic-wise rows with the
// direction's Roe eigenvectors (gas_nd.hpp), the ENO-Pade / CRWENO / WENO rows of the scheme registry, and
// for compact schemes one batched, exact, distributed solve of every line of the direction
// (SubstructuredBlockLines): lines whose rows are all Pade (or explicit) rows take the scalar solve with NV
// right-hand sides, the others two NV x NV block systems (split fluxes f+ and f-). The decision is reduced over
// the ranks that share a line, so per call the messages are O(1) in the number of lines: one Allreduce of the
// line flags, and for each batch one Allgather and one Allreduce: one scalar batch, and block batches of at most
// LineOptions::batch_bytes of rows each (256 MiB: one batch for a 64^3 block even if every line is shocked).
// References: as line_operator.hpp (Shu 1997; Ghosh & Baeder 2012; Lele 1992); dimension-by-dimension
// finite-difference form: Shu, ICASE report 97-65, sec. 2.3.2 (the 1D flux derivative applied along each
// direction, the eigenvectors of that direction's flux Jacobian).
#pragma once

#include "euler/gas_nd.hpp"
#include "euler/line_operator.hpp"
#include "euler/schemes.hpp"
#include "linalg/substructured_block_lines.hpp"

#include <mpi.h>

#include <vector>

namespace suite::euler {

template <int NV> class DirectionSweep {
public:
  using V = typename LineGas<NV>::V;
  static constexpr int kGhost = LineOperator::kGhost;

  DirectionSweep(const SchemeInfo* scheme, const LineOptions& options) : scheme_(scheme), opt_(options) {}

  // q: nlines lines of xm + 2 kGhost states each (cells xs-3 .. xs+xm+2 of the line, in the line's frame,
  // ghosts filled), line after line. n: global cells along the direction; xs, xm: this rank's cells.
  // line_comm: the ranks sharing these lines, in line order (every rank passes the same nlines).
  // alpha: the Lax-Friedrichs speed for compact schemes and -local_lf false (max |u_n| + c of the direction).
  // lambda = dt/dx scaled for the positivity limiter (<= 0: off). Output h: nlines x (xm + 1) face fluxes,
  // h[l (xm+1) + k] at x_{xs+k-1/2}. Collective on line_comm for compact schemes.
  void faceFluxes(MPI_Comm line_comm, const V* q, int nlines, long long n, long long xs, int xm,
                  bool periodic, double alpha, double lambda, V* h);

  const LineStats& stats() const { return stats_; }
  const linalg::SubstructuredBlockLines& lineSolver() const { return lines_; }

private:
  struct LineWork; // per-line scratch (defined in the .cpp)
  void lineExplicit(const V* q, long long n, long long xs, int xm, bool periodic, double alpha, V* h);
  bool lineNeedsBlocks(const V* q, long long n, long long xs, int nown, bool periodic, char* shock);
  void lineCompactRows(const V* q, long long n, long long xs, int xm, int nown, bool periodic, double alpha,
                       const char* shocks, bool blocks, double* abc, double* rhs, double* A[2], double* B[2],
                       double* C[2], double* d[2]);
  void prepareLine(const V* q, int xm, double alpha_global);

  const SchemeInfo* scheme_;
  LineOptions opt_;
  LineStats stats_;
  linalg::SubstructuredBlockLines lines_;
  std::vector<V> f_;
  std::vector<double> speed_, rho_, p_, alpha_;
  std::vector<int> flag_, blocks_;
  std::vector<char> shock_; // per line and owned row: ENO-Pade shock row
  std::vector<double> sabc_, srhs_, sx_, bA_, bB_, bC_, bd_, bx_;
};

extern template class DirectionSweep<3>;
extern template class DirectionSweep<4>;
extern template class DirectionSweep<5>;

} // namespace suite::euler
