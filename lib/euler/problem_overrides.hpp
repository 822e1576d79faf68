// The user's changes to any problem's geometry, for -dim 1|2|3, applied after the problem is created:
//   the domain: -xmin -xmax -ymin -ymax -zmin -zmax (a 1D registered problem reads -xmin -xmax itself);
//   each face: -bc_x_lo -bc_x_hi -bc_y_lo -bc_y_hi -bc_z_lo -bc_z_hi, one of
//     outflow (zero-gradient), wall (reflecting), symmetry (the same mirror: the inviscid equations have no
//     wall friction, so a symmetry plane and a slip wall are one condition; kept as its own name for the
//     output), periodic (both faces of the direction, or an error), inflow (-bc_x_lo_state "rho,u[,v[,w]],p":
//     dim + 2 formulas of x, y, z and t, core/expression.hpp, held in the ghost cells);
//   the registered problems keep their faces (and their custom ones: double_mach's wall, jet's nozzle) unless
//   an option names them. A 1D registered problem's -bc_left / -bc_right are the same faces as -bc_x_lo /
//   -bc_x_hi: giving both names of one face is an error.
#pragma once

#include "euler/problem_nd.hpp"

#include <petscsys.h>

namespace suite::euler {

// -xmin ... -zmax of the problem's dimensions (from `first_dir`: 1 in 1D, where the line problem read x); a
// file problem's extents (fixed_extent) may be repeated, not changed. Collective.
PetscErrorCode readDomainOptions(MPI_Comm comm, int first_dir, ProblemND* problem);
// -bc_* of the problem's faces. Collective.
PetscErrorCode readFaceOptions(MPI_Comm comm, ProblemND* problem);

} // namespace suite::euler
