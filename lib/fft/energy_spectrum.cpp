// Shell-binned energy spectrum with FFTW-MPI (see energy_spectrum.hpp).
#include "fft/energy_spectrum.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cmath>

namespace suite::fft {
namespace {

// Global layout as 3D (a 2D array is one z-plane), this rank's block and every rank's FFTW slab.
struct Layout {
  long long n[3];
  std::vector<long long> blocks; // 6 per rank: start z, y, x, count z, y, x
  std::vector<long long> slabs;  // 2 per rank: first index and count of the distributed dimension
  int rnk;                       // 2 or 3
};

// Slab of FFTW's distributed (first) dimension; for 2D data FFTW distributes y, which is our dim 1.
inline int distDim(const Layout& L) {
  return L.rnk == 3 ? 0 : 1;
}

// Visits the intersection of rank p's block with rank q's slab in row-major order: f(z, y, x).
template <typename F> long long forIntersection(const Layout& L, int p, int q, F f) {
  const long long* b = &L.blocks[6 * (size_t)p];
  long long lo[3] = {b[0], b[1], b[2]}, hi[3] = {b[0] + b[3], b[1] + b[4], b[2] + b[5]};
  const int d = distDim(L);
  lo[d] = std::max(lo[d], L.slabs[2 * (size_t)q]);
  hi[d] = std::min(hi[d], L.slabs[2 * (size_t)q] + L.slabs[2 * (size_t)q + 1]);
  long long count = 0;
  for (long long z = lo[0]; z < hi[0]; ++z)
    for (long long y = lo[1]; y < hi[1]; ++y)
      for (long long x = lo[2]; x < hi[2]; ++x, ++count) f(z, y, x);
  return count;
}

PetscErrorCode makeLayout(MPI_Comm comm, const Block& blk, ptrdiff_t local_n0, ptrdiff_t local_0_start,
                          Layout* L) {
  PetscFunctionBeginUser;
  int P;
  PetscCallMPI(MPI_Comm_size(comm, &P));
  L->rnk = (int)blk.dims.size();
  const int off = 3 - L->rnk;
  long long mine[6] = {0, 0, 0, 1, 1, 1};
  L->n[0] = 1;
  for (int i = 0; i < L->rnk; ++i) {
    L->n[i + off] = blk.dims[i];
    mine[i + off] = blk.start[i];
    mine[3 + i + off] = blk.count[i];
  }
  L->blocks.resize(6 * (size_t)P);
  PetscCallMPI(MPI_Allgather(mine, 6, MPI_LONG_LONG, L->blocks.data(), 6, MPI_LONG_LONG, comm));
  long long slab[2] = {(long long)local_0_start, (long long)local_n0};
  L->slabs.resize(2 * (size_t)P);
  PetscCallMPI(MPI_Allgather(slab, 2, MPI_LONG_LONG, L->slabs.data(), 2, MPI_LONG_LONG, comm));
  PetscFunctionReturn(0);
}

// Moves one component from the caller's blocks into FFTW's padded slab array (last dimension 2 (nx/2 + 1)).
PetscErrorCode redistribute(MPI_Comm comm, const Layout& L, const double* local, double* slab) {
  PetscFunctionBeginUser;
  int P, me;
  PetscCallMPI(MPI_Comm_size(comm, &P));
  PetscCallMPI(MPI_Comm_rank(comm, &me));
  const long long* b = &L.blocks[6 * (size_t)me];
  std::vector<int> scount(P), sdispl(P), rcount(P), rdispl(P);
  std::vector<double> sendbuf, recvbuf;
  for (int q = 0; q < P; ++q) {
    sdispl[q] = (int)sendbuf.size();
    scount[q] = (int)forIntersection(L, me, q, [&](long long z, long long y, long long x) {
      sendbuf.push_back(local[((z - b[0]) * b[4] + (y - b[1])) * b[5] + (x - b[2])]);
    });
  }
  int total = 0;
  for (int p = 0; p < P; ++p) {
    rdispl[p] = total;
    rcount[p] = (int)forIntersection(L, p, me, [](long long, long long, long long) {});
    total += rcount[p];
  }
  recvbuf.resize(total);
  PetscCallMPI(MPI_Alltoallv(sendbuf.data(), scount.data(), sdispl.data(), MPI_DOUBLE, recvbuf.data(),
                             rcount.data(), rdispl.data(), MPI_DOUBLE, comm));
  const long long nxp = 2 * (L.n[2] / 2 + 1), s0 = L.slabs[2 * (size_t)me];
  const int d = distDim(L);
  size_t k = 0;
  for (int p = 0; p < P; ++p)
    forIntersection(L, p, me, [&](long long z, long long y, long long x) {
      const long long zz = d == 0 ? z - s0 : z, yy = d == 1 ? y - s0 : y;
      slab[(zz * (d == 0 ? L.n[1] : L.slabs[2 * (size_t)me + 1]) + yy) * nxp + x] = recvbuf[k++];
    });
  PetscFunctionReturn(0);
}

inline long long signedK(long long j, long long n) {
  return j <= n / 2 ? j : j - n;
}

} // namespace

PetscErrorCode energySpectrum(MPI_Comm comm, const Block& block, const std::vector<const double*>& fields,
                              std::vector<double>* E) {
  PetscFunctionBeginUser;
  const int rnk = (int)block.dims.size();
  PetscCheck(rnk == 2 || rnk == 3, comm, PETSC_ERR_ARG_SIZ, "energy spectrum: 2D or 3D data only (got %dD)",
             rnk);
  static bool fftw_mpi_ready = false;
  if (!fftw_mpi_ready) fftw_mpi_init(), fftw_mpi_ready = true;
  std::vector<ptrdiff_t> n(block.dims.begin(), block.dims.end()), nc = n;
  nc.back() = n.back() / 2 + 1;
  ptrdiff_t local_n0, local_0_start;
  const ptrdiff_t alloc = fftw_mpi_local_size(rnk, nc.data(), comm, &local_n0, &local_0_start);
  Layout L;
  PetscCall(makeLayout(comm, block, local_n0, local_0_start, &L));
  double* data = fftw_alloc_real(2 * std::max<ptrdiff_t>(alloc, 1));
  fftw_complex* spec = reinterpret_cast<fftw_complex*>(data);
  fftw_plan plan = fftw_mpi_plan_dft_r2c(rnk, n.data(), data, spec, comm, FFTW_ESTIMATE);
  const double N = (double)L.n[0] * L.n[1] * L.n[2];
  double kmax2 = 0.0;
  for (int i = 0; i < 3; ++i) kmax2 += (double)(L.n[i] / 2) * (L.n[i] / 2);
  std::vector<double> local((size_t)std::llround(std::sqrt(kmax2)) + 1, 0.0);
  // Local complex block: (local_n0, n1, nx/2+1) in 3D, (local_n0, nx/2+1) in 2D.
  const long long nzl = rnk == 3 ? local_n0 : 1, nyl = rnk == 3 ? L.n[1] : local_n0, nxc = L.n[2] / 2 + 1;
  for (const double* f : fields) {
    std::fill(data, data + 2 * std::max<ptrdiff_t>(alloc, 1), 0.0);
    PetscCall(redistribute(comm, L, f, data));
    fftw_execute(plan);
    for (long long z = 0; z < nzl; ++z)
      for (long long y = 0; y < nyl; ++y)
        for (long long x = 0; x < nxc; ++x) {
          const long long kz = rnk == 3 ? signedK(z + local_0_start, L.n[0]) : 0;
          const long long ky = signedK(rnk == 3 ? y : y + local_0_start, L.n[1]);
          const double k = std::sqrt((double)(kz * kz + ky * ky + x * x));
          const fftw_complex& c = spec[(z * nyl + y) * nxc + x];
          // r2c stores half the spectrum: every x other than 0 and the Nyquist column stands for two modes.
          const double weight = (x == 0 || (L.n[2] % 2 == 0 && x == L.n[2] / 2)) ? 1.0 : 2.0;
          local[(size_t)std::llround(k)] += weight * 0.5 * (c[0] * c[0] + c[1] * c[1]) / (N * N);
        }
  }
  fftw_destroy_plan(plan);
  fftw_free(data);
  E->assign(local.size(), 0.0);
  PetscCallMPI(MPI_Allreduce(local.data(), E->data(), (int)local.size(), MPI_DOUBLE, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

} // namespace suite::fft
