// Shell-binned energy spectrum E(k) of distributed 2D/3D fields: real-to-complex FFTs with FFTW-MPI after
// redistributing the caller's blocks (any block decomposition, e.g. a PETSc DMDA's) to FFTW's slabs.
// E(k) = sum over wavevectors with round(|k|) = k of (1/2) sum_c |u^_c(k)|^2, u^ = (1/N) sum_x u e^{-i k.x},
// k in integer (box) units, so that sum_k E(k) = (1/N) sum_x (1/2) sum_c u_c^2 (Parseval).
// Reference: the FFTW 3 manual, "Distributed-memory FFTW with MPI" (r2c layout, padding, local sizes).
#pragma once

#include <petscsys.h>

#include <vector>

namespace suite::fft {

// This rank's block of a global 2D (ny, nx) or 3D (nz, ny, nx) array stored row-major (last index fastest).
struct Block {
  std::vector<long long> dims, start, count;
};

// fields: this rank's block of each component (e.g. u, v, w, or sqrt(rho) u ...). E gets one entry per shell,
// k = 0 .. round(|k_max|). Collective on comm.
PetscErrorCode energySpectrum(MPI_Comm comm, const Block& block, const std::vector<const double*>& fields,
                              std::vector<double>* E);

} // namespace suite::fft
