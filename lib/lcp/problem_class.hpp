// Cheap classification of an LCP / box LCP / MLCP for the solver portfolio (portfolio.hpp): structure
// (standard LCP, box, MLCP), matrix type and size band. The classification must cost little next to the
// fastest solver of the class, so it is O(n^2) by default: measured on a 300 x 300 box LCP, bpp solves it in
// 80 us and a Cholesky factorisation of M takes ~800 us (auto with the factorisation: 10.7 times the oracle).
//
// Matrix type, first that applies:
//   dd      strictly row diagonally dominant with a positive diagonal (a P-matrix; PGS converges: Cottle,
//           Pang & Stone 2009, 5.3)
//   tril    nonsymmetric, lower triangular with a positive diagonal: a P-matrix (its principal minors are
//           products of diagonal entries), e.g. Murty's example (Murty 1988, ch. 6: 2^n - 1 Lemke pivots),
//           whose symmetric part is indefinite (a class of its own, not "gen" with the Siconos files' general
//           matrices)
//   triu    the same, upper triangular (e.g. the Siconos files lcp_exp_murty*, Murty's matrix transposed).
//           Apart from tril because the solvers' costs differ by orientation: a pivoting or sweeping order
//           that follows the triangle settles each index once (Murty's example, tril: cottle_dantzig 0.24 us
//           at n = 8, pgs 0.34 us; the Siconos files, triu: pgs 0.43 us, cottle_dantzig 0.78 / 3.4 us)
//   sym     symmetric (exactly) and not positive definite: a diagonal entry or a 2 x 2 principal minor <= 0,
//           or (with the Cholesky test) the factorisation of M fails
//   spd     symmetric otherwise: every diagonal entry and 2 x 2 principal minor > 0 (necessary for
//           definiteness; with the Cholesky test: the factorisation succeeds, positive definite)
//   gen     nonsymmetric, the same tests on (M + M^T) / 2 fail (Lemke may ray-terminate, the Newton methods
//           may stall)
//   pd      nonsymmetric otherwise (positive definite symmetric part, hence a P-matrix, CPS 2009, 3.1.6, when
//           the factorisation confirmed it)
// Size band: small n <= 32, medium n <= 256, large n > 256.
// The class name is "<structure>-<matrix>-<size>", e.g. "box-spd-large".
#pragma once

#include "lcp/problem.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace suite::lcp {

struct ProblemFeatures {
  int n = 0;
  Kind kind = Kind::LCP;
  double density = 0;          // fraction of nonzero entries of M
  bool symmetric = false;      // M == M^T exactly (isSymmetric(p) of solver.hpp, as the solvers test it)
  bool diag_positive = false;  // M_ii > 0 for all i
  bool diag_dominant = false;  // strictly row diagonally dominant with a positive diagonal
  bool triangular = false;     // nonsymmetric, not dd, lower or upper triangular with a positive diagonal
  bool minors_ok = false;      // every diagonal entry and 2 x 2 principal minor of (M + M^T) / 2 is > 0
  bool cholesky_tried = false; // the factorisation below was attempted
  bool cholesky_ok = false; // Cholesky of M (symmetric) or of its symmetric part succeeded (not tried if dd)
  bool minors_deferred = false; // classify(p, false, true): the minors test was left out, class spd / pd
                                // provisional (see classify)
  int finite_lower = 0, finite_upper = 0; // number of finite bounds
  std::string_view structure;             // "lcp", "box", "mlcp" (static strings: no copy per problem)
  std::string_view matrix;                // "dd", "tril", "triu", "spd", "sym", "pd", "gen"
  std::string_view size;                  // "small", "medium", "large"
  int class_index = -1;                   // index of name() in problemClassNames()
  std::string name() const {
    return std::string(structure) + "-" + std::string(matrix) + "-" + std::string(size);
  }
};

// The features and class of p (which must be valid, see validate()). thorough: decide definiteness by an
// attempted Cholesky factorisation when the O(n^2) tests pass, and count the nonzeros (density); off in the
// portfolio (see above; the chains do not depend on the density of the dense problems measured).
// defer_minors (not with thorough; solveAuto): when the matrix is neither dd nor tril / triu and its diagonal
// is positive, the 2 x 2 minors test (O(n^2), the dearest of the tests) is left out and the matrix classed
// spd / pd provisionally, minors_deferred set (minors_ok is then not computed); classify(p) gives the final
// class.
ProblemFeatures classify(const Problem& p, bool thorough = false, bool defer_minors = false);

// Every class name classify() can return, in a fixed order (the index used in lcpbench's output).
const std::vector<std::string>& problemClassNames();
// Index of a class name in problemClassNames(), -1 if none.
int problemClassIndex(const std::string& name);

} // namespace suite::lcp
