// Loads of a beam clamped at one end (femdyn's cantilever): a total force P along -y on the end face x = max
// as a uniform traction (consistent nodal loads on its boundary faces), gravity as a body force, and the mean
// displacement of the end-face nodes (the tip deflection).
#pragma once

#include "fem/assembly.hpp"

#include <vector>

namespace suite::fem {

// The nodes on the end plane x = max of the mesh.
std::vector<int> tipNodes(const TetMesh& mesh);
// f (free DOFs) = the load of a total force P along -y spread uniformly over the boundary faces on the end
// plane x = max; zero for P = 0. Errors (naming -tip_load) if that plane holds no boundary face.
PetscErrorCode tipTractionLoad(MPI_Comm comm, const ElasticModel& model, double P, std::vector<double>* f);
// Adds the consistent load of the body force rho g to f (nothing for g = 0).
void addGravityLoad(const ElasticModel& model, double rho, const double g[3], std::vector<double>* f);
// The mean of component c (times sign) of a full displacement (3 per node) over the nodes (0 without any).
double nodalMean(const std::vector<double>& u_full, const std::vector<int>& nodes, int c, double sign = 1);

} // namespace suite::fem
