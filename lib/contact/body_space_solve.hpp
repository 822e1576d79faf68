// Solves A_FF x = r on a set F of free contact rows, A = J M^-1 J^T + D with the compliance D > 0 diagonal
// (delassus.hpp), in body space by the Woodbury identity
//   (D + J M^-1 J^T)^-1 = D^-1 - D^-1 J (M + J^T D^-1 J)^-1 J^T D^-1,
// so that the factorised matrix K = M + J_F^T D_F^-1 J_F has the size 6 x bodies, whatever the number of
// contact rows, and the sparsity of the body graph (6 x 6 blocks of the bodies sharing a free row): a resting
// pyramid of 55 boxes factorises a 330-row K instead of a 1,200-row A_FF. The answer is refined on A_FF
// (matrix-free products) until its residual is at round-off (16 eps |r|) or stops falling, at most 4 times.
// This is the compliant-constraint form of the Schur complement (Lacoursiere, "Ghosts and machines", PhD
// thesis, Umea 2007, ch. 5; Servin et al., "Interactive simulation of elastic deformable materials", SIGRAD
// 2006, for the Woodbury step).
// BodySpaceSolver keeps one factorisation for the many free sets F of one problem (the active-set iterations
// and the splitting passes of a step): the block pattern of K over every row (the 6 x 6 blocks of each body and
// of each body pair sharing a row) is ordered once, by AMD on the body graph (Amestoy, Davis & Duff, SIAM J.
// Matrix Anal. Appl. 17 (1996)), and analysed once by the block Cholesky (block_cholesky.hpp: elimination tree
// and column structures over bodies), so that each new F costs the numeric factorisation only, its values added
// straight into K's blocks (Davis, "Direct methods for sparse linear systems", SIAM 2006, ch. 4: the symbolic
// analysis depends on the pattern alone); a solve with the F of the last factorisation reuses it as is, and a
// free set that differs from the factorised one by at most 16 rows (the active-set iterations exchange a few rows
// at a time) is solved by a low-rank update of that factorisation instead of a new one: K(F) = K(F_) + U Sigma U^T
// (a column J_i^T per row added or removed) by the Woodbury identity once more, K(F_)^-1 U kept per row until the
// next factorisation (Hager, "Updating the inverse of a matrix", SIAM Review 31 (1989); Davis & Hager, SIAM J.
// Matrix Anal. Appl. 20 (1999) for the factor-modifying alternative). An updated answer that is not backward
// stable to 1e-13 (componentwise, Oettli & Prager 1964) is recomputed with a fresh factorisation.
#pragma once

#include "contact/block_cholesky.hpp"
#include "contact/delassus.hpp"

#include <vector>

namespace suite::contact {

// Body mass matrices diag(m I, I_world) (zero for static bodies).
std::vector<M6> bodyMassMatrices(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i);

class BodySpaceSolver {
public:
  // rows, mass: referenced (they must outlive the solver); reg: D per row of A.
  BodySpaceSolver(const std::vector<JRow>& rows, const std::vector<M6>& mass, lcp::Vec reg);
  // x = A_FF^-1 r (r, x indexed like F, F increasing); false as bodySpaceSolve.
  bool solve(const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x);
  int factorizations() const { return factorizations_; } // numeric factorisations so far
  int updates() const { return updates_; }               // low-rank updates of a factorisation so far
  int solves() const { return solves_; }

private:
  bool factor(const std::vector<int>& F);
  bool update(const std::vector<int>& F);
  int maxUpdate() const;
  int newColumn(int i);
  double rowDot(int i, const lcp::Vec& y) const;
  void addRowT(int i, double s, lcp::Vec* g) const;
  void kSolve(lcp::Vec* y) const;
  double refinedSolve(const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x) const;
  double backwardError(const std::vector<int>& F, const lcp::Vec& r, const lcp::Vec& x) const;
  void orderBodies(const std::vector<std::pair<int, int>>& pairs);
  void buildPattern();
  int pos(int body) const { return at_[body] / 6; } // the body's block in K
  void addRow(int i, double s);                     // K += s J_i^T J_i
  lcp::Vec woodbury(const std::vector<int>& F, const lcp::Vec& rhs) const;
  lcp::Vec applyFree(const std::vector<int>& F, const lcp::Vec& x) const;
  const std::vector<JRow>& rows_;
  const std::vector<M6>& mass_;
  const lcp::Vec reg_;
  BlockCholesky chol_;
  std::vector<int> at_;         // first unknown of each body in K (6 x its place in the order)
  std::vector<int> pair_block_; // per body pair: its lower block in chol_
  std::vector<int> pair_of_;    // per row: its pair, -1 without a pair
  std::vector<bool> a_first_;   // per row: body ba comes before bb in the order
  std::vector<int> F_;          // the free set of the current factorisation
  std::vector<int> cur_;        // the free set solved for: F_, or F_ changed by the rows changed_
  std::vector<int> changed_;    // rows added to or removed from F_ (the update's columns, see update())
  Eigen::MatrixXd W_;           // columns K(F_)^-1 J_i^T of the rows changed so far (wcol_[i]: its column)
  std::vector<int> wcol_;
  int wcount_ = 0;
  Eigen::PartialPivLU<Eigen::MatrixXd> S_; // Sigma^-1 + J_changed K(F_)^-1 J_changed^T
  bool ok_ = false;                        // the current factorisation holds K(F_)
  int factorizations_ = 0, updates_ = 0, solves_ = 0;
};

// x = A_FF^-1 r for the rows F (r, x indexed like F); reg: D per row of A. false: some D_i <= 0, or K not
// positive definite (the caller uses the row-space factorisation).
bool bodySpaceSolve(const std::vector<JRow>& rows, const std::vector<M6>& mass, const lcp::Vec& reg,
                    const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x);

} // namespace suite::contact
