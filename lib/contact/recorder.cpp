// Frames and per-step statistics of a contact run (see recorder.hpp).
#include "contact/recorder.hpp"

#include <limits>

namespace suite::contact {

void Recorder::frame(const std::vector<Body>& bodies, long long step, double t) {
  frame_time.push_back(t);
  frame_step.push_back(step);
  for (const Body& b : bodies) {
    pos.insert(pos.end(), {b.x.x(), b.x.y(), b.x.z()});
    quat.insert(quat.end(), {b.q.w(), b.q.x(), b.q.y(), b.q.z()});
    vel.insert(vel.end(), {b.v.x(), b.v.y(), b.v.z(), b.w.x(), b.w.y(), b.w.z()});
  }
}

void Recorder::step(const StepStats& s, double t, double energy_value, double wall) {
  time.push_back(t);
  contacts.push_back(s.contacts);
  sleeping.push_back(s.sleeping);
  rows.push_back(s.rows);
  int idx = -1;
  for (size_t k = 0; k < solver_names.size(); ++k)
    if (solver_names[k] == s.solver) idx = (int)k;
  if (idx < 0 && !s.solver.empty()) {
    solver_names.push_back(s.solver);
    idx = (int)solver_names.size() - 1;
  }
  solver_index.push_back(idx);
  iterations.push_back(s.iterations);
  pivots.push_back(s.pivots);
  splitting_iterations.push_back(s.splitting_iterations);
  fallbacks.push_back(s.fallbacks);
  proximal_steps.push_back(s.proximal_steps);
  factorizations.push_back(s.factorizations);
  budget_stop.push_back(s.budget_stop);
  islands.push_back(s.islands);
  largest_island_bodies.push_back(s.largest_island_bodies);
  largest_island_contacts.push_back(s.largest_island_contacts);
  penetration.push_back(s.penetration);
  force_ratio.push_back(s.force_ratio);
  cone_violation.push_back(s.cone_violation);
  residual.push_back(s.residual);
  splitting_error.push_back(s.splitting_error);
  energy.push_back(energy_value);
  step_wall.push_back(wall);
  split_errors.insert(split_errors.end(), s.split_errors.begin(), s.split_errors.end());
  split_ratios.insert(split_ratios.end(), s.split_ratios.begin(), s.split_ratios.end());
  // with islands the ratios are the largest island's passes, the errors the most passes of any island (with
  // -friction auto the largest island may run none): NaN for the passes without a ratio
  split_ratios.resize(split_errors.size(), std::numeric_limits<double>::quiet_NaN());
  split_offset.push_back((long long)split_errors.size());
  friction_rung.push_back(s.friction_rung);
  auto_solves.push_back(s.auto_solves);
  target_missed.push_back(s.target_missed);
  for (auto [from, to] : {std::pair{&s.problem_rungs, &problem_rung},
                          {&s.problem_rows, &problem_rows},
                          {&s.problem_times, &problem_time},
                          {&s.problem_violations, &problem_violation}})
    to->insert(to->end(), from->begin(), from->end());
  problem_offset.push_back((long long)problem_rung.size());
}

void Recorder::jointStep(const StepStats& s, const Stepper& stepper, const std::vector<Body>& bodies) {
  if (joints.empty()) joints = stepper.joints();
  joint_error.push_back(s.joint_error);
  joint_velocity_error.push_back(s.joint_velocity_error);
  projection_iterations.push_back(s.projection_iterations);
  shake_iterations.push_back(s.shake_iterations);
  actuation_solves.push_back(s.actuation_solves);
  for (int k = 0; k < (int)joints.size(); ++k) {
    const bool axial = joints[k].type == JointType::Hinge || joints[k].type == JointType::Slider;
    joint_coordinate.push_back(axial ? jointCoordinate(joints[k], bodies).phi : 0.0);
    motor_power.push_back(stepper.motorPower(k));
    Vec3 f, m;
    stepper.jointReaction(k, bodies, &f, &m);
    joint_force.insert(joint_force.end(), {f.x(), f.y(), f.z()});
    joint_torque.insert(joint_torque.end(), {m.x(), m.y(), m.z()});
  }
}

} // namespace suite::contact
