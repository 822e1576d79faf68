// Output of the contact app: the run's settings and outcome as root attributes, the record of the run
// (Recorder::write: bodies, frames, steps, splitting histories), and an XDMF point-cloud sidecar
// (Polyvertex, one grid per frame) so ParaView plays the scene.
#pragma once

#include "contact/recorder.hpp"
#include "contact/scenes.hpp"
#include "contact/stepper.hpp"
#include "core/run_context.hpp"

#include <string>
#include <vector>

namespace suite::contact {

// The run's outcome: "completed", "failed: ..." or "stopped at step N (...)", steps asked for and done.
struct RunOutcome {
  std::string status;  // core/run_summary.hpp's runStatus
  std::string failure; // a failed step's cause ("step N: why; problem dumped to FILE"), else empty
  long long steps_requested = 0, steps_done = 0;
};

// The settings written are the scene's and the stepper's (friction model, solver, dt, mu, theta).
PetscErrorCode writeContactOutput(const RunContext& ctx, const std::string& path, const SceneParams& scene,
                                  const StepperOptions& step, const std::vector<Body>& bodies,
                                  const Recorder& rec, const RunOutcome& outcome);

} // namespace suite::contact
