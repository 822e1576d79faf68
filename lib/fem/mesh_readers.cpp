// Mesh readers: TetGen .node/.ele (Si, TetGen manual 1.5, sec. 5.2) and Gmsh .msh ASCII 2.2 and 4.1 (Gmsh
// reference manual, sec. 10.1 and 10.2). Only tetrahedra (Gmsh types 4 and 11) are kept; other elements are
// skipped. Every error names the file and line; an inverted element is an error, not a silent fix.
#include "fem/mesh.hpp"

#include <fstream>
#include <map>
#include <sstream>

namespace suite::fem {
namespace {

// Whitespace token stream over a file with line numbers; '#' starts a comment (TetGen) when hash_comments.
class Tokens {
public:
  Tokens(const std::string& path, bool hash_comments) : path_(path), hash_(hash_comments), in_(path) {}
  bool good() const { return static_cast<bool>(in_); }
  const std::string& path() const { return path_; }
  int line() const { return line_; }
  // Next token, or false at end of file.
  bool next(std::string* tok) {
    while (!(ls_ >> *tok)) {
      std::string l;
      if (!std::getline(in_, l)) return false;
      ++line_;
      if (hash_) {
        const auto h = l.find('#');
        if (h != std::string::npos) l.resize(h);
      }
      ls_.clear();
      ls_.str(l);
    }
    return true;
  }
  // Rest of the current line is dropped (for Gmsh element lines with extra tags we read exactly).
  void skipLine() {
    ls_.clear();
    ls_.str("");
  }

private:
  std::string path_;
  bool hash_;
  std::ifstream in_;
  std::istringstream ls_;
  int line_ = 0;
};

PetscErrorCode nextToken(MPI_Comm comm, Tokens& t, const char* what, std::string* tok) {
  PetscFunctionBeginUser;
  PetscCheck(t.next(tok), comm, PETSC_ERR_FILE_UNEXPECTED,
             "Mesh %s: truncated file: expected %s after line %d", t.path().c_str(), what, t.line());
  PetscFunctionReturn(0);
}

template <typename T> PetscErrorCode nextNumber(MPI_Comm comm, Tokens& t, const char* what, T* v) {
  PetscFunctionBeginUser;
  std::string tok;
  PetscCall(nextToken(comm, t, what, &tok));
  std::istringstream s(tok);
  T x;
  char extra;
  PetscCheck((s >> x) && !(s >> extra), comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s line %d: malformed %s '%s'",
             t.path().c_str(), t.line(), what, tok.c_str());
  *v = x;
  PetscFunctionReturn(0);
}

PetscErrorCode expectToken(MPI_Comm comm, Tokens& t, const char* want) {
  PetscFunctionBeginUser;
  std::string tok;
  PetscCall(nextToken(comm, t, want, &tok));
  PetscCheck(tok == want, comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s line %d: expected %s, found '%s'",
             t.path().c_str(), t.line(), want, tok.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readTetGen(MPI_Comm comm, const std::string& base, TetMesh* mesh) {
  PetscFunctionBeginUser;
  *mesh = TetMesh();
  Tokens nt(base + ".node", true);
  PetscCheck(nt.good(), comm, PETSC_ERR_FILE_OPEN, "Mesh %s.node: cannot open (option -mesh_file)",
             base.c_str());
  long long nn, dim, nattr, nmark;
  PetscCall(nextNumber(comm, nt, "number of nodes", &nn));
  PetscCall(nextNumber(comm, nt, "dimension", &dim));
  PetscCall(nextNumber(comm, nt, "number of attributes", &nattr));
  PetscCall(nextNumber(comm, nt, "boundary marker flag", &nmark));
  PetscCheck(nn > 0 && dim == 3 && nattr >= 0 && (nmark == 0 || nmark == 1), comm, PETSC_ERR_FILE_UNEXPECTED,
             "Mesh %s.node: bad header (%lld nodes, dimension %lld, %lld attributes, markers %lld)",
             base.c_str(), nn, dim, nattr, nmark);
  long long first = 0;
  mesh->nodes.resize(nn);
  for (long long i = 0; i < nn; ++i) {
    long long id;
    PetscCall(nextNumber(comm, nt, "node index", &id));
    if (i == 0) first = id;
    PetscCheck(id == first + i, comm, PETSC_ERR_FILE_UNEXPECTED,
               "Mesh %s.node line %d: node index %lld, expected %lld", base.c_str(), nt.line(), id,
               first + i);
    for (int c = 0; c < 3; ++c) PetscCall(nextNumber(comm, nt, "coordinate", &mesh->nodes[i][c]));
    double skip;
    for (long long a = 0; a < nattr + nmark; ++a) PetscCall(nextNumber(comm, nt, "node attribute", &skip));
  }
  Tokens et(base + ".ele", true);
  PetscCheck(et.good(), comm, PETSC_ERR_FILE_OPEN, "Mesh %s.ele: cannot open (option -mesh_file)",
             base.c_str());
  long long ne, npe, eattr;
  PetscCall(nextNumber(comm, et, "number of tetrahedra", &ne));
  PetscCall(nextNumber(comm, et, "nodes per tetrahedron", &npe));
  PetscCall(nextNumber(comm, et, "number of attributes", &eattr));
  PetscCheck(ne > 0 && npe == 4 && eattr >= 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "Mesh %s.ele: bad header (%lld tetrahedra, %lld nodes each; only 4 is supported)", base.c_str(),
             ne, npe);
  mesh->elems.resize(ne * 4);
  for (long long e = 0; e < ne; ++e) {
    long long id;
    PetscCall(nextNumber(comm, et, "element index", &id));
    for (int a = 0; a < 4; ++a) {
      long long v;
      PetscCall(nextNumber(comm, et, "node of a tetrahedron", &v));
      PetscCheck(v - first >= 0 && v - first < nn, comm, PETSC_ERR_FILE_UNEXPECTED,
                 "Mesh %s.ele line %d: node %lld out of range [%lld, %lld]", base.c_str(), et.line(), v,
                 first, first + nn - 1);
      mesh->elems[e * 4 + a] = static_cast<int>(v - first);
    }
    double skip;
    for (long long a = 0; a < eattr; ++a) PetscCall(nextNumber(comm, et, "element attribute", &skip));
  }
  PetscCall(checkMesh(comm, *mesh, (base + ".ele").c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode readGmsh(MPI_Comm comm, const std::string& path, TetMesh* mesh) {
  PetscFunctionBeginUser;
  *mesh = TetMesh();
  Tokens t(path, false);
  PetscCheck(t.good(), comm, PETSC_ERR_FILE_OPEN, "Mesh %s: cannot open (option -mesh_file)", path.c_str());
  PetscCall(expectToken(comm, t, "$MeshFormat"));
  double version;
  int ftype, dsize;
  PetscCall(nextNumber(comm, t, "format version", &version));
  PetscCall(nextNumber(comm, t, "file type", &ftype));
  PetscCall(nextNumber(comm, t, "data size", &dsize));
  PetscCheck((version == 2.2 || version == 4.1) && ftype == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "Mesh %s: Gmsh format %g (file type %d) not supported; use ASCII 2.2 or 4.1", path.c_str(),
             version, ftype);
  PetscCall(expectToken(comm, t, "$EndMeshFormat"));
  std::map<long long, int> index; // node tag -> index
  std::vector<int> tets;
  bool p2 = false, have_nodes = false;
  std::string tok;
  auto addTet = [&](const std::vector<long long>& tags, int type, int line) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const bool q = type == 11;
    PetscCheck(tets.empty() || q == p2, comm, PETSC_ERR_FILE_UNEXPECTED,
               "Mesh %s line %d: mixes 4- and 10-node tetrahedra", path.c_str(), line);
    p2 = q;
    static const int gmsh_to_vtk[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}; // Gmsh tet10 edges 01,12,20,30,32,31
    for (size_t a = 0; a < tags.size(); ++a) {
      const auto it = index.find(tags[q ? gmsh_to_vtk[a] : a]);
      PetscCheck(it != index.end(), comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s line %d: unknown node tag %lld",
                 path.c_str(), line, tags[q ? gmsh_to_vtk[a] : a]);
      tets.push_back(it->second);
    }
    PetscFunctionReturn(0);
  };
  while (t.next(&tok)) {
    if (tok == "$Nodes") {
      have_nodes = true;
      if (version == 2.2) {
        long long n;
        PetscCall(nextNumber(comm, t, "number of nodes", &n));
        for (long long i = 0; i < n; ++i) {
          long long tag;
          std::array<double, 3> x;
          PetscCall(nextNumber(comm, t, "node tag", &tag));
          for (int c = 0; c < 3; ++c) PetscCall(nextNumber(comm, t, "coordinate", &x[c]));
          index[tag] = static_cast<int>(mesh->nodes.size());
          mesh->nodes.push_back(x);
        }
      } else {
        long long nblocks, n, mn, mx;
        PetscCall(nextNumber(comm, t, "number of node blocks", &nblocks));
        PetscCall(nextNumber(comm, t, "number of nodes", &n));
        PetscCall(nextNumber(comm, t, "min node tag", &mn));
        PetscCall(nextNumber(comm, t, "max node tag", &mx));
        for (long long b = 0; b < nblocks; ++b) {
          long long dim, ent, param, cnt;
          PetscCall(nextNumber(comm, t, "entity dimension", &dim));
          PetscCall(nextNumber(comm, t, "entity tag", &ent));
          PetscCall(nextNumber(comm, t, "parametric flag", &param));
          PetscCall(nextNumber(comm, t, "nodes in block", &cnt));
          PetscCheck(param == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
                     "Mesh %s line %d: parametric nodes not supported", path.c_str(), t.line());
          std::vector<long long> tags(cnt);
          for (auto& g : tags) PetscCall(nextNumber(comm, t, "node tag", &g));
          for (long long i = 0; i < cnt; ++i) {
            std::array<double, 3> x;
            for (int c = 0; c < 3; ++c) PetscCall(nextNumber(comm, t, "coordinate", &x[c]));
            index[tags[i]] = static_cast<int>(mesh->nodes.size());
            mesh->nodes.push_back(x);
          }
        }
      }
      PetscCall(expectToken(comm, t, "$EndNodes"));
    } else if (tok == "$Elements") {
      PetscCheck(have_nodes, comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s line %d: $Elements before $Nodes",
                 path.c_str(), t.line());
      if (version == 2.2) {
        long long n;
        PetscCall(nextNumber(comm, t, "number of elements", &n));
        for (long long i = 0; i < n; ++i) {
          long long tag, type, ntags, skip;
          PetscCall(nextNumber(comm, t, "element tag", &tag));
          PetscCall(nextNumber(comm, t, "element type", &type));
          PetscCall(nextNumber(comm, t, "number of tags", &ntags));
          for (long long k = 0; k < ntags; ++k) PetscCall(nextNumber(comm, t, "element tag value", &skip));
          static const std::map<int, int> nodes_of = {{1, 2}, {2, 3}, {3, 4}, {4, 4},   {5, 8}, {6, 6},
                                                      {7, 5}, {8, 3}, {9, 6}, {11, 10}, {15, 1}};
          const auto it = nodes_of.find(static_cast<int>(type));
          PetscCheck(it != nodes_of.end(), comm, PETSC_ERR_FILE_UNEXPECTED,
                     "Mesh %s line %d: unsupported element type %lld", path.c_str(), t.line(), type);
          std::vector<long long> tags(it->second);
          for (auto& g : tags) PetscCall(nextNumber(comm, t, "element node", &g));
          if (type == 4 || type == 11) PetscCall(addTet(tags, static_cast<int>(type), t.line()));
        }
      } else {
        long long nblocks, n, mn, mx;
        PetscCall(nextNumber(comm, t, "number of element blocks", &nblocks));
        PetscCall(nextNumber(comm, t, "number of elements", &n));
        PetscCall(nextNumber(comm, t, "min element tag", &mn));
        PetscCall(nextNumber(comm, t, "max element tag", &mx));
        for (long long b = 0; b < nblocks; ++b) {
          long long dim, ent, type, cnt;
          PetscCall(nextNumber(comm, t, "entity dimension", &dim));
          PetscCall(nextNumber(comm, t, "entity tag", &ent));
          PetscCall(nextNumber(comm, t, "element type", &type));
          PetscCall(nextNumber(comm, t, "elements in block", &cnt));
          static const std::map<int, int> nodes_of = {{1, 2}, {2, 3}, {3, 4}, {4, 4},   {5, 8}, {6, 6},
                                                      {7, 5}, {8, 3}, {9, 6}, {11, 10}, {15, 1}};
          const auto it = nodes_of.find(static_cast<int>(type));
          PetscCheck(it != nodes_of.end(), comm, PETSC_ERR_FILE_UNEXPECTED,
                     "Mesh %s line %d: unsupported element type %lld", path.c_str(), t.line(), type);
          for (long long i = 0; i < cnt; ++i) {
            long long tag;
            PetscCall(nextNumber(comm, t, "element tag", &tag));
            std::vector<long long> tags(it->second);
            for (auto& g : tags) PetscCall(nextNumber(comm, t, "element node", &g));
            if (type == 4 || type == 11) PetscCall(addTet(tags, static_cast<int>(type), t.line()));
          }
        }
      }
      PetscCall(expectToken(comm, t, "$EndElements"));
    } else if (!tok.empty() && tok[0] == '$' && tok.rfind("$End", 0) != 0) {
      const std::string end = "$End" + tok.substr(1); // skip an unknown section
      std::string s;
      while (true) {
        PetscCall(nextToken(comm, t, end.c_str(), &s));
        if (s == end) break;
      }
    } else {
      SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh %s line %d: unexpected '%s'", path.c_str(), t.line(),
              tok.c_str());
    }
  }
  mesh->nodes_per_elem = p2 ? 10 : 4;
  mesh->elems = std::move(tets);
  PetscCall(checkMesh(comm, *mesh, path.c_str()));
  PetscFunctionReturn(0);
}

} // namespace suite::fem
