// -filter_alpha: the sixth-order compact filter of Gaikwad & Visbal (lib/euler/compact_filter.hpp) applied to
// the conserved state after every step, direction by direction (x, then y, then z, each on the state the
// previous direction left, with fresh ghost cells), default off. It is used in its conservative face form (one
// row per face, the header's g_{k+1/2}), so a closed domain keeps mass and energy to round-off. Faces whose
// stencil leaves a non-periodic domain or holds a density/pressure jump (Jameson phi above -shock_threshold)
// carry no filter flux. Each direction is one batched distributed tridiagonal solve of all its lines with NV
// right-hand sides (linalg::SubstructuredBlockLines::solveScalar, the partition method: exact up to round-off,
// so a filtered run differs between rank counts by round-off, not bitwise).
// Applied in full after every step (the usual practice), its O(dx^6) error per application adds up over the
// steps: O(steps dx^6), i.e. O(dx^5) at CFL steps and O(dx^4.5) with the orders test's dt ~ dx^1.5. With
// -filter_time tau > 0 the step blends the filtered state in with weight theta = min(1, dt / tau), a relaxation
// dU/dt = -(U - F U) / tau at a rate independent of the grid: the filter's error stays O(t dx^6 / tau) whatever
// dt, so the Pade core keeps its sixth order, and the 2-dx mode (T(pi) = 0) still decays like exp(-t / tau).
// It removes the 2-dx noise of the Pade rows (scripts/bench/euler-checkerboard,
// docs/euler_nd.md).
#include "euler_run.hpp"

#include "euler/compact_filter.hpp"
#include "euler_state.hpp"

#include <algorithm>

namespace euler_app {

using namespace suite::euler;

bool EulerRun::filterOn() const {
  return opt_.filter_alpha < 0.5;
}

// Filters direction d of U in place.
template <int NV> PetscErrorCode EulerRun::filterDirection(int d, double t, Vec U) {
  Vec Ul;
  const PetscScalar* ul;
  PetscScalar* u;
  std::vector<std::array<double, NV>> q;
  int a, b, comp[NV];
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da_, &Ul));
  PetscCall(DMGlobalToLocal(da_, U, INSERT_VALUES, Ul));
  PetscCall(VecGetArrayRead(Ul, &ul));
  gatherLines<NV>(d, t, ul, &q);
  PetscCall(VecRestoreArrayRead(Ul, &ul));
  PetscCall(DMRestoreLocalVector(da_, &Ul));
  otherDirections(dim(), d, &a, &b);
  for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim(), d, c);
  // Face rows: faces s_d .. s_d + m_d - 1 of each line, and face n of a non-periodic line on its last rank.
  const int nlines = (int)(m_[a] * m_[b]), xm = (int)m_[d], ncell = xm + 2 * kLineGhost;
  const int nface = xm + (!periodic_[d] && s_[d] + xm == opt_.n[d] ? 1 : 0);
  filter_abc_.resize((size_t)3 * nface * nlines);
  filter_rhs_.resize((size_t)NV * nface * nlines);
  filter_x_.resize((size_t)NV * (xm + 1) * nlines);
  for (int l = 0; l < nlines; ++l)
    compactFilterFaceRows<NV>(q.data() + (size_t)l * ncell, opt_.n[d], s_[d], nface, periodic_[d],
                              opt_.filter_alpha, problem_.gamma, opt_.shock_threshold,
                              &filter_abc_[(size_t)3 * nface * l], &filter_rhs_[(size_t)NV * nface * l]);
  try { // every rank gets faces s_d .. s_d + m_d of its lines (count xm + 1)
    filter_lines_.solveScalar(dim() == 1 ? ctx_.comm() : line_comm_[d], nlines, nface, filter_abc_.data(), NV,
                              filter_rhs_.data(), periodic_[d], s_[d], xm + 1, filter_x_.data());
  } catch (
      const std::exception& e) { // the same on every rank of the line; the filter's rows cannot be singular
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "compact filter: %s", e.what());
  }
  std::vector<std::array<double, NV>> cells(xm);
  const size_t stride[3] = {1, (size_t)m_[0], (size_t)m_[0] * m_[1]};
  PetscCall(VecGetArray(U, &u));
  for (PetscInt jb = 0, l = 0; jb < m_[b]; ++jb)
    for (PetscInt ja = 0; ja < m_[a]; ++ja, ++l) {
      compactFilterApply<NV>(q.data() + (size_t)l * ncell, xm, &filter_x_[(size_t)l * (xm + 1) * NV],
                             cells.data());
      for (int i = 0; i < xm; ++i) {
        const size_t cell = ja * stride[a] + jb * (b < 3 ? stride[b] : 0) + i * stride[d];
        for (int c = 0; c < NV; ++c) u[cell * NV + comp[c]] = cells[i][c];
      }
    }
  PetscCall(VecRestoreArray(U, &u));
  PetscFunctionReturn(0);
}

// U <- U + theta (F U - U), theta = min(1, dt / -filter_time) (1 without -filter_time): F U is the state
// filtered in every direction.
PetscErrorCode EulerRun::applyFilter(double t, double dt, Vec U) {
  PetscFunctionBeginUser;
  if (!filterOn()) PetscFunctionReturn(0);
  const double theta = opt_.filter_time > 0.0 ? std::min(1.0, dt / opt_.filter_time) : 1.0;
  Vec F = U;
  if (theta < 1.0) {
    if (!Ufilter_) PetscCall(VecDuplicate(U, &Ufilter_));
    PetscCall(VecCopy(U, Ufilter_));
    F = Ufilter_;
  }
  for (int d = 0; d < dim(); ++d)
    PetscCall(dim() == 1   ? filterDirection<3>(d, t, F)
              : dim() == 2 ? filterDirection<4>(d, t, F)
                           : filterDirection<5>(d, t, F));
  if (theta < 1.0) PetscCall(VecAXPBY(U, theta, 1.0 - theta, F));
  PetscFunctionReturn(0);
}

} // namespace euler_app
