// femdyn options: one function per group (model, time integration, Newton, haptic probe), named choices
// documented by -help from their registries in lib/fem (-material, -ordering, -solver, the integrator's
// -time_scheme, -jacobian, -newton_predictor, -mass), then the cross-option checks (collective PetscCheck).
#include "core/named_choice.hpp"
#include "core/option_string.hpp"
#include "fem/material.hpp"
#include "femdyn_run.hpp"

namespace femdyn_app {

namespace {
const std::vector<suite::Choice> kMeshes = {{"beam", "structured beam of hexahedra, 6 tets each"},
                                            {"file", "Gmsh or TetGen mesh given by -mesh_file"}};
} // namespace

PetscErrorCode FemdynRun::readModelOptions(PetscOptionItems* PetscOptionsObject) {
  PetscInt ncells = 3, nsize = 2;
  PetscFunctionBeginUser;
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-mesh", "Mesh", kMeshes, &opt_.mesh));
  PetscCall(suite::optionsString(PetscOptionsObject, "-mesh_file",
                                 "Gmsh .msh (2.2/4.1 ASCII) or TetGen basename (.node/.ele)",
                                 &opt_.mesh_file));
  PetscCall(PetscOptionsReal("-beam_length", "Beam length along x", "", opt_.beam_length, &opt_.beam_length,
                             nullptr));
  PetscCall(
      PetscOptionsRealArray("-beam_size", "Beam cross-section sy,sz", "", opt_.beam_size, &nsize, nullptr));
  PetscCall(PetscOptionsIntArray("-beam_cells", "Hexahedra nx,ny,nz", "", opt_.beam_cells, &ncells, nullptr));
  PetscCall(
      PetscOptionsInt("-order", "Element order: 1 (P1) or 2 (P2)", "", opt_.order, &opt_.order, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-material", "Material", suite::fem::materialChoices(),
                                 &opt_.material));
  PetscCall(PetscOptionsReal("-young", "Young's modulus E", "", opt_.young, &opt_.young, nullptr));
  PetscCall(PetscOptionsReal("-poisson", "Poisson ratio nu", "", opt_.poisson, &opt_.poisson, nullptr));
  PetscCall(PetscOptionsReal("-density", "Mass density", "", opt_.density, &opt_.density, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-ordering", "Fill-reducing ordering",
                                 suite::fem::orderingChoices(), &opt_.ordering));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-solver", "Linear solver", suite::fem::solverChoices(),
                                 &opt_.solver));
  PetscCall(suite::optionsString(PetscOptionsObject, "-dirichlet",
                                 "Clamped plane, e.g. x=0 (all DOFs of its nodes fixed), or none",
                                 &opt_.dirichlet));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::readTimeOptions(PetscOptionItems* PetscOptionsObject) {
  PetscInt ngrav = 3;
  auto& nm = opt_.newmark;
  PetscFunctionBeginUser;
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
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-time_scheme", "Time integrator",
                                 suite::fem::timeSchemeChoices(), &opt_.time_scheme));
  PetscCall(PetscOptionsReal("-rho_inf", "Generalized-alpha spectral radius at infinite omega dt, in [0, 1]",
                             "", opt_.rho_inf, &opt_.rho_inf, nullptr));
  PetscCall(PetscOptionsReal("-newmark_beta", "Newmark beta", "", nm.beta, &nm.beta, nullptr));
  PetscCall(PetscOptionsReal("-newmark_gamma", "Newmark gamma", "", nm.gamma, &nm.gamma, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::readNewtonOptions(PetscOptionItems* PetscOptionsObject) {
  auto& nm = opt_.newmark;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt("-newton_max_it", "Newton iterations per step (1: linearly implicit)", "",
                            nm.newton_max_it, &nm.newton_max_it, nullptr));
  PetscCall(PetscOptionsReal("-newton_rtol", "Newton relative residual tolerance", "", nm.newton_rtol,
                             &nm.newton_rtol, nullptr));
  PetscCall(PetscOptionsReal("-newton_atol", "Newton absolute residual tolerance", "", nm.newton_atol,
                             &nm.newton_atol, nullptr));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-jacobian", "Newton matrix",
                                 suite::fem::jacobianChoices(), &opt_.jacobian));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-newton_predictor", "Newton start",
                                 suite::fem::predictorChoices(), &opt_.predictor));
  PetscCall(suite::optionsChoice(PetscOptionsObject, "-mass", "Mass matrix", suite::fem::massChoices(),
                                 &opt_.mass));
  PetscCall(PetscOptionsReal("-rayleigh_alpha", "Rayleigh damping C = alpha M + beta K0: alpha", "",
                             nm.rayleigh_mass, &nm.rayleigh_mass, nullptr));
  PetscCall(PetscOptionsReal("-rayleigh_beta", "Rayleigh damping: beta", "", nm.rayleigh_stiffness,
                             &nm.rayleigh_stiffness, nullptr));
  PetscCall(PetscOptionsInt("-max_halvings", "Step rejections (dt halvings) allowed per step", "",
                            nm.max_halvings, &nm.max_halvings, nullptr));
  PetscCall(PetscOptionsInt("-snapshot_every", "Displacement/velocity snapshot every N steps (0: none)", "",
                            opt_.snapshot_every, &opt_.snapshot_every, nullptr));
  PetscCall(suite::optionsString(PetscOptionsObject, "-output", "HDF5 output file", &opt_.output));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::readProbeOptions(PetscOptionItems* PetscOptionsObject) {
  PetscInt npt = 3;
  auto& p = opt_.probe_set;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool("-probe", "Haptic probe: a rigid point pressing on a surface node (penalty)", "",
                             opt_.probe, &opt_.probe, nullptr));
  PetscCall(PetscOptionsRealArray("-probe_point",
                                  "Probe contact point x,y,z (nearest node; default: top of the free end)",
                                  "", p.point, &npt, nullptr));
  PetscCall(PetscOptionsReal("-probe_stiffness", "Probe penalty stiffness k (force per length)", "",
                             p.stiffness, &p.stiffness, nullptr));
  PetscCall(PetscOptionsReal("-probe_speed", "Probe indentation speed (along -y, from the node's height)", "",
                             p.speed, &p.speed, nullptr));
  PetscCall(PetscOptionsReal("-probe_depth", "Probe travel below the node's initial height, then it holds",
                             "", p.depth, &p.depth, nullptr));
  PetscCall(PetscOptionsReal("-haptic_rate", "Haptic force output rate in Hz (local model between FEM steps)",
                             "", p.haptic_rate, &p.haptic_rate, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::checkProbeOptions() const {
  MPI_Comm comm = ctx_.comm();
  const auto& p = opt_.probe_set;
  PetscFunctionBeginUser;
  PetscCheck(
      !opt_.probe || (p.stiffness > 0 && p.speed >= 0 && p.depth >= 0 && p.haptic_rate > 0), comm,
      PETSC_ERR_ARG_OUTOFRANGE,
      "-probe: -probe_stiffness %g and -haptic_rate %g must be > 0, -probe_speed %g and -probe_depth %g >= 0",
      p.stiffness, p.haptic_rate, p.speed, p.depth);
  PetscCheck(!(opt_.probe && opt_.is_static), comm, PETSC_ERR_ARG_INCOMP,
             "-probe needs a dynamic run (not -static)");
  PetscFunctionReturn(0);
}

// Value ranges and combinations (the named choices are already validated by optionsChoice).
PetscErrorCode FemdynRun::checkOptions() const {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  PetscCheck(opt_.order == 1 || opt_.order == 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-order %d: must be 1 or 2",
             (int)opt_.order);
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
  PetscCheck(!opt_.output.empty() || ctx_.helpRequested(), comm, PETSC_ERR_ARG_WRONG,
             "-output FILE.h5 is required");
  PetscCheck(opt_.rho_inf >= 0 && opt_.rho_inf <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-rho_inf %g: must be in [0, 1]", opt_.rho_inf);
  PetscFunctionReturn(0);
}

PetscErrorCode FemdynRun::readOptions() {
  MPI_Comm comm = ctx_.comm();
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "femdyn options", "");
  PetscCall(readModelOptions(PetscOptionsObject));
  PetscCall(readTimeOptions(PetscOptionsObject));
  PetscCall(readNewtonOptions(PetscOptionsObject));
  PetscCall(readProbeOptions(PetscOptionsObject));
  PetscOptionsEnd();
  PetscCall(checkProbeOptions());
  PetscCall(policy_.setFromOptions(comm, "femdyn"));
  PetscCall(suite::fem::createLinearSolver(comm, opt_.solver, &solver_));
  PetscCall(solver_->setFromOptions(comm)); // -solver petsc: -ksp_type, -pc_type, ...
  PetscCall(checkOptions());
  auto& nm = opt_.newmark;
  nm.initial_jacobian = opt_.jacobian == "initial";
  nm.tangent_predictor = opt_.predictor == "tangent";
  if (opt_.time_scheme == "generalized_alpha") nm = suite::fem::generalizedAlpha(nm, opt_.rho_inf);
  PetscFunctionReturn(0);
}

} // namespace femdyn_app
