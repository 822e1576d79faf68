// Parsers of mesh and matrix files on their content (see mesh_parse.hpp): TetGen .node/.ele (Si, TetGen
// manual 1.5, sec. 5.2), Gmsh .msh ASCII 2.2 and 4.1 (Gmsh reference manual, sec. 10.1-10.2), Matrix Market
// coordinate (Boisvert, Pozo & Remington, NIST 1996). Every error names the file and the line.
#include "fem/mesh_parse.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <unordered_map>

namespace suite::fem {
namespace {

[[noreturn]] void fail(const std::string& msg) {
  throw ParseError(msg);
}

// Whitespace token stream over a string with line numbers; '#' starts a comment when hash_comments.
class Tokens {
public:
  Tokens(const std::string& s, std::string name, bool hash_comments)
      : s_(s), name_(std::move(name)), hash_(hash_comments) {}
  const std::string& name() const { return name_; }
  int line() const { return line_; }
  size_t remaining() const { return s_.size() - pos_; }
  bool next(std::string* tok) {
    for (;;) {
      while (pos_ < s_.size() && isspace(static_cast<unsigned char>(s_[pos_]))) {
        if (s_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if (pos_ >= s_.size()) return false;
      if (hash_ && s_[pos_] == '#') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    const size_t b = pos_;
    while (pos_ < s_.size() && !isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    tok->assign(s_, b, pos_ - b);
    return true;
  }
  std::string token(const char* what) {
    std::string t;
    if (!next(&t))
      fail(name_ + ": truncated file: expected " + what + " after line " + std::to_string(line_));
    return t;
  }
  long long integer(const char* what) {
    const std::string t = token(what);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || errno == ERANGE) malformed(what, t);
    return v;
  }
  double real(const char* what) {
    const std::string t = token(what);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(v)) malformed(what, t);
    return v;
  }
  void expect(const char* want) {
    const std::string t = token(want);
    if (t != want) fail(where() + ": expected " + want + ", found '" + t.substr(0, 40) + "'");
  }
  std::string where() const { return name_ + " line " + std::to_string(line_); }
  [[noreturn]] void malformed(const char* what, const std::string& t) const {
    fail(where() + ": malformed " + what + " '" + t.substr(0, 40) + "'");
  }
  // A count read from the file must fit in what is left of it (each item takes >= min_bytes), so hostile
  // headers cannot make us allocate: e.g. 1e12 nodes in a 1 kB file is an error, not an allocation.
  // The bound uses a quarter of the item's minimum size: a merely truncated file is reported as truncated
  // (with its line), while memory stays bounded by a small multiple of the file size.
  void checkCount(long long n, long long min_bytes, const char* what) const {
    if (n < 0 || n > static_cast<long long>(remaining() / std::max(1LL, min_bytes / 4)) ||
        n > (1LL << 31) - 2)
      fail(where() + ": " + std::to_string(n) + " " + what + " cannot fit in the rest of the file (" +
           std::to_string(remaining()) + " bytes)");
  }

private:
  const std::string& s_;
  std::string name_;
  bool hash_;
  size_t pos_ = 0;
  int line_ = 1;
};

// Gmsh element type -> number of nodes (types we can skip or keep).
int gmshNodesOf(long long type) {
  static const std::map<long long, int> n = {{1, 2}, {2, 3}, {3, 4}, {4, 4},   {5, 8}, {6, 6},
                                             {7, 5}, {8, 3}, {9, 6}, {11, 10}, {15, 1}};
  const auto it = n.find(type);
  return it == n.end() ? -1 : it->second;
}

} // namespace

TetMesh parseTetGen(const std::string& node_content, const std::string& ele_content,
                    const std::string& base) {
  TetMesh mesh;
  Tokens nt(node_content, base + ".node", true);
  const long long nn = nt.integer("number of nodes"), dim = nt.integer("dimension"),
                  nattr = nt.integer("number of attributes"), nmark = nt.integer("boundary marker flag");
  if (!(nn > 0 && dim == 3 && nattr >= 0 && nattr < 1000 && (nmark == 0 || nmark == 1)))
    fail(base + ".node: bad header (" + std::to_string(nn) + " nodes, dimension " + std::to_string(dim) +
         ", " + std::to_string(nattr) + " attributes, markers " + std::to_string(nmark) + ")");
  nt.checkCount(nn, 2 * (4 + nattr + nmark), "nodes");
  long long first = 0;
  mesh.nodes.resize(nn);
  for (long long i = 0; i < nn; ++i) {
    const long long id = nt.integer("node index");
    if (i == 0) first = id;
    if (first != 0 && first != 1)
      fail(nt.where() + ": first node index " + std::to_string(id) + ", expected 0 or 1");
    if (id != first + i)
      fail(nt.where() + ": node index " + std::to_string(id) + ", expected " + std::to_string(first + i));
    for (int c = 0; c < 3; ++c) mesh.nodes[i][c] = nt.real("coordinate");
    for (long long a = 0; a < nattr + nmark; ++a) nt.real("node attribute");
  }
  Tokens et(ele_content, base + ".ele", true);
  const long long ne = et.integer("number of tetrahedra"), npe = et.integer("nodes per tetrahedron"),
                  eattr = et.integer("number of attributes");
  if (!(ne > 0 && (npe == 4 || npe == 10) && eattr >= 0 && eattr < 1000))
    fail(base + ".ele: bad header (" + std::to_string(ne) + " tetrahedra, " + std::to_string(npe) +
         " nodes each: 4 or 10 are supported)");
  et.checkCount(ne, 2 * (1 + npe + eattr), "tetrahedra");
  mesh.nodes_per_elem = static_cast<int>(npe);
  mesh.elems.resize(ne * npe);
  for (long long e = 0; e < ne; ++e) {
    et.integer("element index");
    int t[10];
    for (int a = 0; a < npe; ++a) {
      const long long v = et.integer("node of a tetrahedron");
      if (v - first < 0 || v - first >= nn)
        fail(et.where() + ": node " + std::to_string(v) + " out of range [" + std::to_string(first) + ", " +
             std::to_string(first + nn - 1) + "]");
      t[a] = static_cast<int>(v - first);
    }
    for (long long a = 0; a < eattr; ++a) et.real("element attribute");
    int* out = mesh.elems.data() + e * npe;
    for (int a = 0; a < 4; ++a) out[a] = t[a];
    if (npe == 10) {
      // Place each extra node on the edge whose midpoint it is (TetMesh/VTK edge order 01,12,02,03,13,23).
      static const int edge[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
      bool used[6] = {false, false, false, false, false, false};
      for (int k = 4; k < 10; ++k) {
        const auto& x = mesh.nodes[t[k]];
        int found = -1;
        for (int j = 0; j < 6 && found < 0; ++j) {
          const auto &a = mesh.nodes[t[edge[j][0]]], &b = mesh.nodes[t[edge[j][1]]];
          double d2 = 0, l2 = 0;
          for (int c = 0; c < 3; ++c) {
            const double m = 0.5 * (a[c] + b[c]) - x[c];
            d2 += m * m;
            l2 += (b[c] - a[c]) * (b[c] - a[c]);
          }
          if (!used[j] && d2 <= 1e-16 * l2 && l2 > 0) found = j;
        }
        if (found < 0)
          fail(et.where() + ": node " + std::to_string(t[k] + first) + " of 10-node tetrahedron " +
               std::to_string(e) +
               " is not the midpoint of one of its edges (only straight-sided P2 is supported)");
        used[found] = true;
        out[4 + found] = t[k];
      }
    }
  }
  return mesh;
}

namespace {
// A Gmsh ASCII 2.2/4.1 reader's state: the nodes so far (and their tags), the tetrahedra's nodes.
struct GmshReader {
  Tokens& t;
  TetMesh mesh;
  std::unordered_map<long long, int> index; // node tag -> index
  std::vector<int> tets;
  bool p2 = false;

  void addNode(long long tag, const std::array<double, 3>& x) {
    if (!index.emplace(tag, static_cast<int>(mesh.nodes.size())).second)
      fail(t.where() + ": duplicate node tag " + std::to_string(tag));
    mesh.nodes.push_back(x);
  }
  void addElement(long long type, const std::vector<long long>& tags) {
    if (type != 4 && type != 11) return;
    const bool q = type == 11;
    if (!tets.empty() && q != p2) fail(t.where() + ": mixes 4- and 10-node tetrahedra");
    p2 = q;
    static const int gmsh_to_vtk[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}; // Gmsh tet10 edges 01,12,20,30,32,31
    for (size_t a = 0; a < tags.size(); ++a) {
      const long long g = tags[q ? gmsh_to_vtk[a] : a];
      const auto it = index.find(g);
      if (it == index.end()) fail(t.where() + ": unknown node tag " + std::to_string(g));
      tets.push_back(it->second);
    }
  }
  std::array<double, 3> point() {
    std::array<double, 3> x;
    for (int c = 0; c < 3; ++c) x[c] = t.real("coordinate");
    return x;
  }
  void nodes22() {
    const long long n = t.integer("number of nodes");
    t.checkCount(n, 8, "nodes");
    for (long long i = 0; i < n; ++i) {
      const long long tag = t.integer("node tag");
      addNode(tag, point());
    }
  }
  void nodes41() {
    const long long nblocks = t.integer("number of node blocks");
    t.integer("number of nodes");
    t.integer("min node tag");
    t.integer("max node tag");
    t.checkCount(nblocks, 8, "node blocks");
    for (long long b = 0; b < nblocks; ++b) {
      t.integer("entity dimension");
      t.integer("entity tag");
      const long long param = t.integer("parametric flag"), cnt = t.integer("nodes in block");
      if (param != 0) fail(t.where() + ": parametric nodes not supported");
      t.checkCount(cnt, 8, "nodes in the block");
      std::vector<long long> tags(cnt);
      for (auto& g : tags) g = t.integer("node tag");
      for (long long i = 0; i < cnt; ++i) addNode(tags[i], point());
    }
  }
  int nodesOfType(long long type) {
    const int nn = gmshNodesOf(type);
    if (nn < 0) fail(t.where() + ": unsupported element type " + std::to_string(type));
    return nn;
  }
  void elements22() {
    const long long n = t.integer("number of elements");
    t.checkCount(n, 8, "elements");
    for (long long i = 0; i < n; ++i) {
      t.integer("element tag");
      const long long type = t.integer("element type"), ntags = t.integer("number of tags");
      t.checkCount(ntags, 2, "element tags");
      for (long long k = 0; k < ntags; ++k) t.integer("element tag value");
      std::vector<long long> tags(nodesOfType(type));
      for (auto& g : tags) g = t.integer("element node");
      addElement(type, tags);
    }
  }
  void elements41() {
    const long long nblocks = t.integer("number of element blocks");
    t.integer("number of elements");
    t.integer("min element tag");
    t.integer("max element tag");
    t.checkCount(nblocks, 8, "element blocks");
    for (long long b = 0; b < nblocks; ++b) {
      t.integer("entity dimension");
      t.integer("entity tag");
      const long long type = t.integer("element type"), cnt = t.integer("elements in block");
      const int nn = nodesOfType(type);
      t.checkCount(cnt, 2 * (1 + nn), "elements in the block");
      std::vector<long long> tags(nn);
      for (long long i = 0; i < cnt; ++i) {
        t.integer("element tag");
        for (auto& g : tags) g = t.integer("element node");
        addElement(type, tags);
      }
    }
  }
};
} // namespace

TetMesh parseGmsh(const std::string& content, const std::string& name) {
  Tokens t(content, name, false);
  t.expect("$MeshFormat");
  const double version = t.real("format version");
  const long long ftype = t.integer("file type");
  t.integer("data size");
  if (!((version == 2.2 || version == 4.1) && ftype == 0))
    fail(name + ": Gmsh format " + std::to_string(version) + " (file type " + std::to_string(ftype) +
         ") not supported; use ASCII 2.2 or 4.1");
  t.expect("$EndMeshFormat");
  GmshReader r{t, {}, {}, {}};
  bool have_nodes = false;
  std::string tok;
  while (t.next(&tok)) {
    if (tok == "$Nodes") {
      have_nodes = true;
      version == 2.2 ? r.nodes22() : r.nodes41();
      t.expect("$EndNodes");
    } else if (tok == "$Elements") {
      if (!have_nodes) fail(t.where() + ": $Elements before $Nodes");
      version == 2.2 ? r.elements22() : r.elements41();
      t.expect("$EndElements");
    } else if (!tok.empty() && tok[0] == '$' && tok.rfind("$End", 0) != 0) {
      const std::string end = "$End" + tok.substr(1); // skip an unknown section
      while (t.token(end.c_str()) != end) {
      }
    } else {
      fail(t.where() + ": unexpected '" + tok.substr(0, 40) + "'");
    }
  }
  if (r.tets.empty()) fail(name + ": no tetrahedra (Gmsh types 4 or 11) in the file");
  r.mesh.nodes_per_elem = r.p2 ? 10 : 4;
  r.mesh.elems = std::move(r.tets);
  return std::move(r.mesh);
}

namespace {
// The banner "%%MatrixMarket matrix coordinate <field> <symmetry>" (case-insensitive) into info; line: its text.
void parseMatrixMarketBanner(std::istringstream& in, const std::string& name, std::string& line,
                             MatrixMarketInfo* info) {
  std::string banner, object, format;
  if (!std::getline(in, line)) fail(name + ": empty file");
  {
    std::istringstream s(line);
    s >> banner >> object >> format >> info->field >> info->symmetry;
    for (auto* w : {&object, &format, &info->field, &info->symmetry})
      std::transform(w->begin(), w->end(), w->begin(), [](unsigned char c) { return (char)std::tolower(c); });
  }
  if (!(banner == "%%MatrixMarket" && object == "matrix" && format == "coordinate"))
    fail(name + " line 1: not a Matrix Market coordinate matrix ('" + line.substr(0, 80) + "')");
  if (!(info->field == "real" || info->field == "integer" || info->field == "pattern"))
    fail(name + ": field '" + info->field.substr(0, 40) + "' not supported (real|integer|pattern)");
  if (!(info->symmetry == "symmetric" || info->symmetry == "general"))
    fail(name + ": symmetry '" + info->symmetry.substr(0, 40) + "' not supported (symmetric|general)");
}

// After the comments, the size line "rows cols entries" (a square matrix, sizes a file of `bytes` can hold);
// returns its line number.
int parseMatrixMarketSize(std::istringstream& in, const std::string& name, long long bytes, std::string& line,
                          MatrixMarketInfo* info) {
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line[0] != '%') break;
  }
  {
    std::istringstream s(line);
    if (!((s >> info->rows >> info->cols >> info->entries) && info->rows > 0 && info->rows == info->cols &&
          info->entries >= 0))
      fail(name + " line " + std::to_string(lineno) + ": bad size line '" + line.substr(0, 80) +
           "' (need a square matrix)");
  }
  // Hostile sizes: every entry takes >= 4 bytes of the file; the order n is bounded by the file size too
  // (a Matrix Market file of order n describes n columns: we allocate O(n + entries)).
  if (info->entries > bytes / 4 || info->rows > 64 * bytes + 1024 || info->rows > (1LL << 31) - 2)
    fail(name + " line " + std::to_string(lineno) + ": size line claims " + std::to_string(info->rows) +
         " rows and " + std::to_string(info->entries) + " entries, more than a " + std::to_string(bytes) +
         "-byte file can hold");
  return lineno;
}

struct MatrixMarketEntry {
  int col, row;
  double v;
  bool upper_given; // value from an upper (or symmetric) entry
};

// The structural diagonal, then the entries as (column, row) of the upper triangle.
std::vector<MatrixMarketEntry> parseMatrixMarketEntries(std::istringstream& in, const std::string& name,
                                                        int lineno, std::string& line,
                                                        const MatrixMarketInfo& info) {
  const int n = static_cast<int>(info.rows);
  const bool pattern = info.field == "pattern";
  std::vector<MatrixMarketEntry> ent;
  ent.reserve(static_cast<size_t>(info.entries) + n);
  for (int c = 0; c < n; ++c) ent.push_back({c, c, 0.0, false}); // structural diagonal
  for (long long k = 0; k < info.entries; ++k) {
    if (!std::getline(in, line))
      fail(name + ": truncated after line " + std::to_string(lineno) + " (" + std::to_string(k) + " of " +
           std::to_string(info.entries) + " entries)");
    ++lineno;
    std::istringstream s(line);
    long long i, j;
    double v = 1.0;
    if (!((s >> i >> j) && (pattern || (s >> v))) || !std::isfinite(v))
      fail(name + " line " + std::to_string(lineno) + ": malformed entry '" + line.substr(0, 80) + "'");
    if (!(i >= 1 && i <= n && j >= 1 && j <= n))
      fail(name + " line " + std::to_string(lineno) + ": index (" + std::to_string(i) + ", " +
           std::to_string(j) + ") outside 1.." + std::to_string(n));
    const int r = static_cast<int>(std::min(i, j)) - 1, c = static_cast<int>(std::max(i, j)) - 1;
    const bool upper = !(info.symmetry == "general" && i > j); // general lower entry: pattern of A^T only
    ent.push_back({c, r, upper ? v : 0.0, upper});
  }
  return ent;
}

// Sort by (column, row); duplicates: the last given upper value wins (as the map-based reader did).
SymCsc matrixMarketCsc(std::vector<MatrixMarketEntry>& ent, int n) {
  std::stable_sort(ent.begin(), ent.end(), [](const MatrixMarketEntry& a, const MatrixMarketEntry& b) {
    return a.col != b.col ? a.col < b.col : a.row < b.row;
  });
  SymCsc A;
  A.n = n;
  A.colptr.assign(n + 1, 0);
  for (size_t k = 0; k < ent.size();) {
    size_t e = k;
    double v = 0.0;
    while (e < ent.size() && ent[e].col == ent[k].col && ent[e].row == ent[k].row) {
      if (ent[e].upper_given) v = ent[e].v;
      ++e;
    }
    A.rowind.push_back(ent[k].row);
    A.val.push_back(v);
    ++A.colptr[ent[k].col + 1];
    k = e;
  }
  for (int c = 0; c < n; ++c) A.colptr[c + 1] += A.colptr[c];
  return A;
}
} // namespace

SymCsc parseMatrixMarket(const std::string& content, const std::string& name, MatrixMarketInfo* info) {
  std::istringstream in(content);
  std::string line;
  parseMatrixMarketBanner(in, name, line, info);
  const int lineno = parseMatrixMarketSize(in, name, static_cast<long long>(content.size()), line, info);
  std::vector<MatrixMarketEntry> ent = parseMatrixMarketEntries(in, name, lineno, line, *info);
  return matrixMarketCsc(ent, static_cast<int>(info->rows));
}

} // namespace suite::fem
