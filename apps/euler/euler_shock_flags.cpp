// The ENO-Pade shock rows of a state as a per-cell field of the output (group/shock and its XDMF attribute),
// so a user sees where the CRWENO rows act: the sensor (lib/euler/enopade6.hpp) is evaluated on the written
// state itself, direction by direction on the same lines (ghosts included) as the right-hand side, so the field
// is what the next right-hand side evaluation at this state would flag, whatever the rank count. Value per
// cell: the sum of 2^d over the directions d in which one of the cell's two faces is a shock row (1D: 0 or 1;
// 2D: 0 .. 3; 3D: 0 .. 7); 0 everywhere means Pade rows only.
#include "euler_run.hpp"

#include "euler_state.hpp"

namespace euler_app {

using namespace suite::euler;

bool EulerRun::hasShockFlags() const {
  return scheme_ != nullptr && scheme_->hybrid;
}

template <int NV> void EulerRun::shockFlagsImpl(double t, const double* ul, std::vector<double>* flags) {
  std::vector<std::array<double, NV>> q;
  std::vector<char> faces;
  flags->assign((size_t)localCells(), 0.0);
  const size_t stride[3] = {1, (size_t)m_[0], (size_t)m_[0] * m_[1]};
  for (int d = 0; d < dim(); ++d) {
    int a, b;
    otherDirections(dim(), d, &a, &b);
    gatherLines<NV>(d, t, ul, &q);
    const int nlines = (int)(m_[a] * m_[b]), xm = (int)m_[d];
    faces.resize((size_t)nlines * (xm + 1));
    sweepOf<NV>().shockFaces(q.data(), nlines, opt_.n[d], s_[d], xm, periodic_[d], faces.data());
    size_t line = 0;
    for (PetscInt jb = 0; jb < m_[b]; ++jb)
      for (PetscInt ja = 0; ja < m_[a]; ++ja, ++line) {
        const char* fl = faces.data() + line * (xm + 1);
        const size_t base = ja * stride[a] + jb * (b < 3 ? stride[b] : 0);
        for (int i = 0; i < xm; ++i)
          if (fl[i] || fl[i + 1]) (*flags)[base + i * stride[d]] += (double)(1 << d);
      }
  }
}

PetscErrorCode EulerRun::shockFlags(Vec U, double t, std::vector<double>* flags) {
  Vec Ul;
  const PetscScalar* ul;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da_, &Ul));
  PetscCall(DMGlobalToLocal(da_, U, INSERT_VALUES, Ul));
  PetscCall(VecGetArrayRead(Ul, &ul));
  if (dim() == 1)
    shockFlagsImpl<3>(t, ul, flags);
  else if (dim() == 2)
    shockFlagsImpl<4>(t, ul, flags);
  else
    shockFlagsImpl<5>(t, ul, flags);
  PetscCall(VecRestoreArrayRead(Ul, &ul));
  PetscCall(DMRestoreLocalVector(da_, &Ul));
  PetscFunctionReturn(0);
}

} // namespace euler_app
