// Output of the contact app: per-frame trajectories, per-step solver statistics, splitting histories,
// body table, and an XDMF point-cloud sidecar (Polyvertex, one grid per frame) so ParaView plays the scene.
#pragma once

#include "contact/stepper.hpp"
#include "core/run_context.hpp"

#include <string>
#include <vector>

namespace suite::contact {

struct Recorder {
  // frames
  std::vector<double> frame_time, pos, quat, vel; // F x nb x {3, 4, 6}
  std::vector<long long> frame_step;
  // per step
  std::vector<int> contacts, sleeping, rows, solver_index, iterations, splitting_iterations, fallbacks;
  std::vector<long long> pivots;
  std::vector<double> time, force_ratio, cone_violation, residual, splitting_error, energy, step_wall;
  std::vector<std::string> solver_names;
  // splitting histories (flattened, offsets per step)
  std::vector<double> split_errors, split_ratios;
  std::vector<long long> split_offset{0};

  void frame(const std::vector<Body>& bodies, long long step, double t);
  void step(const StepStats& s, double t, double energy_value, double wall);
};

struct OutputInfo {
  std::string scene, friction, lcp_solver, status, simplifications;
  double dt = 0, mu = 0, theta = 0;
  long long steps_requested = 0, steps_done = 0;
};

PetscErrorCode writeContactOutput(const RunContext& ctx, const std::string& path,
                                  const std::vector<Body>& bodies, const Recorder& rec,
                                  const OutputInfo& info);

} // namespace suite::contact
