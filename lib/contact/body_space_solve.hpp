// Solves A_FF x = r on a set F of free contact rows, A = J M^-1 J^T + D with the compliance D > 0 diagonal
// (delassus.hpp), in body space by the Woodbury identity
//   (D + J M^-1 J^T)^-1 = D^-1 - D^-1 J (M + J^T D^-1 J)^-1 J^T D^-1,
// so that the factorised matrix K = M + J_F^T D_F^-1 J_F has the size 6 x bodies, whatever the number of
// contact rows, and the sparsity of the body graph (6 x 6 blocks of the bodies sharing a free row): a resting
// pyramid of 55 boxes factorises a 330-row K instead of a 1,200-row A_FF. The answer is refined on A_FF
// (matrix-free products) until it stops improving, at most 4 times. This is the compliant-constraint form of
// the Schur complement (Lacoursiere, "Ghosts and machines", PhD thesis, Umea 2007, ch. 5; Servin et al.,
// "Interactive simulation of elastic deformable materials", SIGRAD 2006, for the Woodbury step).
#pragma once

#include "contact/delassus.hpp"

#include <vector>

namespace suite::contact {

// Body mass matrices diag(m I, I_world) (zero for static bodies).
std::vector<M6> bodyMassMatrices(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i);

// x = A_FF^-1 r for the rows F (r, x indexed like F); reg: D per row of A. false: some D_i <= 0, or K not
// positive definite (the caller uses the row-space factorisation).
bool bodySpaceSolve(const std::vector<JRow>& rows, const std::vector<M6>& mass, const lcp::Vec& reg,
                    const std::vector<int>& F, const lcp::Vec& r, lcp::Vec* x);

} // namespace suite::contact
