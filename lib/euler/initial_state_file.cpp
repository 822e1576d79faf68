// An Euler initial state from an HDF5 file (see initial_state_file.hpp).
#include "euler/initial_state_file.hpp"

#include "core/error_handler.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace suite::euler {

namespace {
const char* const kAxisName[3] = {"x", "y", "z"};

std::vector<std::string> primitiveNames(int dim) {
  if (dim == 1) return {"rho", "u", "p"};
  if (dim == 2) return {"rho", "u", "v", "p"};
  return {"rho", "u", "v", "w", "p"};
}
std::vector<std::string> conservativeNames(int dim) {
  if (dim == 1) return {"rho", "mom_x", "E"};
  if (dim == 2) return {"rho", "mom_x", "mom_y", "E"};
  return {"rho", "mom_x", "mom_y", "mom_z", "E"};
}
bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : " ") + s;
  return out;
}
std::string dataset(const InitialStateFile& f, const std::string& name) {
  return (f.group == "/" ? std::string("/") : f.group + "/") + name;
}

// The datasets of the group: one complete set, nothing foreign.
PetscErrorCode chooseFields(MPI_Comm comm, const suite::H5Input& in, int dim, InitialStateFile* f) {
  std::vector<std::string> members;
  PetscFunctionBeginUser;
  PetscCall(in.groupMembers(f->group, &members));
  const std::vector<std::string> prim = primitiveNames(dim), cons = conservativeNames(dim);
  const std::vector<std::string> ignored = {"shock", "mask"};
  bool any_prim = false, any_cons = false;
  for (const std::string& m : members) {
    const bool p = contains(prim, m) && m != "rho", c = contains(cons, m) && m != "rho";
    const bool w2 = dim == 2 && m == "w";
    any_prim = any_prim || p || w2;
    any_cons = any_cons || c;
    PetscCheck(p || c || w2 || m == "rho" || contains(ignored, m), comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: dataset %s is not part of a %dD initial state (primitive: %s; conservative: %s)",
               f->path.c_str(), dataset(*f, m).c_str(), dim, joined(prim).c_str(), joined(cons).c_str());
  }
  PetscCheck(!(any_prim && any_cons), comm, PETSC_ERR_FILE_UNEXPECTED,
             "%s: group %s mixes primitive (%s) and conservative (%s) datasets: give one set",
             f->path.c_str(), f->group.c_str(), joined(prim).c_str(), joined(cons).c_str());
  f->conservative = any_cons;
  f->fields = any_cons ? cons : prim;
  f->zero_w = dim == 2 && contains(members, "w");
  for (const std::string& name : f->fields)
    PetscCheck(contains(members, name), comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: missing dataset %s of the %s %dD initial state (%s)", f->path.c_str(),
               dataset(*f, name).c_str(), f->conservative ? "conservative" : "primitive", dim,
               joined(f->fields).c_str());
  PetscFunctionReturn(0);
}

// Every dataset (the state's and w) of shape (z, y, x) with dim entries, all equal: the grid.
PetscErrorCode readShape(MPI_Comm comm, const suite::H5Input& in, int dim, InitialStateFile* f) {
  suite::Dims first;
  PetscFunctionBeginUser;
  std::vector<std::string> names = f->fields;
  if (f->zero_w) names.push_back("w");
  for (size_t i = 0; i < names.size(); ++i) {
    suite::Dims d;
    PetscCall(in.datasetDims(dataset(*f, names[i]), &d));
    PetscCheck((int)d.size() == dim, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: dataset %s has %d dimensions; a %dD initial state has %d ((z,) (y,) x order)",
               f->path.c_str(), dataset(*f, names[i]).c_str(), (int)d.size(), dim, dim);
    if (i == 0) first = d;
    PetscCheck(d == first, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s has another shape than %s",
               f->path.c_str(), dataset(*f, names[i]).c_str(), dataset(*f, names[0]).c_str());
    PetscCall(in.checkPlausibleSize(dataset(*f, names[i]), d, sizeof(double)));
  }
  for (int a = 0; a < dim; ++a) {
    const unsigned long long na = first[dim - 1 - a];
    PetscCheck(na >= 1 && na <= (unsigned long long)PETSC_MAX_INT, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s: %llu cells along %s do not fit a PetscInt", f->path.c_str(), na, kAxisName[a]);
    f->n[a] = (PetscInt)na;
  }
  PetscFunctionReturn(0);
}

// Extent attributes xmin/xmax ... on the group, else on the root; both ends or neither.
PetscErrorCode readExtents(MPI_Comm comm, const suite::H5Input& in, int dim, InitialStateFile* f) {
  PetscFunctionBeginUser;
  for (int a = 0; a < dim; ++a) {
    const std::string lo = std::string(kAxisName[a]) + "min", hi = std::string(kAxisName[a]) + "max";
    for (const std::string& obj : {f->group, std::string("/")}) {
      bool has_lo = false, has_hi = false;
      PetscCall(in.hasAttribute(obj, lo, &has_lo));
      PetscCall(in.hasAttribute(obj, hi, &has_hi));
      PetscCheck(has_lo == has_hi, comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %s carries attribute %s without %s",
                 f->path.c_str(), obj.c_str(), (has_lo ? lo : hi).c_str(), (has_lo ? hi : lo).c_str());
      if (!has_lo) continue;
      PetscCall(in.readAttribute(obj, lo, &f->lo[a]));
      PetscCall(in.readAttribute(obj, hi, &f->hi[a]));
      PetscCheck(std::isfinite(f->lo[a]) && std::isfinite(f->hi[a]) && f->hi[a] > f->lo[a], comm,
                 PETSC_ERR_FILE_UNEXPECTED, "%s: invalid extent %s %g, %s %g on %s", f->path.c_str(),
                 lo.c_str(), f->lo[a], hi.c_str(), f->hi[a], obj.c_str());
      f->has_extent[a] = true;
      break;
    }
  }
  PetscFunctionReturn(0);
}

// The first invalid value of this rank's block (values: ncomp per cell), as a message naming dataset and cell.
std::string firstInvalid(const InitialStateFile& f, int dim, double gamma, const PetscInt s[3],
                         const PetscInt m[3], const std::vector<double>& v, const std::vector<double>& w) {
  const int nc = dim + 2;
  const size_t ncell = (size_t)m[0] * m[1] * m[2];
  auto message = [&](size_t c, const std::string& name, double value, const char* why) {
    const PetscInt i = s[0] + (PetscInt)(c % m[0]), j = s[1] + (PetscInt)((c / m[0]) % m[1]),
                   k = s[2] + (PetscInt)(c / ((size_t)m[0] * m[1]));
    char cell[96], buf[512];
    if (dim == 1)
      std::snprintf(cell, sizeof cell, "cell i = %d", (int)i);
    else if (dim == 2)
      std::snprintf(cell, sizeof cell, "cell (i, j) = (%d, %d)", (int)i, (int)j);
    else
      std::snprintf(cell, sizeof cell, "cell (i, j, k) = (%d, %d, %d)", (int)i, (int)j, (int)k);
    std::snprintf(buf, sizeof buf, "%s: dataset %s holds %g at %s: %s", f.path.c_str(),
                  dataset(f, name).c_str(), value, cell, why);
    return std::string(buf);
  };
  for (size_t c = 0; c < ncell; ++c) {
    const double* q = &v[c * nc];
    for (int comp = 0; comp < nc; ++comp)
      if (!std::isfinite(q[comp]))
        return message(c, f.fields[comp], q[comp], "initial values must be finite");
    if (!w.empty() && w[c] != 0.0) return message(c, "w", w[c], "a 2D state has w = 0");
    double p = q[nc - 1];
    if (f.conservative) {
      double ke = 0.0;
      for (int d = 0; d < dim; ++d) ke += 0.5 * q[1 + d] * q[1 + d] / q[0];
      p = (gamma - 1.0) * (q[nc - 1] - ke);
    }
    if (q[0] <= 0.0) return message(c, "rho", q[0], "density must be > 0");
    if (p <= 0.0)
      return message(c, f.fields[nc - 1], q[nc - 1],
                     f.conservative ? "pressure must be > 0 (the pressure of rho, mom, E is not)"
                                    : "pressure must be > 0");
  }
  return "";
}
} // namespace

PetscErrorCode inspectInitialStateFile(MPI_Comm comm, const std::string& path, const std::string& group,
                                       int dim, InitialStateFile* f) {
  suite::H5Input in;
  PetscFunctionBeginUser;
  *f = InitialStateFile{};
  f->path = path;
  f->group = group.empty() ? "/" : group;
  PetscCall(in.open(comm, path));
  PetscCall(chooseFields(comm, in, dim, f));
  PetscCall(readShape(comm, in, dim, f));
  PetscCall(readExtents(comm, in, dim, f));
  PetscCall(in.hasAttribute("/", "gamma", &f->has_gamma));
  if (f->has_gamma) PetscCall(in.readAttribute("/", "gamma", &f->gamma));
  PetscFunctionReturn(0);
}

PetscErrorCode readInitialStateBlock(MPI_Comm comm, const InitialStateFile& f, int dim, double gamma,
                                     const PetscInt s[3], const PetscInt m[3], std::vector<double>* values) {
  suite::H5Input in;
  suite::Dims start, count;
  PetscFunctionBeginUser;
  for (int a = dim - 1; a >= 0; --a) { // (z,) (y,) x
    start.push_back((unsigned long long)s[a]);
    count.push_back((unsigned long long)m[a]);
  }
  const int nc = dim + 2;
  const size_t ncell = (size_t)m[0] * m[1] * m[2];
  std::vector<double> one(ncell), w;
  values->assign(ncell * nc, 0.0);
  PetscCall(in.open(comm, f.path));
  for (int comp = 0; comp < nc; ++comp) {
    PetscCall(in.readBlock(dataset(f, f.fields[comp]), start, count, one.data()));
    for (size_t c = 0; c < ncell; ++c) (*values)[c * nc + comp] = one[c];
  }
  if (f.zero_w) {
    w.resize(ncell);
    PetscCall(in.readBlock(dataset(f, "w"), start, count, w.data()));
  }
  std::string message = firstInvalid(f, dim, gamma, s, m, *values, w);
  PetscCall(suite::agreeOnFailure(comm, &message));
  PetscCheck(message.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "%s", message.c_str());
  PetscFunctionReturn(0);
}

} // namespace suite::euler
