// femdyn: options, setup (mesh, material, Dirichlet plane, loads, ordering, solver) and the static or Newmark
// run.
#include "femdyn_run.hpp"

#include "core/log.hpp"
#include "core/log_stages.hpp"
#include "core/progress.hpp"
#include "fem/cpu_timer.hpp"
#include "fem/mesh.hpp"
#include "fem/probe_contact.hpp"
#include "io/h5_output.hpp"

#include <petsctime.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace femdyn_app {

using namespace suite::fem;

namespace {
double now() {
  PetscLogDouble t;
  PetscTime(&t);
  return t;
}

// "x=0" -> axis 0, value 0; "none" -> axis -1.
PetscErrorCode parsePlane(MPI_Comm comm, const std::string& s, int* axis, double* value) {
  PetscFunctionBeginUser;
  *axis = -1;
  if (s == "none") PetscFunctionReturn(0);
  PetscCheck(s.size() >= 3 && (s[0] == 'x' || s[0] == 'y' || s[0] == 'z') && s[1] == '=', comm,
             PETSC_ERR_ARG_WRONG, "-dirichlet %s: expected a plane such as x=0 (or none)", s.c_str());
  char* end = nullptr;
  *value = std::strtod(s.c_str() + 2, &end);
  PetscCheck(end && *end == '\0', comm, PETSC_ERR_ARG_WRONG, "-dirichlet %s: bad coordinate", s.c_str());
  *axis = s[0] - 'x';
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode FemdynRun::readOptions() {
  PetscFunctionBeginUser;
  MPI_Comm comm = ctx_.comm();
  auto& nm = opt_.newmark;
  PetscInt ncells = 3, nsize = 2, ngrav = 3;
  PetscOptionsBegin(comm, "", "femdyn options", "");
  char buf[PETSC_MAX_PATH_LEN];
  auto readString = [&](const char* name, const char* text, std::string* value) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscStrncpy(buf, value->c_str(), sizeof buf));
    PetscCall(PetscOptionsString(name, text, "", buf, buf, sizeof buf, nullptr));
    *value = buf;
    PetscFunctionReturn(0);
  };
  PetscCall(readString("-mesh", "Mesh: beam (structured, 6 tets per hex) or file (-mesh_file)", &opt_.mesh));
  PetscCall(
      readString("-mesh_file", "Gmsh .msh (2.2/4.1 ASCII) or TetGen basename (.node/.ele)", &opt_.mesh_file));
  PetscCall(PetscOptionsReal("-beam_length", "Beam length along x", "", opt_.beam_length, &opt_.beam_length,
                             nullptr));
  PetscCall(
      PetscOptionsRealArray("-beam_size", "Beam cross-section sy,sz", "", opt_.beam_size, &nsize, nullptr));
  PetscCall(PetscOptionsIntArray("-beam_cells", "Hexahedra nx,ny,nz", "", opt_.beam_cells, &ncells, nullptr));
  PetscCall(
      PetscOptionsInt("-order", "Element order: 1 (P1) or 2 (P2)", "", opt_.order, &opt_.order, nullptr));
  PetscCall(readString("-material", "Material: linear, stvk, corotational", &opt_.material));
  PetscCall(PetscOptionsReal("-young", "Young's modulus E", "", opt_.young, &opt_.young, nullptr));
  PetscCall(PetscOptionsReal("-poisson", "Poisson ratio nu", "", opt_.poisson, &opt_.poisson, nullptr));
  PetscCall(PetscOptionsReal("-density", "Mass density", "", opt_.density, &opt_.density, nullptr));
  PetscCall(readString("-ordering", "Ordering: natural, cm, rcm, amd, metis, auto", &opt_.ordering));
  PetscCall(readString(
      "-solver",
      "Linear solver: skyline (envelope), banded (LAPACK), cholmod (supernodal), petsc (MPIAIJ + KSP)",
      &opt_.solver));
  PetscCall(readString("-dirichlet", "Clamped plane, e.g. x=0 (all DOFs of its nodes fixed), or none",
                       &opt_.dirichlet));
  PetscCall(PetscOptionsBool("-static", "Static solve K u = f (StVK: load stepping + Newton)", "",
                             opt_.is_static, &opt_.is_static, nullptr));
  PetscCall(PetscOptionsReal("-tip_load", "Total force P (-y) on the end face x = max as a uniform traction",
                             "", opt_.tip_load, &opt_.tip_load, nullptr));
  PetscCall(PetscOptionsRealArray("-gravity", "Gravity gx,gy,gz (body force density * g)", "", opt_.gravity,
                                  &ngrav, nullptr));
  PetscCall(PetscOptionsInt("-load_steps", "Static load increments", "", opt_.load_steps, &opt_.load_steps,
                            nullptr));
  PetscCall(PetscOptionsReal("-dt", "Time step", "", opt_.dt, &opt_.dt, nullptr));
  PetscCall(PetscOptionsInt("-steps", "Number of time steps", "", opt_.steps, &opt_.steps, nullptr));
  PetscCall(
      readString("-time_scheme",
                 "Time integrator: newmark (-newmark_beta/-newmark_gamma) or generalized_alpha (-rho_inf)",
                 &opt_.time_scheme));
  PetscCall(PetscOptionsReal("-rho_inf", "Generalized-alpha spectral radius at infinite omega dt, in [0, 1]",
                             "", opt_.rho_inf, &opt_.rho_inf, nullptr));
  PetscCall(PetscOptionsReal("-newmark_beta", "Newmark beta", "", nm.beta, &nm.beta, nullptr));
  PetscCall(PetscOptionsReal("-newmark_gamma", "Newmark gamma", "", nm.gamma, &nm.gamma, nullptr));
  PetscCall(PetscOptionsInt("-newton_max_it", "Newton iterations per step (1: linearly implicit)", "",
                            nm.newton_max_it, &nm.newton_max_it, nullptr));
  PetscCall(PetscOptionsReal("-newton_rtol", "Newton relative residual tolerance", "", nm.newton_rtol,
                             &nm.newton_rtol, nullptr));
  PetscCall(PetscOptionsReal("-newton_atol", "Newton absolute residual tolerance", "", nm.newton_atol,
                             &nm.newton_atol, nullptr));
  PetscCall(readString("-jacobian",
                       "Newton matrix: tangent (full Newton) or initial (K0, factor once per dt)",
                       &opt_.jacobian));
  PetscCall(readString("-newton_predictor",
                       "Newton start: constant (Newmark, a_{n+1} = a_n) or tangent (plus one correction "
                       "with the last step's factorised effective tangent; full Newton only)",
                       &opt_.predictor));
  PetscCall(readString("-mass", "Mass matrix: consistent or lumped (HRZ)", &opt_.mass));
  PetscCall(PetscOptionsReal("-rayleigh_alpha", "Rayleigh damping C = alpha M + beta K0: alpha", "",
                             nm.rayleigh_mass, &nm.rayleigh_mass, nullptr));
  PetscCall(PetscOptionsReal("-rayleigh_beta", "Rayleigh damping: beta", "", nm.rayleigh_stiffness,
                             &nm.rayleigh_stiffness, nullptr));
  PetscCall(PetscOptionsInt("-max_halvings", "Step rejections (dt halvings) allowed per step", "",
                            nm.max_halvings, &nm.max_halvings, nullptr));
  PetscCall(PetscOptionsInt("-snapshot_every", "Displacement/velocity snapshot every N steps (0: none)", "",
                            opt_.snapshot_every, &opt_.snapshot_every, nullptr));
  PetscCall(readString("-output", "HDF5 output file", &opt_.output));
  PetscInt npt = 3;
  PetscCall(PetscOptionsBool("-probe", "Haptic probe: a rigid point pressing on a surface node (penalty)", "",
                             opt_.probe, &opt_.probe, nullptr));
  PetscCall(PetscOptionsRealArray("-probe_point",
                                  "Probe contact point x,y,z (nearest node; default: top of the "
                                  "free end)",
                                  "", opt_.probe_point, &npt, nullptr));
  PetscCall(PetscOptionsReal("-probe_stiffness", "Probe penalty stiffness k (force per length)", "",
                             opt_.probe_stiffness, &opt_.probe_stiffness, nullptr));
  PetscCall(PetscOptionsReal("-probe_speed", "Probe indentation speed (along -y, from the node's height)", "",
                             opt_.probe_speed, &opt_.probe_speed, nullptr));
  PetscCall(PetscOptionsReal("-probe_depth", "Probe travel below the node's initial height, then it holds",
                             "", opt_.probe_depth, &opt_.probe_depth, nullptr));
  PetscCall(PetscOptionsReal("-haptic_rate", "Haptic force output rate in Hz (local model between FEM steps)",
                             "", opt_.haptic_rate, &opt_.haptic_rate, nullptr));
  PetscOptionsEnd();
  PetscCheck(
      !opt_.probe || (opt_.probe_stiffness > 0 && opt_.probe_speed >= 0 && opt_.probe_depth >= 0 &&
                      opt_.haptic_rate > 0),
      comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-probe: -probe_stiffness %g and -haptic_rate %g must be > 0, -probe_speed %g and -probe_depth %g >= 0",
      opt_.probe_stiffness, opt_.haptic_rate, opt_.probe_speed, opt_.probe_depth);
  PetscCheck(!(opt_.probe && opt_.is_static), comm, PETSC_ERR_ARG_INCOMP,
             "-probe needs a dynamic run (not -static)");
  PetscCall(policy_.setFromOptions(comm, "femdyn"));
  PetscCall(createLinearSolver(comm, opt_.solver, &solver_));
  PetscCall(solver_->setFromOptions(comm)); // -solver petsc: -ksp_type, -pc_type, ...
  PetscCheck(opt_.order == 1 || opt_.order == 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-order %d: must be 1 or 2",
             (int)opt_.order);
  PetscCheck(opt_.mesh == "beam" || opt_.mesh == "file", comm, PETSC_ERR_ARG_WRONG,
             "-mesh %s: must be beam or file", opt_.mesh.c_str());
  PetscCheck(opt_.beam_length > 0 && opt_.beam_size[0] > 0 && opt_.beam_size[1] > 0, comm,
             PETSC_ERR_ARG_OUTOFRANGE, "-beam_length %g and -beam_size %g,%g must be > 0", opt_.beam_length,
             opt_.beam_size[0], opt_.beam_size[1]);
  PetscCheck(opt_.beam_cells[0] >= 1 && opt_.beam_cells[1] >= 1 && opt_.beam_cells[2] >= 1, comm,
             PETSC_ERR_ARG_OUTOFRANGE, "-beam_cells %d,%d,%d: need at least 1 cell per direction",
             (int)opt_.beam_cells[0], (int)opt_.beam_cells[1], (int)opt_.beam_cells[2]);
  PetscCheck(opt_.density > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-density %g: must be > 0", opt_.density);
  PetscCheck(opt_.is_static || opt_.dt > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-dt %g: time step must be > 0",
             opt_.dt);
  PetscCheck(opt_.steps >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-steps %d: must be >= 0", (int)opt_.steps);
  PetscCheck(opt_.mass == "consistent" || opt_.mass == "lumped", comm, PETSC_ERR_ARG_WRONG,
             "-mass %s: must be consistent or lumped", opt_.mass.c_str());
  PetscCheck(opt_.jacobian == "tangent" || opt_.jacobian == "initial", comm, PETSC_ERR_ARG_WRONG,
             "-jacobian %s: must be tangent or initial", opt_.jacobian.c_str());
  PetscCheck(!opt_.output.empty() || ctx_.helpRequested(), comm, PETSC_ERR_ARG_WRONG,
             "-output FILE.h5 is required");
  nm.initial_jacobian = opt_.jacobian == "initial";
  PetscCheck(opt_.predictor == "constant" || opt_.predictor == "tangent", comm, PETSC_ERR_ARG_WRONG,
             "-newton_predictor %s: must be constant or tangent", opt_.predictor.c_str());
  nm.tangent_predictor = opt_.predictor == "tangent";
  PetscCheck(opt_.time_scheme == "newmark" || opt_.time_scheme == "generalized_alpha", comm,
             PETSC_ERR_ARG_WRONG, "-time_scheme %s: must be newmark or generalized_alpha",
             opt_.time_scheme.c_str());
  PetscCheck(opt_.rho_inf >= 0 && opt_.rho_inf <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-rho_inf %g: must be in [0, 1]", opt_.rho_inf);
  if (opt_.time_scheme == "generalized_alpha") nm = suite::fem::generalizedAlpha(nm, opt_.rho_inf);
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::setup() {
  PetscFunctionBeginUser;
  MPI_Comm comm = ctx_.comm();
  PetscCall(suite::checkOutputWritable(comm, opt_.output, "output"));
  const double t0 = now();
  Lame lame;
  PetscCall(lameFromYoung(comm, opt_.young, opt_.poisson, &lame));
  PetscCall(createMaterial(comm, opt_.material, lame, &material_));
  OrderingFn order_fn;
  PetscCall(findOrdering(comm, opt_.ordering, &order_fn));
  if (opt_.mesh == "beam") {
    BeamSpec s;
    s.length = opt_.beam_length;
    s.size = {opt_.beam_size[0], opt_.beam_size[1]};
    s.cells = {(int)opt_.beam_cells[0], (int)opt_.beam_cells[1], (int)opt_.beam_cells[2]};
    mesh_ = makeBeam(s);
  } else {
    const std::string& f = opt_.mesh_file;
    PetscCheck(!f.empty(), comm, PETSC_ERR_ARG_WRONG, "-mesh file needs -mesh_file");
    if (f.size() > 4 && f.substr(f.size() - 4) == ".msh") {
      PetscCall(readGmsh(comm, f, &mesh_));
    } else {
      std::string base = f;
      for (const char* ext : {".node", ".ele"})
        if (base.size() > 5 && base.substr(base.size() - std::strlen(ext)) == ext)
          base.resize(base.size() - std::strlen(ext));
      PetscCall(readTetGen(comm, base, &mesh_));
    }
  }
  if (opt_.order == 2 && mesh_.order() == 1) mesh_ = promoteToP2(mesh_);
  if (opt_.poisson > 0.45 && mesh_.order() == 1)
    PetscCall(suite::logInfo(
        comm, false,
        "femdyn: warning: -poisson %g with P1 tetrahedra: volumetric locking makes the response "
        "far too stiff (use -order 2)",
        opt_.poisson));

  int axis;
  double value;
  PetscCall(parsePlane(comm, opt_.dirichlet, &axis, &value));
  std::vector<char> fixed(3 * mesh_.numNodes(), 0);
  if (axis >= 0)
    for (int v : nodesOnPlane(mesh_, axis, value))
      for (int c = 0; c < 3; ++c) fixed[3 * v + c] = 1;
  int nfixed = 0;
  for (char f : fixed) nfixed += f;
  PetscCheck(
      !opt_.is_static || nfixed > 0, comm, PETSC_ERR_ARG_WRONG,
      "Dirichlet set -dirichlet %s is empty (no mesh node on that plane): the static problem is singular",
      opt_.dirichlet.c_str());
  PetscCall(model_.setup(comm, mesh_, *material_, fixed));

  double xmax = -1e300;
  for (const auto& x : mesh_.nodes) xmax = std::max(xmax, x[0]);
  tip_nodes_ = nodesOnPlane(mesh_, 0, xmax);
  f_ext_.assign(model_.numFree(), 0.0);
  if (opt_.tip_load != 0) {
    const auto faces = facesOnPlane(mesh_, 0, xmax);
    double area = 0;
    for (const auto& f : faces) {
      const auto &a = mesh_.nodes[f[0]], &b = mesh_.nodes[f[1]], &c = mesh_.nodes[f[2]];
      const Eigen::Vector3d u(b[0] - a[0], b[1] - a[1], b[2] - a[2]),
          w(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
      area += 0.5 * u.cross(w).norm();
    }
    PetscCheck(area > 0, comm, PETSC_ERR_ARG_WRONG, "-tip_load: no boundary face on the end plane x = %g",
               xmax);
    f_ext_ = model_.tractionLoad(faces, {0.0, -opt_.tip_load / area, 0.0});
  }
  if (opt_.gravity[0] != 0 || opt_.gravity[1] != 0 || opt_.gravity[2] != 0) {
    const auto g = model_.bodyForce(
        {opt_.density * opt_.gravity[0], opt_.density * opt_.gravity[1], opt_.density * opt_.gravity[2]});
    for (size_t i = 0; i < g.size(); ++i) f_ext_[i] += g[i];
  }

  // Ordering on the node graph, expanded to the free DOFs; metrics on the DOF matrix.
  const double to = threadCpuSeconds();
  perm_ = expandToDofs(order_fn(model_.nodeGraphOf()), model_.eq(), model_.numFree());
  res_.ordering_time = threadCpuSeconds() - to;
  res_.metrics = computeMetrics(graphOfMatrix(model_.pattern()), perm_);
  solver_->setNodeGraph(model_.nodeGraphOf(), model_.eq());
  PetscCall(solver_->analyze(comm, model_.pattern(), perm_));
  if (solver_->distributedAssembly()) {
    // Each rank assembles the elements whose first corner node it owns (the solver's METIS node partition).
    const auto& part = solver_->nodePartition();
    std::vector<char> owned(mesh_.numElems(), 0);
    for (int e = 0; e < mesh_.numElems(); ++e) owned[e] = part[mesh_.elem(e)[0]] == ctx_.rank();
    model_.setOwnedElements(std::move(owned));
    partial_ = true;
    opt_.newmark.partial_sums = true;
  }
  res_.factor = solver_->stats();
  res_.setup_time = now() - t0;
  PetscCall(suite::logInfo(comm, ctx_.quiet(),
                           "femdyn: %d nodes, %d P%d tets, %d free DOFs, material %s, ordering %s (%.3f ms): "
                           "bandwidth %lld, profile %lld, nnz(L) %lld, %.3g flops; solver %s",
                           mesh_.numNodes(), mesh_.numElems(), mesh_.order(), model_.numFree(),
                           material_->name(), opt_.ordering.c_str(), 1e3 * res_.ordering_time,
                           res_.metrics.bandwidth, res_.metrics.profile, res_.metrics.nnz_L,
                           res_.metrics.flops, solver_->describe().c_str()));
  PetscFunctionReturn(0);
}

std::vector<double> FemdynRun::fullDisplacement(const std::vector<double>& free) const {
  std::vector<double> full(model_.numDofs(), 0.0);
  model_.scatterFree(free.data(), full.data());
  return full;
}

double FemdynRun::tipDeflection(const std::vector<double>& u) const {
  double s = 0;
  for (int v : tip_nodes_) s -= u[3 * v + 1];
  return tip_nodes_.empty() ? 0.0 : s / tip_nodes_.size();
}

double FemdynRun::probeTarget(double t) const {
  return -std::min(opt_.probe_speed * t, opt_.probe_depth); // relative to the node's initial height
}

PetscErrorCode FemdynRun::findProbeNode(int* node) const {
  PetscFunctionBeginUser;
  std::array<double, 3> p = {opt_.probe_point[0], opt_.probe_point[1], opt_.probe_point[2]};
  if (p[0] > 1e299) { // default: top of the free end, middle of z
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& x : mesh_.nodes)
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], x[i]), hi[i] = std::max(hi[i], x[i]);
    p = {hi[0], hi[1], 0.5 * (lo[2] + hi[2])};
  }
  double best = 1e300;
  *node = -1;
  for (int v = 0; v < mesh_.numNodes(); ++v) {
    const auto& x = mesh_.nodes[v];
    const double d =
        (x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]);
    if (d < best) best = d, *node = v;
  }
  PetscCheck(*node >= 0 && model_.eq()[3 * *node + 1] >= 0, ctx_.comm(), PETSC_ERR_ARG_WRONG,
             "-probe_point: the nearest node %d is fixed by -dirichlet %s", *node, opt_.dirichlet.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::solveStaticCase() {
  PetscFunctionBeginUser;
  std::vector<double> u;
  const double t0 = now();
  PetscCall(solveStatic(ctx_.comm(), &model_, solver_.get(), f_ext_, (int)opt_.load_steps,
                        (int)opt_.newmark.newton_max_it, opt_.newmark.newton_rtol, &u, &res_.stat, partial_));
  res_.loop_time = now() - t0;
  res_.u_full = fullDisplacement(u);
  res_.tip_deflection = tipDeflection(res_.u_full);
  double ux = 0;
  for (int v : tip_nodes_) ux += res_.u_full[3 * v];
  ux /= std::max<size_t>(1, tip_nodes_.size());
  res_.tip_ux = ux;
  PetscCall(suite::logInfo(ctx_.comm(), ctx_.quiet(),
                           "femdyn static: tip_deflection %.6f (mean -u_y on %zu tip nodes), tip u_x %.6f, "
                           "%d load steps, %d Newton iterations, residual %.3e, strain energy %.6e, %.3f s",
                           res_.tip_deflection, tip_nodes_.size(), ux, res_.stat.load_steps,
                           res_.stat.newton_iterations, res_.stat.residual, res_.stat.energy,
                           res_.loop_time));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::solveDynamic() {
  PetscFunctionBeginUser;
  MPI_Comm comm = ctx_.comm();
  Newmark nm;
  // Haptic probe: the elastic system plus the probe's penalty force.
  SecondOrderSystem* sys = &model_;
  std::unique_ptr<ProbeSystem> probe;
  ProbeRecord& pr = res_.probe;
  int pdofs[3] = {-1, -1, -1};
  if (opt_.probe) {
    PetscCall(findProbeNode(&pr.node));
    for (int c = 0; c < 3; ++c) pdofs[c] = model_.eq()[3 * pr.node + c];
    probe = std::make_unique<ProbeSystem>(&model_, pdofs[1], mesh_.nodes[pr.node][1], opt_.probe_stiffness,
                                          !partial_ || ctx_.rank() == 0);
    sys = probe.get();
  }
  const double rho = opt_.density;
  auto mass = opt_.mass == "lumped" ? model_.lumpedMass(rho) : model_.consistentMass(rho);
  const std::vector<double>& fe = f_ext_;
  PetscCall(nm.setup(comm, sys, solver_.get(), std::move(mass), opt_.newmark,
                     [&fe](double, double* f) { std::copy(fe.begin(), fe.end(), f); }));
  NewmarkState s;
  s.u.assign(model_.numFree(), 0.0);
  s.v.assign(model_.numFree(), 0.0);
  suite::Progress progress(comm, ctx_.quiet(), ctx_.progressInterval(), opt_.steps * opt_.dt);
  auto record = [&](const StepTimings& tm, double total, double cpu) {
    StepRecord r{};
    r.time = s.t;
    r.assemble = tm.assemble, r.factor = tm.factor, r.solve = tm.solve, r.total = total, r.cpu = cpu;
    r.kinetic = nm.kineticEnergy(s);
    r.strain = nm.strainEnergy(s);
    double w = 0;
    for (size_t i = 0; i < fe.size(); ++i) w += fe[i] * s.u[i];
    r.external = w;
    r.newton = tm.newton_iterations, r.rejected = tm.rejected, r.converged = tm.converged ? 1 : 0;
    const auto full = fullDisplacement(s.u);
    r.tip_uy = tipDeflection(full);
    res_.steps.push_back(r);
  };
  long long k0 = 0;
  if (policy_.restartRequested()) {
    PetscCall(readRestart(&s, &k0)); // u, v, a, t and the history so far
    // Tangent predictor: the factorisation the interrupted run held (probe at its position of the last step).
    if (probe) probe->setProbe(mesh_.nodes[pr.node][1] + probeTarget(s.t));
    PetscCall(nm.restoreTangent(s));
  } else {
    PetscCall(nm.initialize(&s));
    record(StepTimings(), 0.0, 0.0);
    if (opt_.snapshot_every > 0) res_.snapshots.push_back({s.t, fullDisplacement(s.u)});
  }
  const double t0 = now();
  double stepping = 0, stepping_cpu = 0;
  int unconverged = 0;
  for (PetscInt k = (PetscInt)k0 + 1; k <= opt_.steps; ++k) {
    StepTimings tm;
    const double ts = now(), tc = threadCpuSeconds();
    if (probe) probe->setProbe(mesh_.nodes[pr.node][1] + probeTarget(s.t + opt_.dt));
    PetscCall(nm.step(&s, opt_.dt, &tm));
    const double dt_wall = now() - ts, dt_cpu = threadCpuSeconds() - tc;
    stepping += dt_wall;
    stepping_cpu += dt_cpu;
    if (!tm.converged && opt_.newmark.newton_max_it > 1) ++unconverged;
    record(tm, dt_wall, dt_cpu);
    if (probe) {
      // Synchronisation: the full-model probe force, then the local model for the ticks up to the next step
      // (they would run concurrently with it): compliance of the probe node from the current factorisation.
      const double f_full = probe->force(s.u.data());
      pr.sync_time.push_back(s.t);
      pr.force_full.push_back(f_full);
      const double tc0 = threadCpuSeconds();
      std::vector<double> e(model_.numFree(), 0.0), x(model_.numFree());
      double C[3][3] = {{0}};
      for (int a = 0; a < 3; ++a) {
        if (pdofs[a] < 0) continue;
        e[pdofs[a]] = 1.0;
        PetscCall(solver_->solve(e.data(), x.data()));
        e[pdofs[a]] = 0.0;
        for (int b = 0; b < 3; ++b) C[b][a] = pdofs[b] >= 0 ? x[pdofs[b]] : 0.0;
      }
      pr.compliance_seconds += threadCpuSeconds() - tc0;
      pr.compliance_yy.push_back(C[1][1]);
      HapticLocalModel hm;
      hm.t = s.t, hm.y = probe->position(s.u.data()), hm.v = s.v[pdofs[1]], hm.f = f_full, hm.c = C[1][1];
      hm.k = opt_.probe_stiffness;
      const double h = 1.0 / opt_.haptic_rate;
      const int m = std::max(1, (int)std::lround(opt_.dt / h));
      const double tt0 = threadCpuSeconds();
      double fh = 0;
      for (int j = 1; j <= m; ++j) {
        const double t = s.t + j * (opt_.dt / m);
        fh = hm.force(t, mesh_.nodes[pr.node][1] + probeTarget(t));
        pr.haptic_time.push_back(t);
        pr.haptic_force.push_back(fh);
      }
      pr.tick_seconds += threadCpuSeconds() - tt0;
      pr.ticks += m;
      pr.force_predicted.push_back(fh); // the local model's force at the next synchronisation time
    }
    if (opt_.snapshot_every > 0 && k % opt_.snapshot_every == 0)
      res_.snapshots.push_back({s.t, fullDisplacement(s.u)});
    PetscCall(progress.update(k, s.t, opt_.dt));
    bool due = false, stop = false;
    if (policy_.enabled()) PetscCall(policy_.due(k, &due));
    PetscCall(ctx_.stopRequested(&stop));
    // A stop request (SIGTERM/SIGUSR1/-max_walltime) writes a final checkpoint of the state reached.
    if (due || (stop && policy_.enabled() && k < opt_.steps)) PetscCall(writeCheckpointAt(s, k));
    if (stop) {
      PetscCall(suite::logInfo(comm, ctx_.quiet(), "femdyn: stopping at step %d (%s)", (int)k,
                               ctx_.stopReason().c_str()));
      break;
    }
  }
  res_.loop_time = now() - t0;
  res_.u_full = fullDisplacement(s.u);
  // Rates over the steps of this run (a restarted run continues a history that it did not time).
  const int n = (int)(res_.steps.size() - 1 - k0);
  double as = 0, fa = 0, so = 0;
  int newton = 0;
  for (size_t i = 1 + k0; i < res_.steps.size(); ++i)
    as += res_.steps[i].assemble, fa += res_.steps[i].factor, so += res_.steps[i].solve,
        newton += res_.steps[i].newton;
  const auto& e0 = res_.steps.front();
  const auto& e1 = res_.steps.back();
  const double E0 = e0.kinetic + e0.strain - e0.external, E1 = e1.kinetic + e1.strain - e1.external;
  PetscCall(suite::logInfo(
      comm, ctx_.quiet(),
      "femdyn: %d steps, %.2f Newton iterations/step, %.1f Hz cpu (%.3f ms/step: assemble %.3f, "
      "factor %.3f, solve %.3f; wall %.1f Hz), tip -u_y %.6f, energy %.6e -> %.6e%s",
      n, n ? (double)newton / n : 0.0, n && stepping_cpu > 0 ? n / stepping_cpu : 0.0,
      n ? 1e3 * stepping_cpu / n : 0.0, n ? 1e3 * as / n : 0.0, n ? 1e3 * fa / n : 0.0,
      n ? 1e3 * so / n : 0.0, n && stepping > 0 ? n / stepping : 0.0, e1.tip_uy, E0, E1,
      unconverged ? " (some steps did not converge: see /steps/converged)" : ""));
  if (probe && pr.sync_time.size() > 1) {
    double err = 0, fmax = 0;
    for (size_t i = 1; i < pr.sync_time.size(); ++i) {
      err = std::max(err, std::abs(pr.force_predicted[i - 1] - pr.force_full[i]));
      fmax = std::max(fmax, std::abs(pr.force_full[i]));
    }
    PetscCall(suite::logInfo(comm, ctx_.quiet(),
                             "femdyn probe: node %d, final force %.6g; haptic %lld ticks at %.0f Hz (model "
                             "rate %.3g Hz cpu, %.3f ms/step "
                             "for the compliance solves); local model vs full model at the synchronisations: "
                             "max |df| %.3e (%.3e of max "
                             "force %.4g)",
                             pr.node, pr.force_full.back(), pr.ticks, opt_.haptic_rate,
                             pr.tick_seconds > 0 ? pr.ticks / pr.tick_seconds : 0.0,
                             1e3 * pr.compliance_seconds / pr.sync_time.size(), err,
                             fmax > 0 ? err / fmax : 0.0, fmax));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::solve() {
  PetscFunctionBeginUser;
  if (opt_.is_static)
    PetscCall(solveStaticCase());
  else if (opt_.steps > 0)
    PetscCall(solveDynamic());
  else
    res_.u_full.assign(model_.numDofs(), 0.0); // -steps 0: setup, ordering and analysis only
  PetscFunctionReturn(0);
}

PetscErrorCode runFemdyn(const suite::RunContext& ctx) {
  PetscFunctionBeginUser;
  suite::LogStages stages;
  PetscCall(suite::LogStages::get(&stages));
  FemdynRun run(ctx);
  PetscCall(PetscLogStagePush(stages.setup));
  PetscCall(run.readOptions());
  PetscCall(ctx.checkUnusedOptions());
  if (ctx.helpRequested()) {
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }
  PetscCall(run.setup());
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(stages.solve));
  PetscCall(run.solve());
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(stages.output));
  PetscCall(run.writeOutput());
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
