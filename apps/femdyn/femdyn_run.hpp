// The femdyn run: options, mesh and model setup (Dirichlet plane, loads, ordering, solver), the static solve
// or the Newmark time loop with per-step timings and energies, and the HDF5/XDMF output.
#pragma once

#include "core/run_context.hpp"
#include "fem/assembly.hpp"
#include "fem/linear_solver.hpp"
#include "fem/newmark.hpp"
#include "fem/ordering.hpp"
#include "io/checkpoint.hpp"
#include "io/checkpoint_policy.hpp"

#include <memory>
#include <string>
#include <vector>

namespace femdyn_app {

struct Options {
  std::string mesh = "beam", mesh_file, material = "linear", ordering = "rcm", solver = "cholmod",
              mass = "consistent", dirichlet = "x=0", jacobian = "tangent", output, time_scheme = "newmark",
              predictor = "constant";
  double rho_inf = 1, beam_length = 10, young = 1000, poisson = 0.3, density = 1, dt = 0.01, tip_load = 0;
  double beam_size[2] = {1, 1}, gravity[3] = {0, 0, 0};
  PetscInt beam_cells[3] = {10, 1, 1}, order = 1, steps = 100, load_steps = 1, snapshot_every = 0;
  suite::fem::NewmarkParams newmark;
  PetscBool is_static = PETSC_FALSE;
  // Haptic probe: a rigid point pressing (along -y) on the surface node nearest to probe_point.
  PetscBool probe = PETSC_FALSE;
  double probe_point[3] = {1e300, 1e300, 1e300}; // default: top (max y) node of the free end, middle of z
  double probe_stiffness = 1000, probe_speed = 0.5, probe_depth = 0.2, haptic_rate = 1000;
};

struct StepRecord {
  double time, assemble, factor, solve, total, cpu, kinetic, strain, external, tip_uy;
  int newton, rejected, converged;
};

struct ProbeRecord { // haptic probe output
  int node = -1;
  std::vector<double> sync_time, force_full, force_predicted, compliance_yy; // per FEM step (sync point)
  std::vector<double> haptic_time, haptic_force;                             // per haptic tick
  double tick_seconds = 0, compliance_seconds = 0;                           // CPU totals
  long long ticks = 0;
};

struct Results {
  ProbeRecord probe;
  double ordering_time = 0, setup_time = 0, loop_time = 0;
  suite::fem::OrderingMetrics metrics;
  suite::fem::FactorStats factor;
  std::vector<StepRecord> steps;
  std::vector<std::pair<double, std::vector<double>>> snapshots; // time, full u
  std::vector<double> u_full;
  double tip_deflection = 0, tip_ux = 0; // static: mean -u_y and mean u_x over the tip-face nodes
  suite::fem::StaticResult stat;
};

class FemdynRun {
public:
  explicit FemdynRun(const suite::RunContext& ctx) : ctx_(ctx) {}
  PetscErrorCode readOptions();
  PetscErrorCode setup();
  PetscErrorCode solve();
  PetscErrorCode writeOutput() const;

private:
  PetscErrorCode solveStaticCase();
  PetscErrorCode solveDynamic();
  std::vector<double> fullDisplacement(const std::vector<double>& free) const;
  // Checkpoint/restart (femdyn_checkpoint.cpp): the Newmark state u, v, a at the end of `step`, the time,
  // and the step history and snapshots so far (a restarted run writes the same output as an uninterrupted
  // one). The state is replicated: rank 0 writes it, every rank reads it (broadcast).
  suite::CheckpointHeader checkpointHeader() const;
  PetscErrorCode writeCheckpointAt(const suite::fem::NewmarkState& s, long long step);
  PetscErrorCode readRestart(suite::fem::NewmarkState* s, long long* step);
  double tipDeflection(const std::vector<double>& u_full) const;
  double probeTarget(double t) const; // probe tip height y_d(t)
  PetscErrorCode findProbeNode(int* node) const;

  const suite::RunContext& ctx_;
  Options opt_;
  suite::CheckpointPolicy policy_;
  bool partial_ = false; // distributed assembly (-solver petsc at several ranks): partial sums per rank
  suite::fem::TetMesh mesh_;
  std::unique_ptr<suite::fem::Material> material_;
  suite::fem::ElasticModel model_;
  std::unique_ptr<suite::fem::LinearSolver> solver_;
  std::vector<int> perm_;
  std::vector<double> f_ext_;
  std::vector<int> tip_nodes_;
  Results res_;
};

PetscErrorCode runFemdyn(const suite::RunContext& ctx);

} // namespace femdyn_app
