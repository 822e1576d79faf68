// The contact rows of a matrix-free step (-contact_accuracy fast): J, M^-1 J^T and b per row as buildDelassus
// (delassus.hpp) makes them, without forming the Delassus matrix, and the compliance part of each row's
// diagonal, reg_i = (regularisation or regularisation_t) (J M^-1 J^T)_ii. The block PGS sweeps (block_pgs.hpp)
// need nothing else; building the sparse matrix took a third of a fast step on the base-10 pyramid.
#pragma once

#include "contact/delassus.hpp"

namespace suite::contact {

struct ContactRows {
  DelassusSystem sys; // rows, b, nbodies (S and A left empty)
  lcp::Vec reg;       // compliance part of A_ii per row
};

ContactRows buildContactRows(const std::vector<Body>& bodies, const std::vector<Mat3>& inv_i,
                             const std::vector<Vec3>& vstar, const std::vector<Contact>& cs,
                             const std::vector<ConstraintRow>& rows, const StepperOptions& o);

} // namespace suite::contact
