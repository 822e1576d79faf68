// femdyn -backend plex: the output file and the checkpoints, written collectively in the natural node numbering
// (each rank its block of rows: fem/plex_natural.hpp), so that a checkpoint written at P ranks restarts at Q.
// Output: the run's attributes (tip_deflection, sizes, peak resident memory), /steps (replicated, rank 0),
// /partition/{cells,points} (one row per rank), /mesh/coordinates, /mesh/tets (natural node numbers; each rank
// its cells), /final/u, and the XDMF sidecar. Checkpoint: the same attributes with the step, /steps so far and
// /state/{u,v,a}; on restart the model's attributes must match (else an error naming the attribute).
#include "femdyn_plex.hpp"

#include "core/log.hpp"
#include "io/h5_input.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <sys/resource.h>

#include <cmath>
#include <string>
#include <utility>

namespace femdyn_app {

namespace {

using ull = unsigned long long;

double peakRssGiB() { // getrusage: kilobytes on Linux
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / (1024.0 * 1024.0);
}

std::string beamCells(const Options& o) {
  const auto& c = o.beam.cells;
  return std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]);
}

// The attributes a checkpoint must share with the run that restarts from it.
struct ModelAttr {
  const char* name;
  double value;
};

// The model's text attributes: the mesh (beam or the file's path) and the supports and loads by group.
std::vector<std::pair<const char*, std::string>> modelStrings(const Options& o) {
  return {{"mesh", o.mesh == "beam" ? std::string("beam") : o.mesh_file},
          {"dirichlet", o.dirichlet},
          {"bc_fixed", o.bc_fixed},
          {"traction", o.traction},
          {"bc_displacement", o.bc_displacement}};
}

std::vector<ModelAttr> modelAttributes(const Options& o) {
  return {{"beam_length", o.beam.length},
          {"beam_size_y", o.beam.size[0]},
          {"beam_size_z", o.beam.size[1]},
          {"young", o.young},
          {"poisson", o.poisson},
          {"density", o.density},
          {"tip_load", o.tip_load},
          {"dt", o.dt},
          {"newmark_beta", o.newmark.beta},
          {"newmark_gamma", o.newmark.gamma},
          {"bc_ramp", o.bc_ramp},
          {"alpha_m", o.newmark.alpha_m},
          {"alpha_f", o.newmark.alpha_f},
          {"rayleigh_alpha", o.newmark.rayleigh_mass},
          {"rayleigh_beta", o.newmark.rayleigh_stiffness}};
}

} // namespace

PetscErrorCode PlexRun::writeRunAttributes(suite::H5Output& out) const {
  MPI_Comm comm = ctx_.comm();
  double rss = peakRssGiB(), rss_max = 0, rss_sum = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&rss, &rss_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&rss, &rss_sum, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscCall(out.writeProvenance(ctx_));
  PetscCall(out.writeAttribute("/", "status", status_));
  PetscCall(out.writeAttribute("/", "mode", o_.is_static ? "static" : "dynamic"));
  PetscCall(out.writeAttribute("/", "backend", "plex"));
  PetscCall(out.writeAttribute("/", "material", o_.material));
  PetscCall(out.writeAttribute("/", "beam_cells", beamCells(o_)));
  for (const auto& a : modelStrings(o_)) PetscCall(out.writeAttribute("/", a.first, a.second));
  for (const auto& a : modelAttributes(o_)) PetscCall(out.writeAttribute("/", a.name, a.value));
  PetscCall(out.writeAttribute("/", "nodes", nv_));
  PetscCall(out.writeAttribute("/", "elements", nc_));
  PetscCall(out.writeAttribute("/", "dofs", (long long)ndof_));
  PetscCall(out.writeAttribute("/", "tip_deflection", tip_));
  PetscCall(out.writeAttribute("/", "tip_ux", tip_ux_));
  PetscCall(out.writeAttribute("/", "setup_seconds", setup_s_));
  PetscCall(out.writeAttribute("/", "solve_seconds", solve_s_));
  PetscCall(out.writeAttribute("/", "peak_rss_gib_max_rank", rss_max));
  PetscCall(out.writeAttribute("/", "peak_rss_gib_sum", rss_sum));
  PetscFunctionReturn(0);
}

// /steps columns (rank 0 writes them: every rank holds the same history).
PetscErrorCode PlexRun::writeHistory(suite::H5Output& out) const {
  const struct {
    const char* name;
    double PlexStep::*f;
    const char* units;
  } reals[] = {{"time", &PlexStep::time, "s"},
               {"tip_deflection", &PlexStep::tip, "m"},
               {"wall", &PlexStep::wall, "s"},
               {"cpu", &PlexStep::cpu, "s"},
               {"kinetic_energy", &PlexStep::kinetic, "J"},
               {"strain_energy", &PlexStep::strain, "J"}};
  const struct {
    const char* name;
    long long PlexStep::*f;
  } counts[] = {{"newton_iterations", &PlexStep::newton}, {"linear_iterations", &PlexStep::linear}};
  PetscFunctionBeginUser;
  for (const auto& c : reals) {
    std::vector<double> v;
    for (const auto& s : steps_) v.push_back(s.*c.f);
    PetscCall(out.writeReplicated(std::string("/steps/") + c.name, v.data(), {(ull)v.size()}, c.units));
  }
  for (const auto& c : counts) {
    std::vector<long long> v;
    for (const auto& s : steps_) v.push_back(s.*c.f);
    PetscCall(out.writeReplicated(std::string("/steps/") + c.name, v.data(), {(ull)v.size()}, ""));
  }
  PetscCall(out.writeAttribute("/", "steps", (long long)steps_.size()));
  PetscFunctionReturn(0);
}

// A distributed vector of the DM as a {nodes, 3} dataset in the natural numbering.
PetscErrorCode PlexRun::writeNatural(suite::H5Output& out, const char* dataset, Vec plex,
                                     const std::vector<double>* held) const {
  Vec nat;
  const PetscScalar* x;
  PetscFunctionBeginUser;
  PetscCall(nat_.createNatural(&nat));
  PetscCall(nat_.toNatural(plex, nat));
  if (held) {
    const auto& h = nm_.prescribed();
    PetscCall(nat_.setHeld(nat, h.vertices(), h.components(), *held));
  }
  PetscCall(VecGetArrayRead(nat, &x));
  std::vector<double> v(x, x + 3 * nat_.rows());
  PetscCall(VecRestoreArrayRead(nat, &x));
  PetscCall(VecDestroy(&nat));
  PetscCall(out.writeDistributed(dataset, v.data(), {(ull)nat_.nodes(), 3}, {(ull)nat_.row0(), 0},
                                 {(ull)nat_.rows(), 3}, "m"));
  PetscFunctionReturn(0);
}

// Coordinates of this rank's block of natural nodes; its cells' corners as natural nodes; one row per rank of
// /partition.
PetscErrorCode PlexRun::writeMesh(suite::H5Output& out) const {
  PetscInt c0, c1, p0, p1, v0, v1;
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  std::vector<double> xyz;
  PetscCall(nat_.coordinates(&xyz));
  PetscCall(DMPlexGetHeightStratum(dm_, 0, &c0, &c1));
  PetscCall(DMPlexGetChart(dm_, &p0, &p1));
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &v0, &v1));
  std::vector<int> tets; // int: the XDMF sidecar's Int items and the replicated path's /mesh/tets
  for (PetscInt c = c0; c < c1; ++c) {
    PetscInt n = 0, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm_, c, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < 2 * n; i += 2)
      if (pts[i] >= v0 && pts[i] < v1) tets.push_back((int)nat_.vertexNode(pts[i]));
    PetscCall(DMPlexRestoreTransitiveClosure(dm_, c, PETSC_TRUE, &n, &pts));
  }
  ull ncl = (ull)(c1 - c0), cstart = 0;
  PetscCallMPI(MPI_Exscan(&ncl, &cstart, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  if (ctx_.rank() == 0) cstart = 0;
  const long long part[2] = {(long long)ncl, (long long)(p1 - p0)};
  const ull rank = (ull)ctx_.rank(), size = (ull)ctx_.size();
  PetscCall(out.writeDistributed("/mesh/coordinates", xyz.data(), {(ull)nat_.nodes(), 3},
                                 {(ull)nat_.row0(), 0}, {(ull)nat_.rows(), 3}, "m"));
  PetscCall(out.writeDistributed("/mesh/tets", tets.data(), {(ull)nc_, 4}, {cstart, 0}, {ncl, 4}, ""));
  PetscCall(out.writeDistributed("/partition/cells", &part[0], {size}, {rank}, {1}, ""));
  PetscCall(out.writeDistributed("/partition/points", &part[1], {size}, {rank}, {1}, ""));
  PetscFunctionReturn(0);
}

// One value per local cell as a {cells} dataset in the order of /mesh/tets (rank by rank).
PetscErrorCode PlexRun::writeCells(suite::H5Output& out, const char* dataset,
                                   const std::vector<double>& values) const {
  ull n = values.size(), start = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Exscan(&n, &start, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, ctx_.comm()));
  if (ctx_.rank() == 0) start = 0;
  PetscCall(out.writeDistributed(dataset, values.data(), {(ull)nc_}, {start}, {n}, "Pa"));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::snapshot() {
  char u[64], vm[64];
  std::vector<double> stress;
  PetscFunctionBeginUser;
  if (o_.output.empty()) PetscFunctionReturn(0);
  if (!out_) {
    out_ = std::make_unique<suite::H5Output>();
    PetscCall(out_->open(ctx_.comm(), o_.output));
  }
  const long long k = (long long)xsteps_.size();
  PetscCall(PetscSNPrintf(u, sizeof u, "/snapshots/%06lld/u", k));
  PetscCall(PetscSNPrintf(vm, sizeof vm, "/snapshots/%06lld/von_mises", k));
  PetscCall(writeNatural(*out_, u, nm_.displacement(), &nm_.heldDisplacement()));
  PetscCall(nm_.vonMises(&stress));
  PetscCall(writeCells(*out_, vm, stress));
  xsteps_.push_back({nm_.time(), {{"displacement", u, 3, false}, {"von_mises", vm, 1, true}}});
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::write() {
  suite::H5Output local;
  std::vector<double> stress;
  PetscFunctionBeginUser;
  if (o_.output.empty()) PetscFunctionReturn(0); // no -output: nothing written
  suite::H5Output& out = out_ ? *out_ : local;
  if (!out_) PetscCall(out.open(ctx_.comm(), o_.output));
  PetscCall(writeRunAttributes(out));
  if (o_.is_static)
    PetscCall(out.writeAttribute("/", "newton_iterations", (long long)stat_.newton_iterations));
  else
    PetscCall(writeHistory(out));
  PetscCall(writeMesh(out));
  PetscCall(writeNatural(out, "/final/u", nm_.displacement(), &nm_.heldDisplacement()));
  PetscCall(nm_.vonMises(&stress));
  PetscCall(writeCells(out, "/final/von_mises", stress));
  PetscCall(out.commit(&ctx_));
  const double t = steps_.empty() ? 0.0 : steps_.back().time;
  suite::XdmfTetMesh xm{"/mesh/coordinates", "/mesh/tets", (ull)nv_, (ull)nc_};
  std::vector<suite::XdmfTetStep> series = xsteps_;
  if (series.empty())
    series.push_back(
        {t, {{"displacement", "/final/u", 3, false}, {"von_mises", "/final/von_mises", 1, true}}});
  PetscCall(suite::writeXdmfTetSeries(ctx_.comm(), suite::xdmfPathFor(o_.output),
                                      suite::fileNameOf(o_.output), xm, series));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::writeCheckpoint(long long step) {
  suite::H5Output out;
  const std::string path = policy_.pathForStep(step);
  PetscFunctionBeginUser;
  PetscCall(out.open(ctx_.comm(), path));
  PetscCall(writeRunAttributes(out));
  PetscCall(out.writeAttribute("/", "time", nm_.time()));
  PetscCall(writeHistory(out));
  PetscCall(writeNatural(out, "/state/u", nm_.displacement(), &nm_.heldDisplacement()));
  PetscCall(writeNatural(out, "/state/v", nm_.velocity()));
  PetscCall(writeNatural(out, "/state/a", nm_.acceleration()));
  PetscCall(out.commit(&ctx_));
  PetscCall(policy_.written(step));
  PetscFunctionReturn(0);
}

// This rank's block of a {nodes, 3} dataset into a distributed vector of the DM.
PetscErrorCode PlexRun::readNatural(const suite::H5Input& in, const char* dataset, Vec plex) const {
  Vec nat;
  PetscScalar* x;
  suite::Dims dims;
  PetscFunctionBeginUser;
  PetscCall(in.datasetDims(dataset, &dims));
  PetscCheck(dims.size() == 2 && dims[0] == (ull)nat_.nodes() && dims[1] == 3, ctx_.comm(),
             PETSC_ERR_FILE_UNEXPECTED, "restart %s: %s is not a {%lld, 3} array", in.path().c_str(), dataset,
             nat_.nodes());
  std::vector<double> v(3 * nat_.rows());
  PetscCall(in.readBlock(dataset, {(ull)nat_.row0(), 0}, {(ull)nat_.rows(), 3}, v.data()));
  PetscCall(nat_.createNatural(&nat));
  PetscCall(VecGetArray(nat, &x));
  for (size_t i = 0; i < v.size(); ++i) x[i] = v[i];
  PetscCall(VecRestoreArray(nat, &x));
  PetscCall(nat_.fromNatural(nat, plex));
  PetscCall(VecDestroy(&nat));
  PetscFunctionReturn(0);
}

// The history of the first `step` steps (every rank reads it: a few numbers per step).
PetscErrorCode PlexRun::readHistory(const suite::H5Input& in, long long step) {
  std::vector<double> t, tip, wall, cpu, ek, es;
  std::vector<long long> nw, li;
  suite::Dims d;
  PetscFunctionBeginUser;
  PetscCall(in.readAll("/steps/time", &t, &d));
  PetscCall(in.readAll("/steps/tip_deflection", &tip, &d));
  PetscCall(in.readAll("/steps/wall", &wall, &d));
  PetscCall(in.readAll("/steps/cpu", &cpu, &d));
  PetscCall(in.readAll("/steps/kinetic_energy", &ek, &d));
  PetscCall(in.readAll("/steps/strain_energy", &es, &d));
  PetscCall(in.readAll("/steps/newton_iterations", &nw, &d));
  PetscCall(in.readAll("/steps/linear_iterations", &li, &d));
  const size_t n = (size_t)step;
  PetscCheck(t.size() == n && tip.size() == n && wall.size() == n && cpu.size() == n && ek.size() == n &&
                 es.size() == n && nw.size() == n && li.size() == n,
             ctx_.comm(), PETSC_ERR_FILE_UNEXPECTED, "restart %s: /steps does not hold %lld steps",
             in.path().c_str(), step);
  steps_.clear();
  for (size_t i = 0; i < n; ++i)
    steps_.push_back({t[i], tip[i], wall[i], cpu[i], ek[i], es[i], nw[i], li[i]});
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::readCheckpoint(const std::string& path) {
  suite::H5Input in;
  std::string s;
  long long step = 0;
  double time = 0;
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(in.readAttribute("/", "backend", &s));
  PetscCheck(s == "plex", comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: written by -backend %s, not plex",
             path.c_str(), s.c_str());
  PetscCall(in.readAttribute("/", "material", &s));
  PetscCheck(s == o_.material, comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: material %s, this run %s",
             path.c_str(), s.c_str(), o_.material.c_str());
  PetscCall(in.readAttribute("/", "beam_cells", &s));
  PetscCheck(s == beamCells(o_), comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: -beam_cells %s, this run %s",
             path.c_str(), s.c_str(), beamCells(o_).c_str());
  for (const auto& a : modelStrings(o_)) {
    PetscCall(in.readAttribute("/", a.first, &s));
    PetscCheck(s == a.second, comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: %s %s, this run %s", path.c_str(),
               a.first, s.c_str(), a.second.c_str());
  }
  for (const auto& a : modelAttributes(o_)) {
    double v;
    PetscCall(in.readAttribute("/", a.name, &v));
    PetscCheck(v == a.value, comm, PETSC_ERR_FILE_UNEXPECTED, "restart %s: %s %g, this run %g", path.c_str(),
               a.name, v, a.value);
  }
  PetscCall(in.readAttribute("/", "steps", &step));
  PetscCall(in.readAttribute("/", "time", &time));
  PetscCheck(step >= 0 && step <= o_.steps, comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart %s: step %lld is beyond -steps %d", path.c_str(), step, (int)o_.steps);
  PetscCall(readHistory(in, step));
  PetscCall(readNatural(in, "/state/u", nm_.displacement()));
  PetscCall(readNatural(in, "/state/v", nm_.velocity()));
  PetscCall(readNatural(in, "/state/a", nm_.acceleration()));
  nm_.setTime(time);
  restarted_ = true;
  PetscCall(in.close());
  PetscCall(suite::logInfo(comm, ctx_.quiet(), "femdyn plex: restarted from %s at step %lld, t = %g",
                           path.c_str(), step, time));
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
