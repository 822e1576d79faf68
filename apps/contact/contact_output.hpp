// Output of the contact app: per-frame trajectories, per-step solver statistics, splitting histories,
// body table, and an XDMF point-cloud sidecar (Polyvertex, one grid per frame) so ParaView plays the scene.
#pragma once

#include "contact/recorder.hpp"
#include "contact/stepper.hpp"
#include "core/run_context.hpp"

#include <string>
#include <vector>

namespace suite::contact {

struct OutputInfo {
  std::string scene, friction, lcp_solver, status, simplifications;
  double dt = 0, mu = 0, theta = 0;
  long long steps_requested = 0, steps_done = 0;
};

PetscErrorCode writeContactOutput(const RunContext& ctx, const std::string& path,
                                  const std::vector<Body>& bodies, const Recorder& rec,
                                  const OutputInfo& info);

} // namespace suite::contact
