// Inviscid Taylor-Green vortex (`taylor_green`, 3D only) on [0, 2 pi]^3, periodic, gamma = 1.4:
//   rho = 1, u = sin x cos y cos z, v = -cos x sin y cos z, w = 0,
//   p = p0 + (cos 2x + cos 2y)(cos 2z + 2) / 16,  p0 = 1 / (gamma M^2)  (Mach M = 0.1 by default, -mach),
// i.e. the incompressible Taylor-Green pressure on a constant density (reference velocity, length and density
// 1, so p0 = 71.43). The flow transfers energy to small scales (vortex stretching); t = 10, 64^3 by default.
// No exact solution (compare kinetic energy, enstrophy and spectra across resolutions). References: Taylor &
// Green, Proc. R. Soc. Lond. A 158 (1937) 499; Brachet et al., J. Fluid Mech. 130 (1983) 411 (inviscid TGV);
// DeBonis, AIAA 2013-0382 (compressible Mach 0.1 setup).
#include "core/option_value.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>

namespace suite::euler {

PetscErrorCode createTaylorGreenProblemND(MPI_Comm comm, const std::string&, int dim, int, ProblemND* pr) {
  PetscFunctionBeginUser;
  PetscCheck(dim == 3, comm, PETSC_ERR_ARG_INCOMP,
             "Problem taylor_green is three-dimensional: run it with -dim 3 (got -dim %d)", dim);
  double mach = 0.1, gamma = 1.4;
  PetscOptionsBegin(comm, "", "Taylor-Green vortex options", "");
  PetscCall(suite::optionsReal(PetscOptionsObject, "-mach",
                               "Reference Mach number (velocity 1 over the sound speed at p0)", "", mach,
                               &mach, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma", "Ratio of specific heats", "", gamma, &gamma,
                               nullptr));
  PetscOptionsEnd();
  PetscCall(checkGamma(comm, gamma));
  const double p0 = 1.0 / (gamma * mach * mach);
  PetscCheck(mach > 0.0 && p0 - 0.375 > 0.0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -mach %g: must be > 0 with p0 = 1 / (gamma M^2) > 3/8 (the largest pressure dip), i.e. "
             "M < %.4g",
             mach, std::sqrt(1.0 / (0.375 * gamma)));
  pr->gamma = gamma;
  pr->t_final = 10.0;
  for (int d = 0; d < 3; ++d) {
    pr->lo[d] = 0.0;
    pr->hi[d] = 2.0 * M_PI;
    pr->bc[d][0] = pr->bc[d][1] = BcN::Periodic;
    pr->default_n[d] = 64;
  }
  pr->initial = [p0](const double* x) {
    const double sx = std::sin(x[0]), cx = std::cos(x[0]), sy = std::sin(x[1]), cy = std::cos(x[1]);
    const double cz = std::cos(x[2]);
    const double p = p0 + (std::cos(2.0 * x[0]) + std::cos(2.0 * x[1])) * (std::cos(2.0 * x[2]) + 2.0) / 16.0;
    return PrimN{1.0, {sx * cy * cz, -cx * sy * cz, 0.0}, p};
  };
  PetscFunctionReturn(0);
}

} // namespace suite::euler
