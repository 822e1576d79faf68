// Cheap classification of an LCP / box LCP / MLCP for the solver portfolio (portfolio.hpp): structure
// (standard LCP, box, MLCP), matrix type and size band, from features that cost at most one Cholesky
// factorisation (O(n^3 / 3), the cost of one pivoting solve's first factorisation).
//
// Matrix type, first that applies:
//   dd      strictly row diagonally dominant with a positive diagonal (a P-matrix; PGS converges: Cottle,
//           Pang & Stone 2009, 5.3; no factorisation tried)
//   spd     symmetric and the Cholesky factorisation of M succeeds (positive definite)
//   sym     symmetric, not positive definite (semidefinite or indefinite)
//   pd      nonsymmetric, the Cholesky factorisation of (M + M^T) / 2 succeeds (positive definite, hence a
//           P-matrix: every LCP has a unique solution, CPS 2009, 3.1.6)
//   gen     anything else (Lemke may ray-terminate; the Newton methods may stall)
// Before the factorisation, O(n^2) tests rule positive definiteness out when a diagonal entry or a 2 x 2
// principal minor of the symmetric part is <= 0 (necessary conditions); classifyCheap() stops there, so that
// the portfolio factorises only when the outcome changes the chain (portfolio.cpp).
// Size band: small n <= 32, medium n <= 256, large n > 256.
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
  bool symmetric = false;    // |M - M^T|_max <= 1e-14 |M|_max
  bool diag_positive = false; // M_ii > 0 for all i
  bool diag_dominant = false; // strictly row diagonally dominant with a positive diagonal
  bool minors_ok = false;     // every diagonal entry and 2 x 2 principal minor of (M + M^T) / 2 is > 0
  bool cholesky_tried = false; // the factorisation below was attempted
  bool cholesky_ok = false;   // Cholesky of M (symmetric) or of its symmetric part succeeded (not tried if dd)
  int finite_lower = 0, finite_upper = 0; // number of finite bounds
  std::string structure;     // "lcp", "box", "mlcp"
  std::string matrix;        // "dd", "spd", "sym", "pd", "gen"; "" while undecided (classifyCheap)
  std::string size;          // "small", "medium", "large"
  std::string name() const { return nameWith(matrix); }
  std::string nameWith(const std::string& m) const { return structure + "-" + m + "-" + size; }
  // The two possible matrix types while undecided: positive definite or not.
  std::string ifDefinite() const { return symmetric ? "spd" : "pd"; }
  std::string ifNotDefinite() const { return symmetric ? "sym" : "gen"; }
};

// The features and class of p (which must be valid, see validate()).
ProblemFeatures classify(const Problem& p);
// Everything but the factorisation: matrix is "" when only the Cholesky can tell definite from not.
ProblemFeatures classifyCheap(const Problem& p);
// Completes an undecided classification with the Cholesky factorisation.
void classifyByCholesky(const Problem& p, ProblemFeatures* f);

// Every class name classify() can return, in a fixed order (the index used in lcpbench's output).
const std::vector<std::string>& problemClassNames();
// Index of a class name in problemClassNames(), -1 if none.
int problemClassIndex(const std::string& name);

} // namespace suite::lcp
