// `-problem file`: the initial state read from an HDF5 file on the run's grid (initial_state_file.hpp), for
// -dim 1|2|3: -initial_state FILE.h5 (required), -initial_group G (default "/"; a run's output holds its
// final state in /final and, with -output_initial, its initial conservative state in /initial), -gamma.
// The grid size is the datasets' shape (-nx ... may repeat it, not change it); the domain comes from the
// file's xmin/xmax ... attributes where it has them (-xmin ... may repeat them, not change them), else from
// -xmin -xmax ... or [0, 1]^dim; gamma from -gamma, else the file's root attribute `gamma` (a run's output),
// else 1.4. Faces are outflow unless -bc_* says otherwise; -t_final is required.
// Example (three lines of h5py: a 2D density bump at rest on a 128 x 64 grid):
//   x, y = np.meshgrid((np.arange(128) + 0.5) / 128, (np.arange(64) + 0.5) / 64)
//   with h5py.File("bump.h5", "w") as f:
//       f["rho"] = 1 + np.exp(-50 * ((x - .5)**2 + (y - .5)**2)); f["u"] = f["v"] = 0 * x; f["p"] = 1 + 0 * x
#include "core/option_value.hpp"
#include "euler/initial_state_file.hpp"
#include "euler/problem_nd.hpp"

#include <cmath>
#include <memory>

namespace suite::euler {

PetscErrorCode createFileProblem(MPI_Comm comm, int dim, ProblemND* pr) {
  std::string path, group = "/";
  PetscBool given = PETSC_FALSE, gamma_set = PETSC_FALSE;
  double gamma = 1.4;
  InitialStateFile f;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "File problem options", "");
  PetscCall(
      suite::optionsString(PetscOptionsObject, "-initial_state",
                           "HDF5 file of the initial state on the run's grid (primitive rho u [v [w]] p or "
                           "conservative rho mom_x [mom_y [mom_z]] E, (z,) (y,) x order)",
                           &path, &given));
  PetscCall(suite::optionsString(
      PetscOptionsObject, "-initial_group",
      "Group of -initial_state holding the datasets (/final, /initial: a run's output)", &group, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-gamma",
                               "Ratio of specific heats (default: the file's gamma attribute, else 1.4)", "",
                               gamma, &gamma, &gamma_set));
  PetscOptionsEnd();
  PetscCheck(given && !path.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-problem file needs -initial_state FILE.h5 (the initial state on the run's grid)");
  PetscCall(inspectInitialStateFile(comm, path, group, dim, &f));
  if (!gamma_set && f.has_gamma) gamma = f.gamma;
  PetscCall(checkGamma(comm, gamma));
  pr->gamma = gamma;
  pr->initial_file = f.path;
  pr->initial_group = f.group;
  pr->initial_state = std::make_shared<const InitialStateFile>(f);
  for (int d = 0; d < dim; ++d) {
    pr->default_n[d] = f.n[d];
    if (f.has_extent[d]) {
      pr->lo[d] = f.lo[d];
      pr->hi[d] = f.hi[d];
      pr->fixed_extent[d] = true;
    }
  }
  PetscFunctionReturn(0);
}

} // namespace suite::euler
