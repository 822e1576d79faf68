// The Euler right-hand side for -dim 1|2|3 (see euler_run.hpp): per direction, the grid lines of this rank in
// the direction's frame with ghost cells from the neighbours or the boundary conditions, the face fluxes of
// DirectionSweep<NV>, their differences; then the gravity source. In 1D the one line spans every rank.
#include "euler_run.hpp"

#include "core/error_handler.hpp"
#include "euler/line_segments.hpp"
#include "euler_state.hpp"

#include <algorithm>
#include <exception>

namespace euler_app {

using namespace suite::euler;

// Ghost cells of line (ja, jb) of direction d outside a non-periodic domain, from the boundary conditions.
// ql holds cells s_d-3 .. s_d+m_d+2 of the line, in the frame of d.
template <int NV>
void EulerRun::fillBoundaryGhosts(int d, double t, PetscInt ja, PetscInt jb, std::array<double, NV>* ql) {
  const int g = kLineGhost;
  const PetscInt n = opt_.n[d];
  int a, b, comp[NV];
  otherDirections(dim(), d, &a, &b);
  for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim(), d, c);
  auto at = [&](PetscInt c) -> std::array<double, NV>& { return ql[c - (s_[d] - g)]; };
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 && s_[d] != 0) || (side == 1 && s_[d] + m_[d] != n)) continue;
    for (PetscInt gi = 0; gi < g; ++gi) {
      const PetscInt i = side == 0 ? -1 - gi : n + gi;     // ghost cell
      const PetscInt mirror = side == 0 ? gi : n - 1 - gi; // interior cell mirrored across the face
      const PetscInt edge = side == 0 ? 0 : n - 1;         // interior cell next to the face
      std::array<double, NV>& ghost = at(i);
      switch (problem_.bc[d][side]) {
      case BcN::Outflow:
        ghost = at(edge);
        break;
      case BcN::Reflecting:
        ghost = at(mirror);
        ghost[1] = -ghost[1];
        break;
      case BcN::Custom: {
        double x[3], qm[5], qe[5], qg[5];
        PetscInt idx[3] = {0, 0, 0};
        idx[a] = ja, idx[b] = jb, idx[d] = i;
        cellCentre(idx[0], idx[1], idx[2], x);
        for (int c = 0; c < NV; ++c) qm[comp[c]] = at(mirror)[c], qe[comp[c]] = at(edge)[c];
        const PrimN w = problem_.ghost(d, side, x, t, primitive(qm, dim(), problem_.gamma),
                                       primitive(qe, dim(), problem_.gamma));
        conservative(w, dim(), problem_.gamma, qg);
        for (int c = 0; c < NV; ++c) ghost[c] = qg[comp[c]];
        break;
      }
      case BcN::Periodic:
        break;
      }
    }
  }
}

// Fills q with the lines of direction d: cells s_d-3 .. s_d+m_d+2 of every (j, k) of this rank, in the frame of
// d, ghosts outside a non-periodic domain from the boundary conditions at time t.
template <int NV>
void EulerRun::gatherLines(int d, double t, const double* ul, std::vector<std::array<double, NV>>* q) {
  const int g = kLineGhost;
  int a, b, comp[NV];
  otherDirections(dim(), d, &a, &b);
  const PetscInt ncell = m_[d] + 2 * g, n = opt_.n[d];
  q->resize((size_t)(m_[a] * m_[b]) * ncell);
  for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim(), d, c);
  auto local = [&](const PetscInt idx[3]) {
    const PetscInt off = ((idx[2] - gs_[2]) * gm_[1] + (idx[1] - gs_[1])) * gm_[0] + (idx[0] - gs_[0]);
    return ul + (size_t)off * NV;
  };
  PetscInt line = 0;
  for (PetscInt jb = s_[b]; jb < s_[b] + m_[b]; ++jb)
    for (PetscInt ja = s_[a]; ja < s_[a] + m_[a]; ++ja, ++line) {
      std::array<double, NV>* ql = q->data() + (size_t)line * ncell;
      PetscInt idx[3];
      idx[a] = ja, idx[b] = jb;
      for (PetscInt m = 0; m < ncell; ++m) {
        const PetscInt i = s_[d] - g + m;
        if (!periodic_[d] && (i < 0 || i >= n)) continue;
        idx[d] = i;
        const double* src = local(idx);
        for (int c = 0; c < NV; ++c) ql[m][c] = src[comp[c]];
        if (!solid_local_.empty() && solid_local_[(src - ul) / NV]) ql[m][0] = kSolidSentinel;
      }
      if (!periodic_[d]) fillBoundaryGhosts<NV>(d, t, ja, jb, ql);
    }
}

// f -= the flux differences of direction d (1D: f = -(h_{k+1} - h_k) / dx, the line's own arithmetic).
template <int NV>
void EulerRun::addFluxDifferences(int d, const std::vector<std::array<double, NV>>& h, double* f) const {
  int a, b, comp[NV];
  otherDirections(dim(), d, &a, &b);
  for (int c = 0; c < NV; ++c) comp[c] = frameComponent(dim(), d, c);
  const int xm = (int)m_[d];
  if (dim() == 1) {
    for (int i = 0; i < xm; ++i)
      for (int c = 0; c < NV; ++c) f[i * NV + c] = -(h[i + 1][c] - h[i][c]) / dx_[0];
    return;
  }
  const double inv = 1.0 / dx_[d];
  const size_t stride[3] = {1, (size_t)m_[0], (size_t)m_[0] * m_[1]};
  size_t line = 0;
  for (PetscInt jb = 0; jb < m_[b]; ++jb)
    for (PetscInt ja = 0; ja < m_[a]; ++ja, ++line) {
      const std::array<double, NV>* hl = h.data() + line * (xm + 1);
      const size_t base = ja * stride[a] + jb * (b < 3 ? stride[b] : 0);
      for (int i = 0; i < xm; ++i) {
        double* fc = f + (base + i * stride[d]) * NV;
        for (int c = 0; c < NV; ++c) fc[comp[c]] -= (hl[i + 1][c] - hl[i][c]) * inv;
      }
    }
}

void EulerRun::addGravity(const double* ul, double* f) const {
  const double* grav = problem_.gravity;
  if (grav[0] == 0.0 && grav[1] == 0.0 && grav[2] == 0.0) return;
  const int nv = this->nv();
  size_t c = 0;
  for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
    for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
      for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i, ++c) {
        const PetscInt off = ((k - gs_[2]) * gm_[1] + (j - gs_[1])) * gm_[0] + (i - gs_[0]);
        const double* qc = ul + (size_t)off * nv;
        for (int d = 0; d < dim(); ++d) {
          f[c * nv + 1 + d] += qc[0] * grav[d];
          f[c * nv + nv - 1] += qc[1 + d] * grav[d];
        }
      }
}

// amax[d] = max |u_d| + c over the cells this rank owns; false when one of them has a density or pressure that is
// not > 0 (or not finite).
template <int NV> bool EulerRun::stageSpeeds(const double* ul, double amax[3], double* flux_scale) const {
  bool ok = true;
  for (PetscInt k = s_[2]; k < s_[2] + m_[2]; ++k)
    for (PetscInt j = s_[1]; j < s_[1] + m_[1]; ++j)
      for (PetscInt i = s_[0]; i < s_[0] + m_[0]; ++i) {
        const PetscInt off = ((k - gs_[2]) * gm_[1] + (j - gs_[1])) * gm_[0] + (i - gs_[0]);
        if (!solid_local_.empty() && solid_local_[off]) continue;
        const double* q = ul + (size_t)off * NV;
        double s[3];
        waveSpeeds(q, dim(), problem_.gamma, s);
        for (int d = 0; d < dim(); ++d) amax[d] = std::max(amax[d], s[d]);
        const PrimN w = primitive(q, dim(), problem_.gamma);
        ok = ok && q[0] > 0.0 && w.p > 0.0;
        double momentum_flux = w.p; // p + rho |u|^2
        for (int d = 0; d < dim(); ++d) momentum_flux += q[1 + d] * w.u[d];
        *flux_scale = std::max(*flux_scale, momentum_flux);
      }
  return ok;
}

long long EulerRun::unattainableFaces() const {
  return dim() == 1   ? sweep3_->stats().unattainable_faces
         : dim() == 2 ? sweep4_->stats().unattainable_faces
                      : sweep5_->stats().unattainable_faces;
}

template <int NV> PetscErrorCode EulerRun::rhsImpl(double t, const double* ul, double* f) {
  using V = std::array<double, NV>;
  DirectionSweep<NV>& sweep = sweepOf<NV>();
  PetscFunctionBeginUser;
  // Max |u_d| + c over the stage state per direction, speeds[3] = 1 where an explicit stage state has a cell
  // that is not admissible, and speeds[4] the largest momentum flux p + rho |u|^2 (the flux scale of
  // characteristic_conditioning.hpp), in one Allreduce. A rejected stage is retried (euler_step.cpp) and no flux
  // is computed.
  double speeds[5] = {0, 0, 0, 0, 0};
  if (!stageSpeeds<NV>(ul, speeds, &speeds[4]) && !opt_.implicit) speeds[3] = 1.0;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, speeds, 5, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  const double* amax = speeds;
  if (speeds[3] > 0.0) {
    stage_rejected_ = true;
    std::fill(f, f + (size_t)localCells() * NV, 0.0);
    PetscFunctionReturn(0);
  }
  // The positivity limiter's scaled dt/dx per direction (direction_sweep.hpp): 1D dt/dx; 2D/3D
  // dt sum_e(amax_e/dx_e) / amax_d, the weights w_d = (dt amax_d/dx_d) / sum_e(dt amax_e/dx_e) of the split.
  double cfl_rate = 0.0;
  for (int d = 0; d < dim(); ++d) cfl_rate += amax[d] / dx_[d];
  std::fill(f, f + (size_t)localCells() * NV, 0.0);
  std::vector<V> q, h;
  for (int d = 0; d < dim(); ++d) {
    if (dim() > 1) PetscCall(PetscLogStagePush(stage_lines_[d]));
    gatherLines<NV>(d, t, ul, &q);
    int a, b;
    otherDirections(dim(), d, &a, &b);
    const int nlines = (int)(m_[a] * m_[b]), xm = (int)m_[d];
    h.resize((size_t)nlines * (xm + 1));
    double lambda = 0.0;
    if (opt_.positivity) lambda = dim() == 1 ? dt_limiter_ / dx_[0] : dt_limiter_ * cfl_rate / amax[d];
    try {
      sweep.faceFluxes(dim() == 1 ? ctx_.comm() : line_comm_[d], q.data(), nlines, opt_.n[d], s_[d], xm,
                       periodic_[d], amax[d] * (1.0 + 1e-12), lambda, speeds[4], h.data());
      addFluxDifferences<NV>(d, h, f);
    } catch (const std::exception& e) {
      // Reduced over the whole grid by rhs(). The other directions still run: their line communicators hold
      // ranks that did not fail here and wait for this rank in their collectives.
      if (rhs_failure_.empty()) rhs_failure_ = e.what();
    }
    if (dim() > 1) PetscCall(PetscLogStagePop());
  }
  addGravity(ul, f);
  zeroSolidCells(f);
  PetscFunctionReturn(0);
}

// The line layout is also the shock flags' (euler_shock_flags.cpp).
template void EulerRun::gatherLines<3>(int, double, const double*, std::vector<std::array<double, 3>>*);
template void EulerRun::gatherLines<4>(int, double, const double*, std::vector<std::array<double, 4>>*);
template void EulerRun::gatherLines<5>(int, double, const double*, std::vector<std::array<double, 5>>*);

PetscErrorCode EulerRun::rhs(double t, Vec U, Vec F) {
  Vec Ul;
  const PetscScalar* ul;
  PetscScalar* f;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da_, &Ul));
  PetscCall(DMGlobalToLocal(da_, U, INSERT_VALUES, Ul));
  PetscCall(VecGetArrayRead(Ul, &ul));
  PetscCall(VecGetArray(F, &f));
  rhs_failure_.clear();
  stage_rejected_ = false;
  PetscCall(dim() == 1 ? rhsImpl<3>(t, ul, f) : dim() == 2 ? rhsImpl<4>(t, ul, f) : rhsImpl<5>(t, ul, f));
  // A non-admissible stage state (the same decision on every rank): its first bad cell names the retry.
  if (stage_rejected_ && stage_failure_.empty()) {
    PetscCall(findInvalidState(U, step_ + 1, t, &stage_failure_));
    stage_failure_ = "a stage state: " + stage_failure_;
  }
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(VecRestoreArrayRead(Ul, &ul));
  PetscCall(DMRestoreLocalVector(da_, &Ul));
  // A line-solve failure is the same on the ranks of a line but not of the grid: agree before returning.
  PetscCall(suite::agreeOnFailure(ctx_.comm(), &rhs_failure_));
  PetscCheck(rhs_failure_.empty(), ctx_.comm(), PETSC_ERR_NOT_CONVERGED,
             "Euler right-hand side failed at step %" PetscInt_FMT ", t = %g (a compact line solve: %s)",
             step_, t, rhs_failure_.c_str());
  PetscFunctionReturn(0);
}

} // namespace euler_app
