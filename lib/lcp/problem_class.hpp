// Cheap classification of an LCP / box LCP / MLCP for the solver portfolio (portfolio.hpp): structure
// (standard LCP, box, MLCP), matrix type and size band. The classification must cost little next to the
// fastest solver of the class (measured: bpp on a 300 x 300 box LCP in 80 us, a Cholesky factorisation of
// the same matrix in ~1 ms), so it is O(n^2) except for large problems:
//
// Matrix type, first that applies:
//   dd      strictly row diagonally dominant with a positive diagonal (a P-matrix; PGS converges: Cottle,
//           Pang & Stone 2009, 5.3)
//   sym     symmetric (exactly), and a diagonal entry or a 2 x 2 principal minor <= 0 (not positive definite),
//           or (large only) the Cholesky factorisation of M fails
//   spd     symmetric, every diagonal entry and 2 x 2 principal minor > 0 (necessary for positive
//           definiteness), and (large only) the Cholesky factorisation of M succeeds
//   gen     nonsymmetric, a diagonal entry or a 2 x 2 principal minor of (M + M^T) / 2 <= 0 or (large only)
//           its Cholesky factorisation fails (Lemke may ray-terminate, the Newton methods may stall)
//   pd      nonsymmetric otherwise (positive definite symmetric part, hence a P-matrix, CPS 2009, 3.1.6, when
//           the factorisation confirmed it)
// Size band: small n <= 32, medium n <= 256, large n > 256. The Cholesky test is attempted for large
// problems only, where a wrong chain costs far more than the factorisation (a failed Newton run on n = 1000
// took 16 s, the factorisation ~30 ms).
// The class name is "<structure>-<matrix>-<size>", e.g. "box-spd-large".
#pragma once

#include "lcp/problem.hpp"

#include <string>
#include <vector>

namespace suite::lcp {

struct ProblemFeatures {
  int n = 0;
  Kind kind = Kind::LCP;
  double density = 0;        // fraction of nonzero entries of M
  bool symmetric = false;    // M == M^T exactly (isSymmetric(p) of solver.hpp, as the solvers test it)
  bool diag_positive = false; // M_ii > 0 for all i
  bool diag_dominant = false; // strictly row diagonally dominant with a positive diagonal
  bool minors_ok = false;     // every diagonal entry and 2 x 2 principal minor of (M + M^T) / 2 is > 0
  bool cholesky_tried = false; // the factorisation below was attempted
  bool cholesky_ok = false;   // Cholesky of M (symmetric) or of its symmetric part succeeded (not tried if dd)
  int finite_lower = 0, finite_upper = 0; // number of finite bounds
  std::string structure;     // "lcp", "box", "mlcp"
  std::string matrix;        // "dd", "spd", "sym", "pd", "gen"
  std::string size;          // "small", "medium", "large"
  std::string name() const { return structure + "-" + matrix + "-" + size; }
};

// The features and class of p (which must be valid, see validate()).
ProblemFeatures classify(const Problem& p);

// Every class name classify() can return, in a fixed order (the index used in lcpbench's output).
const std::vector<std::string>& problemClassNames();
// Index of a class name in problemClassNames(), -1 if none.
int problemClassIndex(const std::string& name);

} // namespace suite::lcp
