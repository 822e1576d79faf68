// 2D/3D -spectrum: the kinetic-energy spectrum E(k) of sqrt(rho) u (so that sum_k E(k) is the mean kinetic
// energy) in box wavenumbers, computed with FFTW-MPI on the run's blocks, into group/k and group/E.
#include "euler_run.hpp"

#include "core/log.hpp"
#include "fft/energy_spectrum.hpp"

#include <cmath>

namespace euler_app {

PetscErrorCode EulerRun::writeSpectrum(const std::string& group) {
  std::vector<double> fields[5], comp[3], E;
  std::vector<const double*> ptrs;
  suite::fft::Block block;
  suite::Dims dims, start, count;
  PetscFunctionBeginUser;
  PetscCall(primitiveFields(U_, fields));
  for (int d = 0; d < dim(); ++d) {
    comp[d].resize(fields[0].size());
    for (size_t c = 0; c < fields[0].size(); ++c) comp[d][c] = std::sqrt(fields[0][c]) * fields[1 + d][c];
    ptrs.push_back(comp[d].data());
  }
  blockDims(&dims, &start, &count);
  for (size_t e = 0; e < dims.size(); ++e) {
    block.dims.push_back((long long)dims[e]);
    block.start.push_back((long long)start[e]);
    block.count.push_back((long long)count[e]);
  }
  PetscCall(suite::fft::energySpectrum(ctx_.comm(), block, ptrs, &E));
  std::vector<double> k(E.size());
  double total = 0.0;
  for (size_t i = 0; i < E.size(); ++i) k[i] = (double)i, total += E[i];
  PetscCall(out_.writeReplicated(group + "/k", k.data(), {(unsigned long long)k.size()}, ""));
  PetscCall(out_.writeReplicated(group + "/E", E.data(), {(unsigned long long)E.size()}, ""));
  PetscCall(out_.writeAttribute(group, "field", "sqrt(rho) u"));
  PetscCall(out_.writeAttribute(group, "sum_E", total));
  PetscCall(suite::logInfo(ctx_.comm(), quiet(), "spectrum %s: %zu shells, sum E(k) = %.12e", group.c_str(),
                           E.size(), total));
  PetscFunctionReturn(0);
}

} // namespace euler_app
