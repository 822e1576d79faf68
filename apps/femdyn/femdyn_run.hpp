// The femdyn run: options (femdyn_options.cpp), sizes (femdyn_size_check.cpp), mesh and model setup (femdyn_setup.cpp), the static solve or
// the Newmark dynamics on the suite's time loop (femdyn_dynamics.*, the haptic probe as an observer,
// fem/haptic_probe.hpp), checkpoints (femdyn_checkpoint.cpp) and the HDF5/XDMF output (femdyn_output.cpp).
#pragma once

#include "core/run_context.hpp"
#include "fem/beam_loads.hpp"
#include "fem/haptic_probe.hpp"
#include "fem/law_switch.hpp"
#include "fem/linear_solver.hpp"
#include "fem/newmark.hpp"
#include "fem/ordering.hpp"
#include "fem/step_control.hpp"
#include "io/checkpoint_policy.hpp"
#include "io/xdmf.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace suite {
class H5Output;
} // namespace suite

namespace femdyn_app {

struct Options {
  std::string mesh = "beam", mesh_file, material = "linear", ordering = "rcm", solver = "cholmod",
              mass = "consistent", dirichlet = "x=0", jacobian = "tangent", output, time_scheme = "newmark",
              predictor = "constant", backend = "replicated";
  // -backend plex: supports and loads by group (a Gmsh physical group's name or tag; femdyn_plex_groups.cpp)
  std::string bc_fixed;        // G1,G2,...: every displacement component zero
  std::string traction;        // G:tx,ty,tz[;G2:...]: dead traction per area
  std::string bc_displacement; // G:ux=a,uz=b[;G2:...]: components held at values (ramped over bc_ramp)
  double bc_ramp = 0;          // > 0: the prescribed values grow linearly from 0 over this time
  std::string mesh_convert;    // -backend plex: write the mesh as the suite's parallel mesh file, then stop
  double rho_inf = 1, young = 1000, poisson = 0.3, density = 1, dt = 0.01, tip_load = 0,
         gravity[3] = {0, 0, 0};
  suite::fem::BeamSpec beam; // -beam_length, -beam_size, -beam_cells
  PetscInt order = 1, steps = 100, load_steps = 1, snapshot_every = 0;
  PetscInt plex_rank_cap = 0; // -backend plex: most mesh points or local DOFs one rank may hold (0: no cap)
  suite::fem::NewmarkParams newmark;
  PetscBool is_static = PETSC_FALSE, probe = PETSC_FALSE;
  suite::fem::HapticProbeSettings probe_set; // -probe: a rigid point pressing (along -y) on a surface node
  // -material auto (femdyn_material_auto.cpp): the linear law while the estimated error of the linear law is
  // below the target, else -material_auto_law; -target_error E and the switch band of the policy.
  std::string auto_law = "stvk";
  suite::fem::LawSwitchPolicy law_policy;
  PetscBool target_set = PETSC_FALSE;
  bool materialAuto() const { return material == "auto"; }
  // -dt_adapt (femdyn_time_adapt.cpp): the step from the Zienkiewicz-Xie estimate (fem/step_control.hpp) over
  // t_final = -steps x -dt, -dt the first try. The user's -target_error E is the budget of the whole run:
  // E for the time discretisation, or with -material auto E/2 for the law and E/2 for the time steps.
  PetscBool dt_adapt = PETSC_FALSE;
  double target_error = 0; // the user's E (with -dt_adapt)
  suite::fem::StepControlParams step_control;
  double load_release = 0; // > 0: the loads are removed at this time (free vibration after)
};

struct StepRecord {
  double time, assemble, factor, solve, total, cpu, kinetic, strain, external, tip_uy, residual;
  int newton, rejected, converged, factorizations;
};
// Its columns, in the order of /steps and of the checkpoint's history: the reals, then the counts.
template <class T> struct StepColumn {
  const char* name;
  T StepRecord::*field;
  const char* units;
};
inline constexpr StepColumn<double> kStepReals[] = {{"time", &StepRecord::time, "s"},
                                                    {"assemble", &StepRecord::assemble, "s"},
                                                    {"factor", &StepRecord::factor, "s"},
                                                    {"solve", &StepRecord::solve, "s"},
                                                    {"wall", &StepRecord::total, "s"},
                                                    {"cpu", &StepRecord::cpu, "s"},
                                                    {"kinetic_energy", &StepRecord::kinetic, "J"},
                                                    {"strain_energy", &StepRecord::strain, "J"},
                                                    {"external_work", &StepRecord::external, "J"},
                                                    {"tip_deflection", &StepRecord::tip_uy, "m"},
                                                    {"residual", &StepRecord::residual, "N"}};
inline constexpr StepColumn<int> kStepCounts[] = {{"newton_iterations", &StepRecord::newton, ""},
                                                  {"rejected", &StepRecord::rejected, ""},
                                                  {"converged", &StepRecord::converged, ""},
                                                  {"factorizations", &StepRecord::factorizations, ""}};

struct Results {
  std::string status = "completed"; // the output's status attribute (core/run_summary.hpp)
  suite::fem::HapticProbeRecord probe;
  double ordering_time = 0, setup_time = 0, loop_time = 0;
  std::string ordering_taken; // -ordering, or the one auto chose
  suite::fem::OrderingMetrics metrics;
  suite::fem::FactorStats factor;
  std::vector<StepRecord> steps;
  std::vector<std::pair<double, std::vector<double>>> snapshots; // time, full u
  std::vector<double> u_full;
  double tip_deflection = 0, tip_ux = 0; // static: mean -u_y and mean u_x over the tip-face nodes
  suite::fem::StaticResult stat;
  // -material auto, per step record (step 0 first): the law used (0 linear, 1 -material_auto_law) and the
  // estimated relative error of the linear law at the step's result; switches and CPU seconds per law.
  std::vector<int> law;
  std::vector<double> law_estimate;
  int law_switches = 0;
  double law_cpu[2] = {0, 0};
  int law_steps[2] = {0, 0};
  int law_factorizations[2] = {0, 0}; // numeric factorisations of K_eff per law (linear: one per dt)
  // -dt_adapt, per step record (step 0 first): dt, the estimate over the tolerance, rejected tries before the
  // accepted one; per try: start time, dt, ratio, accepted (0/1); the sum of the accepted steps' relative
  // local estimates (the run's estimated error) and the K_eff factorisations of all tries.
  std::vector<double> adapt_dt, adapt_ratio, try_time, try_dt, try_ratio;
  std::vector<int> adapt_rejected, try_accepted;
  double adapt_error = 0, adapt_unresolved = 0;
  int adapt_factorizations = 0;
};

class FemdynRun {
public:
  explicit FemdynRun(const suite::RunContext& ctx) : ctx_(ctx) {}
  PetscErrorCode readOptions();
  const Options& options() const { return opt_; }
  suite::CheckpointPolicy& checkpointPolicy() { return policy_; }
  PetscErrorCode setup();
  // The static solve or the time loop, then the output (written by the loop's final write).
  PetscErrorCode solve();

private:
  friend class FemdynDynamics; // the time-stepped side of the run (femdyn_dynamics.hpp)
  // Options (femdyn_options.cpp); the first two run inside the options block.
  PetscErrorCode readModelOptions(PetscOptionItems* PetscOptionsObject);
  PetscErrorCode readIntegratorOptions(PetscOptionItems* PetscOptionsObject);
  PetscErrorCode checkOptions() const;
  // Sizes before the allocations they drive (femdyn_size_check.cpp).
  PetscErrorCode checkIntegerOptions() const;
  PetscErrorCode checkModelSizes(double nodes, double elems, const char* what) const;
  PetscErrorCode checkBeamSizes() const;
  PetscErrorCode checkFactorSizes() const;
  // Setup (femdyn_setup.cpp).
  PetscErrorCode buildMesh();
  PetscErrorCode clampAndSetupModel();
  PetscErrorCode orderAndAnalyze();
  // Solves (femdyn_run.cpp).
  PetscErrorCode solveStaticCase();
  PetscErrorCode solveDynamic();
  // Output (femdyn_output.cpp), in the output log stage.
  PetscErrorCode writeOutput() const;
  PetscErrorCode writeRunAttributes(suite::H5Output& out) const;
  PetscErrorCode writeOrdering(suite::H5Output& out) const;
  PetscErrorCode writeMesh(suite::H5Output& out) const;
  PetscErrorCode writeSteps(suite::H5Output& out) const;
  PetscErrorCode writeProbe(suite::H5Output& out) const;
  // -material auto (femdyn_material_auto.cpp): the option checks and the output.
  PetscErrorCode checkMaterialAuto() const;
  PetscErrorCode writeMaterialAuto(suite::H5Output& out) const;
  // -dt_adapt (femdyn_time_adapt.cpp): the option checks and budget split, the output.
  PetscErrorCode checkTimeAdapt();
  PetscErrorCode writeTimeAdapt(suite::H5Output& out) const;
  PetscErrorCode writeSnapshots(suite::H5Output& out, std::vector<suite::XdmfTetStep>* xsteps) const;

  // The external force at time t (free DOFs): f_ext_, zero from -load_release on.
  bool released(double t) const { return opt_.load_release > 0 && t >= opt_.load_release; }
  std::function<void(double, double*)> loadAt() const {
    return [this](double t, double* f) {
      if (released(t))
        std::fill(f, f + f_ext_.size(), 0.0);
      else
        std::copy(f_ext_.begin(), f_ext_.end(), f);
    };
  }

  const suite::RunContext& ctx_;
  Options opt_;
  suite::CheckpointPolicy policy_;
  bool partial_ = false; // distributed assembly (-solver petsc at several ranks): partial sums per rank
  suite::fem::TetMesh mesh_;
  std::unique_ptr<suite::fem::Material> material_;
  suite::fem::ElasticModel model_;
  std::unique_ptr<suite::fem::LinearSolver> solver_;
  // -material auto: the nonlinear law on the same mesh with its own solver (the linear law's factorisation of
  // K_eff stays in solver_ while the nonlinear law refactorises its tangent).
  std::unique_ptr<suite::fem::Material> material_nl_;
  suite::fem::ElasticModel model_nl_;
  std::unique_ptr<suite::fem::LinearSolver> solver_nl_;
  // -dt_adapt: the low-pass filter's solver (M + K0 / wc^2, refactorised when dt changes; fem/step_control.hpp)
  std::unique_ptr<suite::fem::LinearSolver> solver_filter_;
  std::vector<int> perm_;
  std::vector<double> f_ext_;
  std::vector<int> tip_nodes_;
  Results res_;
};

PetscErrorCode runFemdyn(const suite::RunContext& ctx);
// -backend plex (femdyn_plex.cpp): the distributed DMPlex run, from the options read by FemdynRun.
PetscErrorCode runPlexFemdyn(const suite::RunContext& ctx, const Options& opt,
                             suite::CheckpointPolicy& policy);

} // namespace femdyn_app
