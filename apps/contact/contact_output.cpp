// Output of the contact app (HDF5 via suite::H5Output, replicated data written by rank 0; XDMF sidecar).
#include "contact_output.hpp"

#include "contact/xdmf_points.hpp"
#include "io/xdmf.hpp"
#include "io/h5_output.hpp"

namespace suite::contact {

PetscErrorCode writeContactOutput(const RunContext& ctx, const std::string& path, const SceneParams& scene,
                                  const StepperOptions& step, const std::vector<Body>& bodies,
                                  const Recorder& rec, const RunOutcome& outcome) {
  H5Output out;
  PetscFunctionBeginUser;
  PetscCall(out.open(ctx.comm(), path));
  PetscCall(out.writeProvenance(ctx));
  PetscCall(out.writeAttribute("/", "scene", scene.scene));
  PetscCall(out.writeAttribute("/", "friction", frictionName(step.friction)));
  PetscCall(out.writeAttribute("/", "lcp_solver", step.lcp_solver));
  PetscCall(out.writeAttribute("/", "contact_islands", step.islands ? "on" : "off"));
  PetscCall(out.writeAttribute("/", "contact_accuracy", accuracyName(step.accuracy)));
  PetscCall(out.writeAttribute("/", "dt", step.dt));
  PetscCall(out.writeAttribute("/", "mu", step.mu));
  if (step.friction == FrictionModel::Auto)
    PetscCall(out.writeAttribute("/", "target_error", step.target_error));
  PetscCall(out.writeAttribute("/", "theta", scene.theta_deg));
  PetscCall(out.writeAttribute("/", "steps_requested", outcome.steps_requested));
  PetscCall(out.writeAttribute("/", "steps", outcome.steps_done));
  PetscCall(out.writeAttribute("/", "status", outcome.status));
  if (!outcome.failure.empty()) PetscCall(out.writeAttribute("/", "failure", outcome.failure));
  PetscCall(out.writeAttribute("/", "simplifications", simplifications(step, bodies)));
  PetscCall(rec.write(out, bodies));
  PetscCall(out.commit(&ctx));
  if (ctx.rank() == 0 && !rec.frame_time.empty())
    writeXdmf(suite::xdmfPathFor(path), path, bodies.size(), rec.frame_time.size(), rec.frame_time);
  PetscFunctionReturn(0);
}

} // namespace suite::contact
