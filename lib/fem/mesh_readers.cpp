// Mesh file readers for the apps: read the files (one clear collective error if missing) and parse their
// content with the MPI-free parsers of mesh_parse.hpp (a ParseError becomes one collective error naming the
// file and line), then check the mesh (inverted or degenerate elements are errors, not silently fixed). An
// app's -mesh: the structured beam or a file (makeMesh).
#include "fem/mesh.hpp"
#include "fem/mesh_parse.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

namespace suite::fem {
namespace {
bool readFile(const std::string& path, std::string* content) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  *content = s.str();
  return true;
}
} // namespace

PetscErrorCode readTetGen(MPI_Comm comm, const std::string& base, TetMesh* mesh) {
  PetscFunctionBeginUser;
  std::string node, ele;
  PetscCheck(readFile(base + ".node", &node), comm, PETSC_ERR_FILE_OPEN,
             "Mesh %s.node: cannot open (option -mesh_file)", base.c_str());
  PetscCheck(readFile(base + ".ele", &ele), comm, PETSC_ERR_FILE_OPEN,
             "Mesh %s.ele: cannot open (option -mesh_file)", base.c_str());
  std::string error;
  try {
    *mesh = parseTetGen(node, ele, base);
  } catch (const ParseError& e) {
    error = e.what();
  }
  PetscCheck(error.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s", error.c_str());
  PetscCall(checkMesh(comm, *mesh, (base + ".ele").c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode readGmsh(MPI_Comm comm, const std::string& path, TetMesh* mesh) {
  PetscFunctionBeginUser;
  std::string content;
  PetscCheck(readFile(path, &content), comm, PETSC_ERR_FILE_OPEN, "Mesh %s: cannot open (option -mesh_file)",
             path.c_str());
  std::string error;
  try {
    *mesh = parseGmsh(content, path);
  } catch (const ParseError& e) {
    error = e.what();
  }
  PetscCheck(error.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s", error.c_str());
  PetscCall(checkMesh(comm, *mesh, path.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode readMeshFile(MPI_Comm comm, const std::string& f, TetMesh* mesh) {
  PetscFunctionBeginUser;
  if (f.size() > 4 && f.substr(f.size() - 4) == ".msh") {
    PetscCall(readGmsh(comm, f, mesh));
  } else {
    std::string base = f;
    for (const char* ext : {".node", ".ele"})
      if (base.size() > 5 && base.substr(base.size() - std::strlen(ext)) == ext)
        base.resize(base.size() - std::strlen(ext));
    PetscCall(readTetGen(comm, base, mesh));
  }
  PetscFunctionReturn(0);
}

std::vector<suite::Choice> meshChoices() {
  return {{"beam", "structured beam of hexahedra, 6 tets each"},
          {"file", "Gmsh or TetGen mesh given by -mesh_file"}};
}

PetscErrorCode makeMesh(MPI_Comm comm, const std::string& kind, const BeamSpec& beam, const std::string& file,
                        int order, TetMesh* mesh) {
  PetscFunctionBeginUser;
  if (kind == "beam") {
    *mesh = makeBeam(beam);
  } else {
    PetscCheck(!file.empty(), comm, PETSC_ERR_ARG_WRONG, "-mesh file needs -mesh_file");
    PetscCall(readMeshFile(comm, file, mesh));
  }
  if (order == 2 && mesh->order() == 1) *mesh = promoteToP2(*mesh);
  PetscFunctionReturn(0);
}

} // namespace suite::fem
