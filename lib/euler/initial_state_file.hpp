// An Euler initial state read from an HDF5 file (`-problem file -initial_state FILE.h5`): one group (default
// "/"; -initial_group /final or /initial take a run's own output) holding either the primitive datasets
//   1D rho u p, 2D rho u v p (w allowed, all 0), 3D rho u v w p
// or the conservative ones
//   1D rho mom_x E, 2D rho mom_x mom_y E, 3D rho mom_x mom_y mom_z E,
// each an array of the run's grid in the app's layout: (z, y, x) order, x fastest; 1D (nx), 2D (ny, nx), 3D
// (nz, ny, nx). The grid size comes from the shape; the domain from attributes xmin xmax [ymin ymax [zmin
// zmax]] on the group or the root (the app writes them), when present. Datasets the app writes beside the
// state (shock, mask) are ignored; any other name, a set mixing primitive and conservative names, a missing
// dataset or unequal shapes is one collective error naming the file and the dataset. Values are read
// collectively, each rank its own block (parallel HDF5 hyperslabs), and checked before the first step: a NaN
// or Inf, rho <= 0 or p <= 0 is one error naming the dataset, the cell (i, j, k) and the value.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite::euler {

struct InitialStateFile {
  std::string path, group;
  bool conservative = false;
  std::vector<std::string> fields; // the datasets of the state, in the order of the state's components
  bool zero_w = false;             // 2D primitive: a w dataset to check for zeros
  PetscInt n[3] = {1, 1, 1};       // the grid (x, y, z) from the shape
  bool has_extent[3] = {false, false, false};
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  bool has_gamma = false; // the root attribute gamma (a run's output)
  double gamma = 1.4;
};

// Collective: opens path, checks the group's datasets, shapes and extent attributes.
PetscErrorCode inspectInitialStateFile(MPI_Comm comm, const std::string& path, const std::string& group,
                                       int dim, InitialStateFile* file);

// Collective: this rank's block s .. s + m - 1 (per direction x, y, z) of the state: values[c * ncomp + v]
// for cell c (x fastest) and component v (dim + 2 components: primitive rho, u.., p or conservative rho,
// mom.., E, as file.conservative says), after the value checks.
PetscErrorCode readInitialStateBlock(MPI_Comm comm, const InitialStateFile& file, int dim, double gamma,
                                     const PetscInt s[3], const PetscInt m[3], std::vector<double>* values);

} // namespace suite::euler
