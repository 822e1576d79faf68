// XDMF (v3) sidecar for gridded data in the suite's HDF5 files, so ParaView/VisIt open them.
// Written by rank 0 under a temporary name and renamed.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {

// The sidecar of an output file, the one naming rule of every program: out.h5 -> out.xmf beside it (a name
// without the .h5 extension gets .xmf appended: out -> out.xmf).
std::string xdmfPathFor(const std::string& h5_path);
// What a run with output file h5_path writes: the file and its sidecar ({} without an output file).
std::vector<std::string> outputWithSidecar(const std::string& h5_path);
// The file name of a path (what a sidecar refers to: the .h5 beside it, relative).
std::string fileNameOf(const std::string& path);

struct XdmfAttribute {
  std::string name;           // shown in ParaView
  std::string dataset;        // HDF5 path inside the file, e.g. /snapshots/000010/rho
  bool cell_centered = false; // false: node data
};

struct XdmfStep {
  double time;
  std::vector<XdmfAttribute> attributes;
};

// Structured grid (1D, 2D or 3D) of dims points (z, y, x order, as in the HDF5 datasets), origin and
// spacing also (z, y, x). The HDF5 file name is written relative to the .xmf location.
struct XdmfRectGrid {
  std::vector<unsigned long long> dims;
  std::vector<double> origin, spacing;
};

PetscErrorCode writeXdmfRectSeries(MPI_Comm comm, const std::string& xmf_path, const std::string& h5_file,
                                   const XdmfRectGrid& grid, const std::vector<XdmfStep>& steps);

// Unstructured tetrahedral mesh: /mesh/coordinates (N x 3), /mesh/tets (E x 4, int), steps with node data
// (vectors allowed: an attribute whose dataset has 3 columns is written as a Vector).
struct XdmfTetMesh {
  std::string coords_dataset, tets_dataset;
  unsigned long long nnodes = 0, nelems = 0;
};
struct XdmfNodeField {
  std::string name, dataset;
  int ncomp = 1;
  bool cell = false; // one value per tetrahedron (else per node)
};
struct XdmfTetStep {
  double time;
  std::vector<XdmfNodeField> fields;
};
PetscErrorCode writeXdmfTetSeries(MPI_Comm comm, const std::string& xmf_path, const std::string& h5_file,
                                  const XdmfTetMesh& mesh, const std::vector<XdmfTetStep>& steps);

} // namespace suite
