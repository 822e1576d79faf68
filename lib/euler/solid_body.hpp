// Solid obstacles in an Euler run, for -dim 1|2|3 and any problem:
//   -solid "formula": a cell is solid where the formula of its centre (x[, y[, z]]; core/expression.hpp) is > 0,
//     e.g. "0.04 - (x-1)^2 - y^2" a cylinder of radius 0.2;
//   -solid_mask FILE.h5: dataset `mask` (the root, or -solid_mask_group) on the run's grid ((z,) (y,) x order),
//     non-zero = solid (a run's output holds /final/mask).
// The solid's boundary is the staircase of cell faces between fluid and solid cells; each is a reflecting wall
// (line_segments.hpp: the lines are cut into fluid segments with the schemes' wall closures). Solid cells keep
// their initial state, take no part in the time step, the conservation sums and the wave speeds, and are
// written as the `mask` field. Problems with an obstacle of their own (forward_step, shock_cylinder,
// shock_sphere: problem_nd_obstacles.cpp) refuse -solid and -solid_mask.
#pragma once

#include "euler/problem_nd.hpp"

#include <petscsys.h>

#include <vector>

namespace suite::euler {

// Collective: -solid / -solid_mask into problem->solid / solid_mask_file (checked: parses; the file's dataset
// exists with the grid's rank).
PetscErrorCode readSolidOptions(MPI_Comm comm, ProblemND* problem);

// Collective: solid[c] (1 solid, 0 fluid) for the cells c of the block s .. s + m - 1 (x fastest) of the grid n
// on the domain problem.lo .. problem.hi. A formula that is not finite at a cell centre, a mask of another
// shape, or no fluid cell left anywhere is one error naming the cell or the file.
PetscErrorCode solidCells(MPI_Comm comm, const ProblemND& problem, const PetscInt n[3], const PetscInt s[3],
                          const PetscInt m[3], std::vector<char>* solid);

} // namespace suite::euler
