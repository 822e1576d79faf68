// XDMF v3 sidecars (structured co-rectilinear grids and tetrahedral meshes) for the suite's HDF5 files.
#include "io/xdmf.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace suite {

std::string xdmfPathFor(const std::string& h5_path) {
  std::string xmf = h5_path;
  if (xmf.size() > 3 && xmf.compare(xmf.size() - 3, 3, ".h5") == 0) xmf.resize(xmf.size() - 3);
  return xmf + ".xmf";
}

std::vector<std::string> outputWithSidecar(const std::string& h5_path) {
  if (h5_path.empty()) return {};
  return {h5_path, xdmfPathFor(h5_path)};
}

std::string fileNameOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}
namespace {

std::string join(const std::vector<unsigned long long>& v) {
  std::ostringstream s;
  for (size_t i = 0; i < v.size(); ++i) s << (i ? " " : "") << v[i];
  return s.str();
}

std::string join(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(17);
  for (size_t i = 0; i < v.size(); ++i) s << (i ? " " : "") << v[i];
  return s.str();
}

// Rank 0 writes text to path.tmp and renames; the result is agreed on by all ranks.
PetscErrorCode writeTextAtomically(MPI_Comm comm, const std::string& path, const std::string& text) {
  PetscFunctionBeginUser;
  int rank = 0, err = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) {
    const std::string tmp = path + ".tmp";
    FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f)
      err = errno ? errno : EIO;
    else {
      if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) err = errno ? errno : EIO;
      if (std::fclose(f) != 0 && !err) err = errno ? errno : EIO;
      if (!err && std::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(err == 0, comm, PETSC_ERR_FILE_WRITE, "cannot write %s: %s", path.c_str(), std::strerror(err));
  PetscFunctionReturn(0);
}

std::string baseName(const std::string& p) {
  auto s = p.find_last_of('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

const char* header() {
  return "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"3.0\">\n "
         "<Domain>\n"
         "  <Grid Name=\"series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}
const char* footer() {
  return "  </Grid>\n </Domain>\n</Xdmf>\n";
}

} // namespace

PetscErrorCode writeXdmfRectSeries(MPI_Comm comm, const std::string& xmf_path, const std::string& h5_file,
                                   const XdmfRectGrid& grid, const std::vector<XdmfStep>& steps) {
  PetscFunctionBeginUser;
  const size_t dim = grid.dims.size();
  PetscCheck(dim >= 1 && dim <= 3 && grid.origin.size() == dim && grid.spacing.size() == dim, comm,
             PETSC_ERR_ARG_SIZ, "XDMF grid: dims, origin and spacing must have 1 to 3 entries each");
  // XDMF has no 1D co-rectilinear topology: a 1D grid is shown as a 2D grid one cell thick.
  std::vector<unsigned long long> nodes = grid.dims;
  std::vector<double> origin = grid.origin, spacing = grid.spacing;
  if (dim == 1) {
    nodes.insert(nodes.begin(), 2);
    origin.insert(origin.begin(), 0.0);
    spacing.insert(spacing.begin(), spacing.back());
  }
  std::vector<unsigned long long> cells = nodes;
  for (auto& c : cells) c = c > 1 ? c - 1 : 1;
  const size_t d = nodes.size();
  const std::string h5 = baseName(h5_file);
  std::ostringstream x;
  x << header();
  for (const auto& st : steps) {
    x << "   <Grid Name=\"mesh\" GridType=\"Uniform\">\n    <Time Value=\"" << st.time << "\"/>\n";
    x << "    <Topology TopologyType=\"" << d << "DCoRectMesh\" Dimensions=\"" << join(nodes) << "\"/>\n";
    x << "    <Geometry GeometryType=\"" << (d == 3 ? "ORIGIN_DXDYDZ" : "ORIGIN_DXDY") << "\">\n";
    x << "     <DataItem Format=\"XML\" Dimensions=\"" << d << "\">" << join(origin) << "</DataItem>\n";
    x << "     <DataItem Format=\"XML\" Dimensions=\"" << d << "\">" << join(spacing) << "</DataItem>\n";
    x << "    </Geometry>\n";
    for (const auto& a : st.attributes) {
      x << "    <Attribute Name=\"" << a.name << "\" AttributeType=\"Scalar\" Center=\""
        << (a.cell_centered ? "Cell" : "Node") << "\">\n";
      x << "     <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\""
        << join(a.cell_centered ? cells : nodes) << "\">" << h5 << ":" << a.dataset << "</DataItem>\n";
      x << "    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << footer();
  PetscCall(writeTextAtomically(comm, xmf_path, x.str()));
  PetscFunctionReturn(0);
}

PetscErrorCode writeXdmfTetSeries(MPI_Comm comm, const std::string& xmf_path, const std::string& h5_file,
                                  const XdmfTetMesh& mesh, const std::vector<XdmfTetStep>& steps) {
  PetscFunctionBeginUser;
  const std::string h5 = baseName(h5_file);
  std::ostringstream x;
  x << header();
  for (const auto& st : steps) {
    x << "   <Grid Name=\"mesh\" GridType=\"Uniform\">\n    <Time Value=\"" << st.time << "\"/>\n";
    x << "    <Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"" << mesh.nelems << "\">\n";
    x << "     <DataItem Format=\"HDF\" NumberType=\"Int\" Dimensions=\"" << mesh.nelems << " 4\">" << h5
      << ":" << mesh.tets_dataset << "</DataItem>\n    </Topology>\n";
    x << "    <Geometry GeometryType=\"XYZ\">\n";
    x << "     <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"" << mesh.nnodes
      << " 3\">" << h5 << ":" << mesh.coords_dataset << "</DataItem>\n    </Geometry>\n";
    for (const auto& f : st.fields) {
      x << "    <Attribute Name=\"" << f.name << "\" AttributeType=\"" << (f.ncomp == 3 ? "Vector" : "Scalar")
        << "\" Center=\"" << (f.cell ? "Cell" : "Node") << "\">\n";
      x << "     <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\""
        << (f.cell ? mesh.nelems : mesh.nnodes);
      if (f.ncomp > 1) x << " " << f.ncomp;
      x << "\">" << h5 << ":" << f.dataset << "</DataItem>\n    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << footer();
  PetscCall(writeTextAtomically(comm, xmf_path, x.str()));
  PetscFunctionReturn(0);
}

} // namespace suite
