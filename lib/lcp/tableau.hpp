// Dense pivoting tableau in the compact (dictionary) form x_B = b + A x_N used by the complementary
// pivoting methods (Lemke, Cottle-Dantzig): variable ids 0..n-1 are w_i, n..2n-1 are z_i, 2n is Lemke's
// artificial z0. A simple pivot exchanges the basic variable of one row with a nonbasic column
// (O(rows*cols)).
#pragma once

#include "lcp/problem.hpp"

#include <vector>

namespace suite::lcp {

struct Tableau {
  // Initial dictionary w = q + M z (+ d z0 if with_z0): basic w, nonbasic z (and z0 as last column).
  Tableau(const Mat& M, const Vec& q, const Vec* d);
  int n;
  Vec b;                           // values of the basic variables
  Mat A;                           // n x ncols
  std::vector<int> basic;          // variable id of each row
  std::vector<int> nonbasic;       // variable id of each column
  std::vector<int> row_of, col_of; // -1 if not in that role
  // Exchanges the basic variable of row r with the nonbasic variable of column c.
  void pivot(int r, int c);
  // Row r of B^{-1} (coefficients of the original basis w in the perturbation), entry k.
  double binv(int r, int k) const {
    const int c = col_of[k];
    if (c < 0) return row_of[k] == r ? 1.0 : 0.0;
    return -A(r, c);
  }
  // z of the current basic solution: basic z_i take their row value (clipped at 0 against round-off),
  // nonbasic z_i are 0.
  Vec zValues() const;
  static int complement(int id, int n) { return id < n ? id + n : (id < 2 * n ? id - n : -1); }
};

} // namespace suite::lcp
