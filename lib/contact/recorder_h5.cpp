// The HDF5 layout of a contact run's record (see recorder.hpp): /bodies, /frames, /steps, /splitting.
#include "contact/recorder.hpp"

#include "io/h5_output.hpp"

namespace suite::contact {

namespace {
PetscErrorCode writeBodies(H5Output& out, const std::vector<Body>& bodies) {
  using U = unsigned long long;
  const U nb = bodies.size();
  std::vector<int> type(nb), is_static(nb);
  std::vector<double> dims(nb * 4), mass(nb);
  std::string names;
  std::vector<std::string> name(nb);
  PetscFunctionBeginUser;
  for (U i = 0; i < nb; ++i) {
    const Body& b = bodies[i];
    type[i] = (int)b.shape.type;
    is_static[i] = b.is_static;
    dims[4 * i + 0] = b.shape.radius;
    dims[4 * i + 1] = b.shape.half_length;
    dims[4 * i + 2] = b.shape.half.x();
    dims[4 * i + 3] = b.shape.half.y();
    mass[i] = b.mass;
    names += (i ? "," : "") + b.name;
    name[i] = b.name;
  }
  if (nb) {
    PetscCall(out.writeReplicated("/bodies/type", type.data(), {nb}, ""));
    PetscCall(out.writeReplicated("/bodies/static", is_static.data(), {nb}, ""));
    PetscCall(out.writeReplicated("/bodies/radius_halflength_halfx_halfy", dims.data(), {nb, 4}, "m"));
    PetscCall(out.writeReplicated("/bodies/mass", mass.data(), {nb}, "kg"));
    PetscCall(out.writeReplicatedStrings("/bodies/name", name)); // the scene's names, in body order
  }
  PetscCall(out.writeAttribute("/bodies", "names", names));
  PetscCall(out.writeAttribute("/bodies", "types", "0 plane, 1 sphere, 2 box, 3 capsule, 4 cylinder"));
  PetscFunctionReturn(0);
}

PetscErrorCode writeFrames(H5Output& out, unsigned long long nb, const Recorder& rec) {
  const unsigned long long nf = rec.frame_time.size();
  PetscFunctionBeginUser;
  if (nf) {
    PetscCall(out.writeReplicated("/frames/time", rec.frame_time.data(), {nf}, "s"));
    PetscCall(out.writeReplicated("/frames/step", rec.frame_step.data(), {nf}, ""));
    PetscCall(out.writeReplicated("/frames/positions", rec.pos.data(), {nf, nb, 3}, "m"));
    PetscCall(out.writeReplicated("/frames/orientations", rec.quat.data(), {nf, nb, 4}, ""));
    PetscCall(out.writeReplicated("/frames/velocities", rec.vel.data(), {nf, nb, 6}, "m/s, rad/s"));
  }
  PetscCall(out.writeAttribute("/frames", "orientations", "unit quaternions w, x, y, z (body to world)"));
  PetscCall(out.writeAttribute("/frames", "velocities", "vx, vy, vz (m/s), wx, wy, wz (rad/s), world frame"));
  PetscFunctionReturn(0);
}

PetscErrorCode writeSteps(H5Output& out, const Recorder& rec) {
  const unsigned long long ns = rec.time.size();
  PetscFunctionBeginUser;
  if (ns) {
    PetscCall(out.writeReplicated("/steps/time", rec.time.data(), {ns}, "s"));
    PetscCall(out.writeReplicated("/steps/contacts", rec.contacts.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/rows", rec.rows.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/sleeping", rec.sleeping.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/force_ratio", rec.force_ratio.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/cone_violation", rec.cone_violation.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/solver", rec.solver_index.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/iterations", rec.iterations.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/pivots", rec.pivots.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/fallbacks", rec.fallbacks.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/proximal_steps", rec.proximal_steps.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/residual", rec.residual.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/splitting_iterations", rec.splitting_iterations.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/splitting_error", rec.splitting_error.data(), {ns}, "m/s"));
    PetscCall(out.writeReplicated("/steps/energy", rec.energy.data(), {ns}, "J"));
    PetscCall(out.writeReplicated("/steps/wall_time", rec.step_wall.data(), {ns}, "s"));
    PetscCall(out.writeReplicated("/steps/factorizations", rec.factorizations.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/budget_stop", rec.budget_stop.data(), {ns}, ""));
    PetscCall(out.writeReplicated("/steps/penetration", rec.penetration.data(), {ns}, "m"));
    PetscCall(out.writeReplicated("/steps/islands", rec.islands.data(), {ns}, ""));
    PetscCall(
        out.writeReplicated("/steps/largest_island_bodies", rec.largest_island_bodies.data(), {ns}, ""));
    PetscCall(
        out.writeReplicated("/steps/largest_island_contacts", rec.largest_island_contacts.data(), {ns}, ""));
  }
  PetscCall(out.writeAttribute("/steps", "islands",
                               "-contact_islands on: islands solved per step (0: off or no contact), the "
                               "largest one's dynamic bodies and contacts"));
  std::string sn;
  for (size_t k = 0; k < rec.solver_names.size(); ++k) sn += (k ? "," : "") + rec.solver_names[k];
  PetscCall(out.writeAttribute("/steps", "solver_names", sn));
  PetscCall(out.writeAttribute("/steps", "force_ratio",
                               "sum over body pairs |sum tangential impulse| / sum normal"));
  PetscFunctionReturn(0);
}

PetscErrorCode writeSplitting(H5Output& out, const Recorder& rec) {
  const unsigned long long nh = rec.split_errors.size(), ns = rec.time.size();
  PetscFunctionBeginUser;
  if (nh) {
    PetscCall(out.writeReplicated("/splitting/error", rec.split_errors.data(), {nh}, "m/s"));
    PetscCall(out.writeReplicated("/splitting/force_ratio", rec.split_ratios.data(), {nh}, ""));
    PetscCall(out.writeReplicated("/splitting/offset", rec.split_offset.data(), {ns + 1}, ""));
    PetscCall(out.writeAttribute("/splitting", "layout",
                                 "pass k of step s at offset[s] + k; error = max|delta lambda_n| "
                                 "(pass 1: max lambda_n)"));
  }
  PetscFunctionReturn(0);
}
// -friction auto: /friction_auto (see Recorder).
PetscErrorCode writeFrictionAuto(H5Output& out, const Recorder& rec) {
  const unsigned long long np = rec.problem_rung.size(), ns = rec.time.size();
  PetscFunctionBeginUser;
  if (rec.auto_rungs.empty() || !ns) PetscFunctionReturn(0);
  PetscCall(out.writeReplicated("/friction_auto/step_rung", rec.friction_rung.data(), {ns}, ""));
  PetscCall(out.writeReplicated("/friction_auto/step_rung_solves", rec.auto_solves.data(), {ns}, ""));
  PetscCall(out.writeReplicated("/friction_auto/step_target_missed", rec.target_missed.data(), {ns}, ""));
  PetscCall(out.writeReplicated("/friction_auto/offset", rec.problem_offset.data(), {ns + 1}, ""));
  if (np) {
    PetscCall(out.writeReplicated("/friction_auto/rung", rec.problem_rung.data(), {np}, ""));
    PetscCall(out.writeReplicated("/friction_auto/rows", rec.problem_rows.data(), {np}, ""));
    PetscCall(out.writeReplicated("/friction_auto/time", rec.problem_time.data(), {np}, "s"));
    PetscCall(out.writeReplicated("/friction_auto/cone_violation", rec.problem_violation.data(), {np}, ""));
  }
  PetscCall(out.writeAttribute("/friction_auto", "rungs", rec.auto_rungs));
  PetscCall(out.writeAttribute("/friction_auto", "layout",
                               "problem k (island k, or the whole scene) of step s at offset[s] + k: rung "
                               "(index into rungs), LCP rows, wall time of its rung solves, cone violation; "
                               "step_rung: the highest rung of the step (-1: no contact)"));
  PetscFunctionReturn(0);
}
// Joints: /joints (the table, the per-step errors and reactions; see Recorder).
PetscErrorCode writeJoints(H5Output& out, const Recorder& rec) {
  using U = unsigned long long;
  const U nj = rec.joints.size(), ns = rec.joint_error.size();
  std::vector<int> type(nj), pair(2 * nj);
  std::vector<std::string> name(nj);
  PetscFunctionBeginUser;
  if (!nj || !ns) PetscFunctionReturn(0);
  for (U k = 0; k < nj; ++k) {
    type[k] = (int)rec.joints[k].type;
    pair[2 * k] = rec.joints[k].a, pair[2 * k + 1] = rec.joints[k].b;
    name[k] = rec.joints[k].name;
  }
  PetscCall(out.writeReplicated("/joints/type", type.data(), {nj}, ""));
  PetscCall(out.writeReplicated("/joints/bodies", pair.data(), {nj, 2}, ""));
  PetscCall(out.writeReplicatedStrings("/joints/name", name));
  PetscCall(out.writeReplicated("/joints/error", rec.joint_error.data(), {ns}, "m"));
  PetscCall(out.writeReplicated("/joints/velocity_error", rec.joint_velocity_error.data(), {ns}, "m/s"));
  PetscCall(out.writeReplicated("/joints/projection_iterations", rec.projection_iterations.data(), {ns}, ""));
  PetscCall(out.writeReplicated("/joints/shake_iterations", rec.shake_iterations.data(), {ns}, ""));
  PetscCall(out.writeReplicated("/joints/force", rec.joint_force.data(), {ns, nj, 3}, "N"));
  PetscCall(out.writeReplicated("/joints/torque", rec.joint_torque.data(), {ns, nj, 3}, "N m"));
  PetscCall(out.writeReplicated("/joints/coordinate", rec.joint_coordinate.data(), {ns, nj}, "rad or m"));
  PetscCall(out.writeReplicated("/joints/motor_power", rec.motor_power.data(), {ns, nj}, "W"));
  PetscCall(out.writeReplicated("/joints/actuation_solves", rec.actuation_solves.data(), {ns}, ""));
  PetscCall(out.writeAttribute("/joints", "types", "0 ball, 1 hinge, 2 slider, 3 fixed, 4 distance"));
  PetscCall(out.writeAttribute("/joints", "layout",
                               "bodies: (a, b) body indices, b = -1 the world; per step: shake_iterations "
                               "(-1: SHAKE stopped contracting, the velocity projection alone) "
                               "of the velocities, error = max |Phi| after the position projection "
                               "(projection_iterations), velocity_error = max |G v| at the step's end, "
                               "force and torque (about the anchor) of the joint on body a, world frame, "
                               "limit and motor included; coordinate: hinge angle (rad) or slider travel "
                               "(m) of b relative to a at the step's end (0: other types); motor_power: "
                               "motor torque (force) times the rate it drove; actuation_solves: the "
                               "solves of the step's velocities (limits' and motors' active set)"));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode Recorder::write(H5Output& out, const std::vector<Body>& bodies) const {
  PetscFunctionBeginUser;
  PetscCall(writeBodies(out, bodies));
  PetscCall(writeFrames(out, bodies.size(), *this));
  PetscCall(writeSteps(out, *this));
  PetscCall(writeSplitting(out, *this));
  PetscCall(writeFrictionAuto(out, *this));
  PetscCall(writeJoints(out, *this));
  PetscFunctionReturn(0);
}

} // namespace suite::contact
