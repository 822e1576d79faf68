// femdyn -backend plex: the supports and the surface loads from the options, by group (fem/plex_groups.hpp).
//   -bc_fixed G1,G2     every displacement component of these surface groups zero;
//   -bc_displacement G:ux=a,uz=b[;G2:...]   components held at values (any subset: rollers, symmetry planes,
//                       driven faces), scaled in time by the -bc_ramp load factor;
//   -dirichlet x=0      without -bc_fixed and -bc_displacement: the group "clamped", or when the mesh has none, the boundary faces
//                       on the plane x = 0 (the generated beam's "clamped"); -dirichlet none: no clamp;
//   -traction G:tx,ty,tz[;G2:...]   dead traction per area;
//   -tip_load P         total force P along -y on the group "tip", or when the mesh has none, on the boundary
//                       faces on the plane x = max (the generated beam's "tip").
// The tip deflection reported is the mean -u_y over the vertices of "tip" (the same fallback).
#include "femdyn_plex.hpp"

#include "fem/plex_groups.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace femdyn_app {

using namespace suite::fem;

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  size_t a = 0;
  while (true) {
    const size_t b = s.find(sep, a);
    out.push_back(s.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return out;
}

bool parseVector(const std::string& s, double v[3]) {
  const auto parts = split(s, ',');
  if (parts.size() != 3) return false;
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(parts[i].c_str(), &end);
    if (parts[i].empty() || *end != '\0' || !std::isfinite(v[i])) return false;
  }
  return true;
}

// "ux=a,uz=b": the components held and their values.
bool parseComponents(const std::string& s, PlexPrescribed* p) {
  for (int c = 0; c < 3; ++c) p->comp[c] = false, p->value[c] = 0.0;
  for (const std::string& a : split(s, ',')) {
    const size_t eq = a.find('=');
    if (eq != 2 || a[0] != 'u' || a[1] < 'x' || a[1] > 'z') return false;
    const int c = a[1] - 'x';
    char* end = nullptr;
    const std::string v = a.substr(eq + 1);
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x) || p->comp[c]) return false;
    p->comp[c] = true, p->value[c] = x;
  }
  return true;
}

// The group `name`, or when the mesh has none, a new group of the boundary faces on the plane x = x0.
PetscErrorCode groupOrPlane(DM dm, const char* name, double x0, double tol, const char* option,
                            PlexGroup* g) {
  bool has = false;
  PetscFunctionBeginUser;
  PetscCall(hasGroup(dm, name, &has));
  if (!has) PetscCall(markPlaneFaces(dm, name, x0, tol));
  PetscCall(findGroup(dm, name, 2, option, g));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode plexSupportsAndLoads(DM dm, const Options& o, PlexModelGroups* m) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscBool dirichlet_set = PETSC_FALSE;
  double xmax;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-dirichlet", &dirichlet_set));
  const bool by_group = !o.bc_fixed.empty() || !o.bc_displacement.empty();
  PetscCheck(!by_group || !dirichlet_set, comm, PETSC_ERR_ARG_INCOMP,
             "-dirichlet %s with -bc_fixed or -bc_displacement: give one of them (these name the supports by "
             "group)",
             o.dirichlet.c_str());
  PetscCheck(o.dirichlet == "x=0" || o.dirichlet == "none", comm, PETSC_ERR_SUP,
             "-dirichlet %s: -backend plex clamps x=0 or none (other supports: -bc_fixed GROUP)",
             o.dirichlet.c_str());
  PetscCall(meshMaxX(dm, &xmax));
  const double tol = 1e-9 * std::max(1.0, std::abs(xmax));
  m->held.clear();
  m->loads.clear();
  std::vector<PlexGroup> groups;
  PetscCall(listGroups(dm, &groups));
  if (by_group) {
    if (!o.bc_fixed.empty())
      for (const std::string& name : split(o.bc_fixed, ',')) {
        PlexPrescribed p;
        PetscCall(findGroupIn(comm, groups, name, 2, "-bc_fixed", &p.group));
        const bool again = std::any_of(m->held.begin(), m->held.end(), [&](const PlexPrescribed& f) {
          return f.group.name == p.group.name && f.group.value == p.group.value;
        });
        if (!again) m->held.push_back(p); // a group named twice (by name and by tag) is fixed once
      }
    if (!o.bc_displacement.empty())
      for (const std::string& item : split(o.bc_displacement, ';')) {
        const size_t colon = item.rfind(':');
        PlexPrescribed p;
        PetscCheck(colon != std::string::npos && parseComponents(item.substr(colon + 1), &p), comm,
                   PETSC_ERR_ARG_WRONG,
                   "-bc_displacement %s: expected GROUP:ux=a,uy=b,uz=c (any subset, each once, finite "
                   "values; several: ';')",
                   item.c_str());
        PetscCall(findGroupIn(comm, groups, item.substr(0, colon), 2, "-bc_displacement", &p.group));
        m->held.push_back(p);
      }
  } else if (o.dirichlet == "x=0") {
    PlexPrescribed p;
    PetscCall(groupOrPlane(dm, "clamped", 0.0, tol, "-dirichlet x=0", &p.group));
    std::vector<PetscInt> faces;
    PetscCall(groupFaces(dm, p.group, &faces));
    long long n = (long long)faces.size(), all = 0;
    PetscCallMPI(MPI_Allreduce(&n, &all, 1, MPI_LONG_LONG, MPI_SUM, comm));
    PetscCheck(all > 0, comm, PETSC_ERR_ARG_WRONG,
               "-dirichlet x=0: the mesh has no group clamped and no boundary face on the plane x = 0 (name "
               "the supports with -bc_fixed GROUP)");
    m->held.push_back(p);
  }
  PetscCall(groupOrPlane(dm, "tip", xmax, tol, "-tip_load", &m->tip));
  if (o.tip_load != 0.0) {
    PlexSurfaceLoad l;
    l.group = m->tip, l.total = true, l.value[1] = -o.tip_load;
    m->loads.push_back(l);
  }
  PetscCall(listGroups(dm, &groups)); // with the groups the clamp and the tip load may have made
  if (!o.traction.empty())
    for (const std::string& item : split(o.traction, ';')) {
      const size_t colon = item.rfind(':');
      PlexSurfaceLoad l;
      PetscCheck(colon != std::string::npos && parseVector(item.substr(colon + 1), l.value), comm,
                 PETSC_ERR_ARG_WRONG, "-traction %s: expected GROUP:tx,ty,tz (finite numbers; several: ';')",
                 item.c_str());
      PetscCall(findGroupIn(comm, groups, item.substr(0, colon), 2, "-traction", &l.group));
      m->loads.push_back(l);
    }
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
