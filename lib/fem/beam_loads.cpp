// Beam loads (see beam_loads.hpp): the end face is the plane x = max over the nodes; the tip traction is
// -P / area along y on its boundary faces (ElasticModel::tractionLoad), gravity rho g
// (ElasticModel::bodyForce).
#include "fem/beam_loads.hpp"

#include <algorithm>

namespace suite::fem {

namespace {
double endPlane(const TetMesh& mesh) {
  double xmax = -1e300;
  for (const auto& x : mesh.nodes) xmax = std::max(xmax, x[0]);
  return xmax;
}
} // namespace

std::vector<int> tipNodes(const TetMesh& mesh) {
  return nodesOnPlane(mesh, 0, endPlane(mesh));
}

PetscErrorCode tipTractionLoad(MPI_Comm comm, const ElasticModel& model, double P, std::vector<double>* f) {
  PetscFunctionBeginUser;
  f->assign(model.numFree(), 0.0);
  if (P == 0) PetscFunctionReturn(0);
  const double xmax = endPlane(model.mesh());
  const auto faces = facesOnPlane(model.mesh(), 0, xmax);
  const double area = facesArea(model.mesh(), faces);
  PetscCheck(area > 0, comm, PETSC_ERR_ARG_WRONG, "-tip_load: no boundary face on the end plane x = %g",
             xmax);
  *f = model.tractionLoad(faces, {0.0, -P / area, 0.0});
  PetscFunctionReturn(0);
}

void addGravityLoad(const ElasticModel& model, double rho, const double g[3], std::vector<double>* f) {
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) return;
  const auto b = model.bodyForce({rho * g[0], rho * g[1], rho * g[2]});
  for (size_t i = 0; i < b.size(); ++i) (*f)[i] += b[i];
}

double nodalMean(const std::vector<double>& u_full, const std::vector<int>& nodes, int c, double sign) {
  double s = 0;
  for (int v : nodes) s += sign * u_full[3 * v + c];
  return s / std::max<size_t>(1, nodes.size());
}

} // namespace suite::fem
