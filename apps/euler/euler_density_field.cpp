// The final density of an Euler run on the whole grid, on every rank (for the accuracy-target driver's
// comparisons of runs at different resolutions): each rank's block gathered to all ranks and placed in
// natural (x fastest) order, so that the result does not depend on the rank count. The solve's cost: its CPU time,
// the maximum over the ranks (on a dedicated node the wall time; unlike that, robust on a shared one).
#include "euler_run.hpp"

namespace euler_app {

PetscErrorCode EulerRun::densityField(suite::model_choice::GridField* g) const {
  std::vector<double> fields[5];
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  PetscCallMPI(MPI_Comm_size(ctx_.comm(), &size));
  int block[6] = {(int)s_[0], (int)s_[1], (int)s_[2], (int)m_[0], (int)m_[1], (int)m_[2]};
  std::vector<int> blocks(6 * (size_t)size), counts((size_t)size), displs((size_t)size);
  PetscCallMPI(MPI_Allgather(block, 6, MPI_INT, blocks.data(), 6, MPI_INT, ctx_.comm()));
  int total = 0;
  for (int r = 0; r < size; ++r) {
    counts[r] = blocks[6 * r + 3] * blocks[6 * r + 4] * blocks[6 * r + 5];
    displs[r] = total, total += counts[r];
  }
  std::vector<double> all((size_t)total);
  PetscCallMPI(MPI_Allgatherv(fields[0].data(), (int)localCells(), MPI_DOUBLE, all.data(), counts.data(),
                              displs.data(), MPI_DOUBLE, ctx_.comm()));
  g->dim = dim();
  for (int d = 0; d < 3; ++d) g->n[d] = opt_.n[d], g->lo[d] = problem_.lo[d], g->hi[d] = problem_.hi[d];
  g->values.assign((size_t)total, 0.0);
  for (int r = 0; r < size; ++r) {
    const int* b = &blocks[6 * r];
    size_t c = (size_t)displs[r];
    for (int k = b[2]; k < b[2] + b[5]; ++k)
      for (int j = b[1]; j < b[1] + b[4]; ++j)
        for (int i = b[0]; i < b[0] + b[3]; ++i, ++c)
          g->values[(size_t)(i + g->n[0] * (j + g->n[1] * k))] = all[c];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EulerRun::solveSeconds(double* seconds, bool after_first_step) const {
  PetscFunctionBeginUser;
  *seconds = cpu_solve_ - (after_first_step ? cpu_first_step_ : 0.0);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, seconds, 1, MPI_DOUBLE, MPI_MAX, ctx_.comm()));
  PetscFunctionReturn(0);
}

} // namespace euler_app
