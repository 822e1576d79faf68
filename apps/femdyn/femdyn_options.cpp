// femdyn options: two groups read in the options block (the model with its loads and time step; the
// integrator's Newton, mass, damping, output and the haptic probe), named choices documented by -help from
// their registries in lib/fem (-mesh, -material, -ordering, -solver, the integrator's -time_scheme,
// -jacobian, -newton_predictor, -mass), then the cross-option checks (collective PetscCheck).
#include "core/named_choice.hpp"
#include <cmath>
#include "core/option_value.hpp"
#include "fem/material.hpp"
#include "femdyn_run.hpp"

namespace femdyn_app {

namespace {
// One option in the options block (real, integer, flag, string or named choice); its value is the default.
struct Read {
  PetscOptionItems* PetscOptionsObject;
  PetscErrorCode operator()(const char* name, const char* text, PetscReal* v) const {
    return suite::optionsReal(PetscOptionsObject, name, text, "", *v, v, nullptr);
  }
  PetscErrorCode operator()(const char* name, const char* text, PetscInt* v) const {
    return suite::optionsInt(PetscOptionsObject, name, text, "", *v, v, nullptr);
  }
  PetscErrorCode operator()(const char* name, const char* text, PetscBool* v) const {
    return suite::optionsBool(PetscOptionsObject, name, text, "", *v, v, nullptr);
  }
  PetscErrorCode operator()(const char* name, const char* text, std::string* v) const {
    return suite::optionsString(PetscOptionsObject, name, text, v);
  }
  PetscErrorCode operator()(const char* name, const char* text, const std::vector<suite::Choice>& c,
                            std::string* v) const {
    return suite::optionsChoice(PetscOptionsObject, name, text, c, v);
  }
};
} // namespace

// Mesh, material, linear solver, Dirichlet plane, loads and the time step.
PetscErrorCode FemdynRun::readModelOptions(PetscOptionItems* PetscOptionsObject) {
  const Read o{PetscOptionsObject};
  PetscInt ncells = 3, nsize = 2, ngrav = 3;
  PetscFunctionBeginUser;
  PetscCall(o("-mesh", "Mesh", suite::fem::meshChoices(), &opt_.mesh));
  PetscCall(o("-mesh_file", "Gmsh .msh (2.2/4.1 ASCII) or TetGen basename (.node/.ele)", &opt_.mesh_file));
  PetscCall(o("-beam_length", "Beam length along x", &opt_.beam.length));
  PetscCall(suite::optionsRealArray(PetscOptionsObject, "-beam_size", "Beam cross-section sy,sz", "",
                                    opt_.beam.size.data(), &nsize, nullptr));
  PetscCall(suite::optionsIntArray(PetscOptionsObject, "-beam_cells", "Hexahedra nx,ny,nz", "",
                                   opt_.beam.cells.data(), &ncells, nullptr));
  PetscCall(o("-order", "Element order: 1 (P1) or 2 (P2)", &opt_.order));
  auto materials = suite::fem::materialChoices();
  materials.push_back({"auto", "the linear law while its estimated error is below -target_error, else "
                               "-material_auto_law (per-step law in /material_auto)"});
  PetscCall(o("-material", "Material", materials, &opt_.material));
  PetscCall(o("-material_auto_law", "-material auto: the nonlinear law", suite::fem::materialChoices(),
              &opt_.auto_law));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-target_error",
                               "-material auto / -dt_adapt: bound E on max_t |tip(t) - tip_ref(t)| / "
                               "max_t |tip_ref(t)| (tip: mean -u_y of the end face; ref: the nonlinear law, "
                               "same -dt; with -dt_adapt at a fine fixed dt, E/2 law + E/2 time steps "
                               "when both)",
                               "", opt_.law_policy.target, &opt_.law_policy.target, &opt_.target_set));
  PetscCall(o("-target_switch_up", "-material auto: to the nonlinear law when the estimate > this * target",
              &opt_.law_policy.up));
  PetscCall(o("-target_switch_down", "-material auto: back to linear when the estimate < this * target",
              &opt_.law_policy.down));
  PetscCall(o("-young", "Young's modulus E", &opt_.young));
  PetscCall(o("-poisson", "Poisson ratio nu", &opt_.poisson));
  PetscCall(o("-density", "Mass density", &opt_.density));
  PetscCall(o("-ordering", "Fill-reducing ordering", suite::fem::orderingChoices(), &opt_.ordering));
  PetscCall(o("-solver", "Linear solver", suite::fem::solverChoices(), &opt_.solver));
  PetscCall(
      o("-backend", "Where the mesh and the state live",
        {{"replicated", "every rank holds the mesh and the time-stepping state (-solver: the linear solver)"},
         {"plex",
          "distributed DMPlex mesh, state, assembly and output (the beam or a Gmsh / -mesh_convert "
          "file, linear/stvk/corotational, Newmark or generalized-alpha, Rayleigh damping; SNES and KSP "
          "options as usual, default CG + GAMG with rigid-body modes)"}},
        &opt_.backend));
  PetscCall(o(
      "-plex_rank_cap",
      "-backend plex: the most mesh points (cells, faces, edges, vertices) or local DOFs one rank may hold, "
      "checked after generation and after distribution (0: no cap)",
      &opt_.plex_rank_cap));
  PetscCall(
      o("-dirichlet", "Clamped plane, e.g. x=0 (all DOFs of its nodes fixed), or none", &opt_.dirichlet));
  PetscCall(
      o("-mesh_convert",
        "-backend plex: write the mesh (with its groups) as the suite's parallel HDF5 mesh file, read back "
        "at any rank count by -mesh_file FILE.h5, and stop",
        &opt_.mesh_convert));
  PetscCall(
      o("-bc_fixed",
        "-backend plex: groups (Gmsh physical group names or tags, comma-separated) whose displacements "
        "are zero; replaces the -dirichlet clamp",
        &opt_.bc_fixed));
  PetscCall(
      o("-bc_displacement",
        "-backend plex: prescribed displacement components on surface groups, G:ux=a,uy=b,uz=c (any "
        "subset; 0 for rollers and symmetry planes; several: separated by ';'); replaces the -dirichlet "
        "clamp",
        &opt_.bc_displacement));
  PetscCall(
      o("-bc_ramp",
        "-backend plex: time over which the -bc_displacement values grow linearly from 0 (0: applied at "
        "once)",
        &opt_.bc_ramp));
  PetscCall(o("-traction",
              "-backend plex: dead traction (force per area) on surface groups, G:tx,ty,tz (several: "
              "separated by ';')",
              &opt_.traction));
  PetscCall(o("-static", "Static solve K u = f (StVK: load stepping + Newton)", &opt_.is_static));
  PetscCall(
      o("-tip_load",
        "Total force P (-y) on the end face x = max as a uniform traction (-backend plex: on the group tip "
        "when the mesh has one)",
        &opt_.tip_load));
  PetscCall(suite::optionsRealArray(PetscOptionsObject, "-gravity",
                                    "Gravity gx,gy,gz (body force density * g)", "", opt_.gravity, &ngrav,
                                    nullptr));
  PetscCall(o("-load_steps", "Static load increments", &opt_.load_steps));
  PetscCall(o("-dt", "Time step", &opt_.dt));
  PetscCall(o("-steps", "Number of time steps", &opt_.steps));
  PetscCall(o("-load_release", "Time at which the loads are removed (free vibration after; 0: never)",
              &opt_.load_release));
  PetscCall(
      o("-dt_adapt",
        "Adaptive dt (Zienkiewicz-Xie estimate, step rejection) to meet -target_error over -steps x -dt "
        "(-dt: first try; per-step dt in /time_adapt)",
        &opt_.dt_adapt));
  PetscCall(o("-dt_min", "-dt_adapt: smallest dt (reached: error; default 1e-6 x -steps x -dt)",
              &opt_.step_control.dt_min));
  PetscCall(o("-dt_max", "-dt_adapt: largest dt (0: -steps x -dt)", &opt_.step_control.dt_max));
  PetscFunctionReturn(0);
}

// The time integrator with its Newton iteration, mass and damping; snapshots and output; the haptic probe.
PetscErrorCode FemdynRun::readIntegratorOptions(PetscOptionItems* PetscOptionsObject) {
  const Read o{PetscOptionsObject};
  PetscInt npt = 3;
  auto& nm = opt_.newmark;
  auto& p = opt_.probe_set;
  PetscFunctionBeginUser;
  PetscCall(o("-time_scheme", "Time integrator", suite::fem::timeSchemeChoices(), &opt_.time_scheme));
  PetscCall(
      o("-rho_inf", "Generalized-alpha spectral radius at infinite omega dt, in [0, 1]", &opt_.rho_inf));
  PetscCall(o("-newmark_beta", "Newmark beta", &nm.beta));
  PetscCall(o("-newmark_gamma", "Newmark gamma", &nm.gamma));
  PetscCall(o("-newton_max_it", "Newton iterations per step (1: linearly implicit)", &nm.newton_max_it));
  PetscCall(o("-newton_rtol", "Newton relative residual tolerance", &nm.newton_rtol));
  PetscCall(o("-newton_atol", "Newton absolute residual tolerance", &nm.newton_atol));
  PetscCall(o("-jacobian", "Newton matrix", suite::fem::jacobianChoices(), &opt_.jacobian));
  PetscCall(o("-newton_predictor", "Newton start", suite::fem::predictorChoices(), &opt_.predictor));
  PetscCall(o("-lagged_refresh_contraction",
              "-jacobian lagged: refactorise when an iteration contracts the residual by less than this",
              &nm.refresh_contraction));
  PetscCall(o("-lagged_refresh_iterations",
              "-jacobian lagged: refactorise when the corrections with one factorisation in a step, made and "
              "predicted by the contraction, exceed this",
              &nm.refresh_iterations));
  PetscCall(o("-newton_max_corrections",
              "Work cap: at most this many Newton corrections per step, then the step is accepted with its "
              "residual recorded (0: no cap)",
              &nm.max_corrections));
  PetscCall(o("-mass", "Mass matrix", suite::fem::massChoices(), &opt_.mass));
  PetscCall(o("-rayleigh_alpha", "Rayleigh damping C = alpha M + beta K0: alpha", &nm.rayleigh_mass));
  PetscCall(o("-rayleigh_beta", "Rayleigh damping: beta", &nm.rayleigh_stiffness));
  PetscCall(o("-max_halvings", "Step rejections (dt halvings) allowed per step", &nm.max_halvings));
  PetscCall(
      o("-snapshot_every", "Displacement/velocity snapshot every N steps (0: none)", &opt_.snapshot_every));
  PetscCall(o("-output", "HDF5 output file", &opt_.output));
  PetscCall(o("-probe", "Haptic probe: a rigid point pressing on a surface node (penalty)", &opt_.probe));
  PetscCall(suite::optionsRealArray(PetscOptionsObject, "-probe_point",
                                    "Probe contact point x,y,z (nearest node; default: top of the free end)",
                                    "", p.point, &npt, nullptr));
  PetscCall(o("-probe_stiffness", "Probe penalty stiffness k (force per length)", &p.stiffness));
  PetscCall(o("-probe_speed", "Probe indentation speed (along -y, from the node's height)", &p.speed));
  PetscCall(o("-probe_depth", "Probe travel below the node's initial height, then it holds", &p.depth));
  PetscCall(
      o("-haptic_rate", "Haptic force output rate in Hz (local model between FEM steps)", &p.haptic_rate));
  PetscFunctionReturn(0);
}

// Value ranges and combinations (the named choices are already validated by optionsChoice).
PetscErrorCode FemdynRun::checkOptions() const {
  MPI_Comm comm = ctx_.comm();
  const auto& b = opt_.beam;
  PetscFunctionBeginUser;
  PetscCall(checkIntegerOptions());
  PetscCheck(opt_.order == 1 || opt_.order == 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-order %d: must be 1 or 2",
             (int)opt_.order);
  PetscCheck(b.length > 0 && b.size[0] > 0 && b.size[1] > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_length %g and -beam_size %g,%g must be > 0", b.length, b.size[0], b.size[1]);
  PetscCheck(b.cells[0] >= 1 && b.cells[1] >= 1 && b.cells[2] >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_cells %d,%d,%d: need at least 1 cell per direction", b.cells[0], b.cells[1], b.cells[2]);
  PetscCheck(
      opt_.mesh != "beam" || opt_.mesh_file.empty(), comm, PETSC_ERR_ARG_WRONG,
      "-mesh_file %s is read only with -mesh file (the mesh is -mesh %s): add -mesh file or drop -mesh_file",
      opt_.mesh_file.c_str(), opt_.mesh.c_str());
  PetscCheck(opt_.density > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-density %g: must be > 0", opt_.density);
  PetscCheck(opt_.is_static || opt_.dt > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-dt %g: time step must be > 0",
             opt_.dt);
  PetscCheck(opt_.steps >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-steps %d: must be >= 0", (int)opt_.steps);
  PetscCheck(opt_.load_release >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_release %g: must be >= 0",
             opt_.load_release);
  PetscCheck(opt_.rho_inf >= 0 && opt_.rho_inf <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-rho_inf %g: must be in [0, 1]", opt_.rho_inf);
  PetscCheck(opt_.plex_rank_cap >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-plex_rank_cap %d: must be >= 0 (0: no cap)", (int)opt_.plex_rank_cap);
  PetscCheck(opt_.plex_rank_cap == 0 || opt_.backend == "plex", comm, PETSC_ERR_ARG_INCOMP,
             "-plex_rank_cap applies to -backend plex only (the backend is %s)", opt_.backend.c_str());
  PetscCheck(
      (opt_.bc_fixed.empty() && opt_.traction.empty() && opt_.bc_displacement.empty() &&
       opt_.mesh_convert.empty()) ||
          opt_.backend == "plex",
      comm, PETSC_ERR_ARG_INCOMP,
      "-bc_fixed, -bc_displacement, -traction and -mesh_convert apply to -backend plex only (the backend is "
      "%s)",
      opt_.backend.c_str());
  PetscCheck(opt_.bc_ramp >= 0 && std::isfinite(opt_.bc_ramp), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-bc_ramp %g: must be a finite time >= 0", opt_.bc_ramp);
  const auto& nm = opt_.newmark;
  PetscCheck(nm.refresh_contraction > 0 && nm.refresh_contraction < 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-lagged_refresh_contraction %g: must be in (0, 1)", nm.refresh_contraction);
  PetscCheck(nm.refresh_iterations >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-lagged_refresh_iterations %d: must be >= 1", nm.refresh_iterations);
  PetscCall(checkMaterialAuto());
  PetscFunctionReturn(0);
}

// The options block, the probe's checks, the checkpoint policy and the solver's options, the other checks,
// and the integrator's settings from the named choices.
PetscErrorCode FemdynRun::readOptions() {
  MPI_Comm comm = ctx_.comm();
  const auto& p = opt_.probe_set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "femdyn options", "");
  PetscCall(readModelOptions(PetscOptionsObject));
  PetscCall(readIntegratorOptions(PetscOptionsObject));
  PetscOptionsEnd();
  PetscCheck(
      !opt_.probe || (p.stiffness > 0 && p.speed >= 0 && p.depth >= 0 && p.haptic_rate > 0), comm,
      PETSC_ERR_ARG_OUTOFRANGE,
      "-probe: -probe_stiffness %g and -haptic_rate %g must be > 0, -probe_speed %g and -probe_depth %g >= 0",
      p.stiffness, p.haptic_rate, p.speed, p.depth);
  PetscCheck(!(opt_.probe && opt_.is_static), comm, PETSC_ERR_ARG_INCOMP,
             "-probe needs a dynamic run (not -static)");
  PetscCall(policy_.setFromOptions(comm, "femdyn"));
  PetscCall(suite::fem::createLinearSolver(comm, opt_.solver, &solver_));
  PetscCall(solver_->setFromOptions(comm)); // -solver petsc: -ksp_type, -pc_type, ...
  if (opt_.materialAuto()) {                // the nonlinear law's own solver (same kind and options)
    PetscCall(suite::fem::createLinearSolver(comm, opt_.solver, &solver_nl_));
    PetscCall(solver_nl_->setFromOptions(comm));
  }
  if (opt_.dt_adapt) { // the low-pass filter of the time-step error estimate: its own solver
    PetscCall(suite::fem::createLinearSolver(comm, opt_.solver, &solver_filter_));
    PetscCall(solver_filter_->setFromOptions(comm));
  }
  PetscCall(checkOptions());
  auto& nm = opt_.newmark;
  nm.initial_jacobian = opt_.jacobian == "initial";
  nm.lagged = opt_.jacobian == "lagged";
  nm.tangent_predictor = opt_.predictor == "tangent";
  if (opt_.time_scheme == "generalized_alpha") nm = suite::fem::generalizedAlpha(nm, opt_.rho_inf);
  PetscCall(checkTimeAdapt()); // after the scheme's beta is final
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
