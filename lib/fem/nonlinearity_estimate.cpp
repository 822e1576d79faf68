// Geometric-nonlinearity estimate (see nonlinearity_estimate.hpp): H = sum_a u_a (x) dN_a/dX at every
// quadrature point of the stiffness rule, ||1/2 H^T H||_F^2 and ||H||_F^2 integrated with the rule's weights.
//
// Why eta: for a rigid rotation by theta about z, H = R - I has ||H||_F^2 = 4 (1 - cos theta) and 1/2 H^T H =
// (1 - cos theta) I on the rotation plane, so eta = sin(theta / 2) exactly (tests/unit/fem) wherever rotation
// dominates the gradient (bending of slender bodies); for a uniaxial stretch e, eta = e / 2. Either way eta is the size of the neglected quadratic kinematics relative to the kept linear
// part, and the linear law's displacement error along the load is second order in it (the displacement is odd
// in the load, the error of linearised rotations is O(theta^2)).
//
// Calibration (measured with femdyn: cantilever L = 10, 1 x 1, E = 1000, nu = 0.3, rho = 1, a step tip load P
// from t = 0, Newmark dt = 0.2, 100 steps (one period); err = max_t |tip_lin(t) - tip_stvk(t)| /
// max_t |tip_stvk(t)| (tip: mean -u_y of the end face), eta_max = max_t eta(u_lin(t))):
//
//   -beam_cells 20,2,2:  P      1e-3     1e-2     0.1      0.3      0.5      1        2
//                        eta    2.54e-4  2.54e-3  0.0254   0.0761   0.127    0.254    0.507
//                        err    1.63e-5  1.71e-4  2.54e-3  0.0135   0.0319   0.109    0.356
//   -beam_cells 20,8,8:  P = 0.01: eta 3.73e-3, err 5.86e-5;  P = 1: eta 0.373, err 0.207
//
// Small loads show a first-order term (err/eta -> 0.064 on 20,2,2, 0.016 on 20,8,8: the tetrahedral split of
// the hexahedra is not symmetric in y, so u_y has an even part in P), large ones the second-order term
// (err/eta^2 -> 1.4). linearLawError = 0.07 eta + 1.5 eta^2 bounds every case above from above (by 2% at
// P = 0.5 on 20,2,2, by 7% at P = 1 on 20,8,8).
#include "fem/nonlinearity_estimate.hpp"

#include <cmath>

namespace suite::fem {

namespace {
// ||1/2 H^T H||_F^2 and ||H||_F^2 of H (row i = component, column J = material direction).
void accumulate(const Mat3& H, double w, NonlinearityEstimate* est) {
  const Mat3 Q = 0.5 * H.transpose() * H;
  est->quadratic2 += w * Q.squaredNorm();
  est->linear2 += w * H.squaredNorm();
}
} // namespace

double NonlinearityEstimate::ratio() const {
  return linear2 > 0 ? std::sqrt(quadratic2 / linear2) : 0.0;
}

PetscErrorCode estimateNonlinearity(MPI_Comm comm, const ElasticModel& model, const double* u_full,
                                    NonlinearityEstimate* est) {
  const TetMesh& mesh = model.mesh();
  const ElementGeometry& geo = model.geometry();
  const int nen = geo.nen, nq = geo.nq, ne = mesh.numElems();
  PetscFunctionBeginUser;
  *est = NonlinearityEstimate();
  for (int e = 0; e < ne; ++e) {
    if (!model.ownsElement(e)) continue;
    const int* t = mesh.elem(e);
    for (int q = 0; q < nq; ++q) {
      const double* g = geo.grad(e, q);
      Mat3 H = Mat3::Zero();
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < 3; ++i)
          for (int J = 0; J < 3; ++J) H(i, J) += u_full[3 * t[a] + i] * g[3 * a + J];
      accumulate(H, geo.weight(e, q), est);
    }
  }
  if (model.partial()) {
    double s[2] = {est->quadratic2, est->linear2};
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 2, MPI_DOUBLE, MPI_SUM, comm));
    est->quadratic2 = s[0], est->linear2 = s[1];
  }
  PetscFunctionReturn(0);
}

const double kLinearErrorPerRatio = 0.07, kLinearErrorPerRatio2 = 1.5;

double linearLawError(double ratio) {
  return kLinearErrorPerRatio * ratio + kLinearErrorPerRatio2 * ratio * ratio;
}

} // namespace suite::fem
