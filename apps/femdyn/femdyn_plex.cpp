// femdyn -backend plex: the beam as a distributed DMPlex (fem/plex_beam.hpp), P1 linear or StVK
// elastodynamics with PetscFE (fem/plex_elasticity.hpp), Newmark + SNES on distributed Vecs
// (fem/plex_newmark.hpp). No rank holds a global-size array: the mesh is generated in slabs and repartitioned,
// the state and the loads are distributed, the tip mean is reduced, and the output is written collectively
// (each rank its owned vertices' and its cells' rows, in the DMPlex's global vertex numbering).
// The options this path does not have yet are refused by name (refuseUnsupported).
#include "core/clocks.hpp"
#include "core/log.hpp"
#include "fem/material.hpp"
#include "fem/plex_beam.hpp"
#include "fem/plex_newmark.hpp"
#include "femdyn_run.hpp"
#include "io/h5_output.hpp"
#include "io/xdmf.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <vector>

namespace femdyn_app {

using namespace suite::fem;

namespace {

using ull = unsigned long long;

// Options of the replicated path that -backend plex does not implement (yet): given explicitly, an error.
PetscErrorCode refuseUnsupported(MPI_Comm comm, const Options& o) {
  static const char* names[] = {"-mesh_file",
                                "-order",
                                "-material_auto_law",
                                "-target_error",
                                "-target_switch_up",
                                "-target_switch_down",
                                "-ordering",
                                "-solver",
                                "-load_steps",
                                "-time_scheme",
                                "-rho_inf",
                                "-jacobian",
                                "-newton_predictor",
                                "-mass",
                                "-rayleigh_alpha",
                                "-rayleigh_beta",
                                "-max_halvings",
                                "-snapshot_every",
                                "-probe",
                                "-probe_point",
                                "-probe_stiffness",
                                "-probe_speed",
                                "-probe_depth",
                                "-haptic_rate",
                                "-checkpoint_dir",
                                "-checkpoint_every",
                                "-checkpoint_wall",
                                "-checkpoint_keep",
                                "-restart",
                                "-max_walltime"};
  PetscFunctionBeginUser;
  for (const char* n : names) {
    PetscBool set = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, n, &set));
    PetscCheck(!set, comm, PETSC_ERR_SUP, "%s is not available with -backend plex (the distributed path)", n);
  }
  PetscCheck(o.mesh == "beam", comm, PETSC_ERR_SUP, "-backend plex generates the beam only (-mesh beam)");
  PetscCheck(o.material == "linear" || o.material == "stvk", comm, PETSC_ERR_SUP,
             "-backend plex has -material linear and stvk, not %s", o.material.c_str());
  PetscCheck(o.dirichlet == "x=0", comm, PETSC_ERR_SUP,
             "-backend plex clamps the plane x=0 only (-dirichlet %s)", o.dirichlet.c_str());
  PetscFunctionReturn(0);
}

struct PlexStep {
  double time, tip, wall, cpu;
  int newton, linear;
};

// Peak resident set of this process in GiB (getrusage: kilobytes on Linux).
double peakRssGiB() {
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / (1024.0 * 1024.0);
}

// Owned vertices (coordinates, u) and local cells (global vertex numbers) as distributed datasets.
PetscErrorCode writePlexMesh(suite::H5Output& out, DM dm, Vec u, long long nv, long long nc) {
  IS numbering;
  const PetscInt* gnum;
  PetscInt v0, v1, c0, c1;
  Vec loc, coords;
  PetscSection ls, cs;
  const PetscScalar *ul, *cx;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v0, &v1));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(DMPlexGetVertexNumbering(dm, &numbering));
  PetscCall(ISGetIndices(numbering, &gnum));
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(DMGlobalToLocal(dm, u, INSERT_VALUES, loc));
  PetscCall(DMGetLocalSection(dm, &ls));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(VecGetArrayRead(loc, &ul));
  PetscCall(VecGetArrayRead(coords, &cx));
  std::vector<double> xyz, disp;
  long long first = -1;
  for (PetscInt v = v0; v < v1; ++v) {
    const PetscInt g = gnum[v - v0];
    if (g < 0) continue;
    if (first < 0) first = g;
    PetscInt off, coff;
    PetscCall(PetscSectionGetOffset(ls, v, &off));
    PetscCall(PetscSectionGetOffset(cs, v, &coff));
    for (int d = 0; d < 3; ++d)
      xyz.push_back(PetscRealPart(cx[coff + d])), disp.push_back(PetscRealPart(ul[off + d]));
  }
  PetscCall(VecRestoreArrayRead(coords, &cx));
  PetscCall(VecRestoreArrayRead(loc, &ul));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  const ull nown = xyz.size() / 3;
  ull start = 0, cstart = 0, ncl = (ull)(c1 - c0);
  PetscCallMPI(MPI_Exscan(&nown, &start, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  PetscCallMPI(MPI_Exscan(&ncl, &cstart, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  int rank;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) start = cstart = 0;
  PetscCheck(nown == 0 || first == (long long)start, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "DMPlex vertex numbering is not contiguous per rank (first owned %lld, expected %llu)", first,
             start);
  std::vector<int> tets;
  for (PetscInt c = c0; c < c1; ++c) {
    PetscInt n = 0, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < 2 * n; i += 2)
      if (pts[i] >= v0 && pts[i] < v1) {
        const PetscInt g = gnum[pts[i] - v0];
        tets.push_back((int)(g < 0 ? -(g + 1) : g));
      }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
  }
  PetscCall(ISRestoreIndices(numbering, &gnum));
  PetscCall(out.writeDistributed("/mesh/coordinates", xyz.data(), {(ull)nv, 3}, {start, 0}, {nown, 3}, "m"));
  PetscCall(out.writeDistributed("/mesh/tets", tets.data(), {(ull)nc, 4}, {cstart, 0}, {ncl, 4}, ""));
  PetscCall(out.writeDistributed("/final/u", disp.data(), {(ull)nv, 3}, {start, 0}, {nown, 3}, "m"));
  PetscFunctionReturn(0);
}

// /partition/{cells,points}: each rank's local cells and mesh points (one entry per rank).
PetscErrorCode writePartition(suite::H5Output& out, DM dm, int rank, int size) {
  PetscInt c0, c1, p0, p1;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c0, &c1));
  PetscCall(DMPlexGetChart(dm, &p0, &p1));
  const long long cells = c1 - c0, points = p1 - p0;
  PetscCall(out.writeDistributed("/partition/cells", &cells, {(ull)size}, {(ull)rank}, {1}, ""));
  PetscCall(out.writeDistributed("/partition/points", &points, {(ull)size}, {(ull)rank}, {1}, ""));
  PetscFunctionReturn(0);
}

// The whole distributed run: setup, static solve or the time steps, output.
class PlexRun {
public:
  PlexRun(const suite::RunContext& ctx, const Options& o) : ctx_(ctx), o_(o) {}
  ~PlexRun() {
    DMDestroy(&aux_);
    DMDestroy(&dm_);
  }
  PetscErrorCode setup();
  PetscErrorCode solve();
  // -plex_rank_cap on this rank's local vector (owned and ghost DOFs).
  PetscErrorCode checkLocalDofs() const;
  PetscErrorCode write() const;

private:
  const suite::RunContext& ctx_;
  const Options& o_;
  DM dm_ = nullptr, aux_ = nullptr;
  PlexNewmark nm_;
  long long nv_ = 0, nc_ = 0;
  PetscInt ndof_ = 0;
  std::vector<PlexStep> steps_;
  PlexStepStats stat_;
  double tip_ = 0, tip_ux_ = 0, setup_s_ = 0, solve_s_ = 0;
};

PetscErrorCode PlexRun::setup() {
  MPI_Comm comm = ctx_.comm();
  Lame lame;
  Vec g;
  PetscFunctionBeginUser;
  const double t0 = suite::wallSeconds();
  PetscCall(refuseUnsupported(comm, o_));
  PetscCall(suite::checkOutputWritable(comm, o_.output, "output"));
  PetscCall(lameFromYoung(comm, o_.young, o_.poisson, &lame));
  PetscCall(createPlexBeam(comm, o_.beam, o_.plex_rank_cap, &dm_));
  PlexElasticParams p;
  p.law = o_.material, p.lambda = lame.lambda, p.mu = lame.mu, p.rho = o_.density;
  std::copy(o_.gravity, o_.gravity + 3, p.gravity);
  PetscCall(setupPlexElasticity(dm_, p, &aux_));
  const auto& n = o_.newmark;
  PetscCall(
      nm_.setup(dm_, aux_, p, o_.tip_load, n.beta, n.gamma, n.newton_rtol, n.newton_atol, n.newton_max_it));
  PetscCall(ctx_.checkUnusedOptions()); // after SNESSetFromOptions: -snes_*, -ksp_*, -pc_* are used now
  PetscCall(plexGlobalSizes(dm_, &nv_, &nc_));
  PetscCall(DMGetGlobalVector(dm_, &g));
  PetscCall(VecGetSize(g, &ndof_));
  PetscCall(DMRestoreGlobalVector(dm_, &g));
  PetscCall(checkLocalDofs());
  setup_s_ = suite::wallSeconds() - t0;
  PetscCall(
      suite::logInfo(comm, ctx_.quiet(),
                     "femdyn plex: %lld nodes, %lld P1 tets, %d free DOFs on %d ranks (distributed DMPlex), "
                     "material %s, setup %.3f s",
                     nv_, nc_, (int)ndof_, ctx_.size(), o_.material.c_str(), setup_s_));
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::checkLocalDofs() const {
  Vec l;
  PetscInt n;
  long long most = 0, mine;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm_, &l));
  PetscCall(VecGetLocalSize(l, &n));
  PetscCall(DMRestoreLocalVector(dm_, &l));
  mine = n;
  PetscCallMPI(MPI_Allreduce(&mine, &most, 1, MPI_LONG_LONG, MPI_MAX, ctx_.comm()));
  PetscCheck(o_.plex_rank_cap <= 0 || most <= o_.plex_rank_cap, ctx_.comm(), PETSC_ERR_MEM,
             "a rank holds %lld local DOFs, above -plex_rank_cap %lld", most, (long long)o_.plex_rank_cap);
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::solve() {
  PetscFunctionBeginUser;
  const double L = o_.beam.length, t0 = suite::wallSeconds();
  if (o_.is_static) {
    PetscCall(nm_.solveStatic(&stat_));
  } else {
    PetscCall(nm_.initialize());
    for (PetscInt s = 0; s < o_.steps; ++s) {
      const double w0 = suite::wallSeconds(), c0 = suite::processCpuSeconds();
      PlexStepStats st;
      PetscCall(nm_.step(o_.dt, &st));
      double tip;
      PetscCall(nm_.planeMean(L, 1, -1.0, &tip));
      steps_.push_back({nm_.time(), tip, suite::wallSeconds() - w0, suite::processCpuSeconds() - c0,
                        (int)st.newton_iterations, (int)st.linear_iterations});
    }
  }
  solve_s_ = suite::wallSeconds() - t0;
  PetscCall(nm_.planeMean(L, 1, -1.0, &tip_));
  PetscCall(nm_.planeMean(L, 0, 1.0, &tip_ux_));
  PetscCall(
      suite::logInfo(ctx_.comm(), ctx_.quiet(),
                     "femdyn plex: tip_deflection %.10g (mean -u_y on the end face), tip u_x %.6g, %s %.3f s",
                     tip_, tip_ux_, o_.is_static ? "static solve" : "time steps", solve_s_));
  PetscCall(write());
  PetscFunctionReturn(0);
}

PetscErrorCode PlexRun::write() const {
  suite::H5Output out;
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  double rss = peakRssGiB(), rss_max = 0, rss_sum = 0;
  PetscCallMPI(MPI_Allreduce(&rss, &rss_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&rss, &rss_sum, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscCall(out.open(comm, o_.output));
  PetscCall(out.writeProvenance(ctx_));
  PetscCall(out.writeAttribute("/", "mode", o_.is_static ? "static" : "dynamic"));
  PetscCall(out.writeAttribute("/", "backend", "plex"));
  PetscCall(out.writeAttribute("/", "material", o_.material));
  PetscCall(out.writeAttribute("/", "nodes", nv_));
  PetscCall(out.writeAttribute("/", "elements", nc_));
  PetscCall(out.writeAttribute("/", "dofs", (long long)ndof_));
  PetscCall(out.writeAttribute("/", "tip_load", o_.tip_load));
  PetscCall(out.writeAttribute("/", "tip_deflection", tip_));
  PetscCall(out.writeAttribute("/", "tip_ux", tip_ux_));
  PetscCall(out.writeAttribute("/", "setup_seconds", setup_s_));
  PetscCall(out.writeAttribute("/", "solve_seconds", solve_s_));
  PetscCall(out.writeAttribute("/", "peak_rss_gib_max_rank", rss_max));
  PetscCall(out.writeAttribute("/", "peak_rss_gib_sum", rss_sum));
  if (!steps_.empty()) {
    const struct {
      const char* name;
      double PlexStep::*f;
      const char* units;
    } cols[] = {{"time", &PlexStep::time, "s"},
                {"tip_deflection", &PlexStep::tip, "m"},
                {"wall", &PlexStep::wall, "s"},
                {"cpu", &PlexStep::cpu, "s"}};
    for (const auto& c : cols) {
      std::vector<double> v;
      for (const auto& s : steps_) v.push_back(s.*c.f);
      PetscCall(out.writeReplicated(std::string("/steps/") + c.name, v.data(), {(ull)v.size()}, c.units));
    }
    std::vector<int> nw, li;
    for (const auto& s : steps_) nw.push_back(s.newton), li.push_back(s.linear);
    PetscCall(out.writeReplicated("/steps/newton_iterations", nw.data(), {(ull)nw.size()}, ""));
    PetscCall(out.writeReplicated("/steps/linear_iterations", li.data(), {(ull)li.size()}, ""));
    PetscCall(out.writeAttribute("/", "steps", (long long)steps_.size()));
    PetscCall(out.writeAttribute("/", "dt", o_.dt));
  } else {
    PetscCall(out.writeAttribute("/", "newton_iterations", (long long)stat_.newton_iterations));
  }
  PetscCall(writePlexMesh(out, dm_, nm_.displacement(), nv_, nc_));
  PetscCall(writePartition(out, dm_, ctx_.rank(), ctx_.size()));
  PetscCall(out.commit(&ctx_));
  const double t = steps_.empty() ? 0.0 : steps_.back().time;
  suite::XdmfTetMesh xm{"/mesh/coordinates", "/mesh/tets", (ull)nv_, (ull)nc_};
  PetscCall(suite::writeXdmfTetSeries(comm, o_.output + ".xmf", o_.output, xm,
                                      {{t, {{"displacement", "/final/u", 3}}}}));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode runPlexFemdyn(const suite::RunContext& ctx, const Options& opt) {
  PlexRun run(ctx, opt);
  PetscFunctionBeginUser;
  PetscCall(run.setup());
  PetscCall(run.solve());
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
