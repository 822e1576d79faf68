// What a contact run records: frames (every body's position, orientation and velocities at chosen steps)
// and the statistics of every step (contacts, problem size, solver, iterations, fallbacks, splitting history,
// energy, wall time), in flat arrays, and writes them to HDF5 (the output of apps/contact).
#pragma once

#include "contact/stepper.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {
class H5Output;
}

namespace suite::contact {

struct Recorder {
  // frames
  std::vector<double> frame_time, pos, quat, vel; // F x nb x {3, 4, 6}
  std::vector<long long> frame_step;
  // per step
  std::vector<int> contacts, sleeping, rows, solver_index, iterations, splitting_iterations, fallbacks,
      proximal_steps, factorizations, budget_stop, islands, largest_island_bodies, largest_island_contacts;
  std::vector<long long> pivots;
  std::vector<double> time, force_ratio, cone_violation, residual, splitting_error, energy, step_wall,
      penetration;
  std::vector<std::string> solver_names;
  // splitting histories (flattened, offsets per step)
  std::vector<double> split_errors, split_ratios;
  std::vector<long long> split_offset{0};
  // -friction auto (friction_auto.hpp): per step the highest rung, rung solves and problems that missed the
  // target; per problem (islands in order) rung, LCP rows, time (s), cone violation, offsets per step
  std::vector<int> friction_rung, auto_solves, target_missed;
  std::vector<double> problem_rung, problem_rows, problem_time, problem_violation;
  std::vector<long long> problem_offset{0};
  std::string auto_rungs; // the ladder's names, comma-separated ("": not auto)
  // joints: the joint table, per step the largest |Phi| after the projection, its iterations, the largest
  // |G v|, the solves of the velocities (the limits' and motors' active set), per step and joint the reaction
  // force and torque (about the anchor) on body a (steps x nj x 3), the coordinate (hinge, slider; 0 for the
  // others) at the step's end and the motor's power (0 without a motor) (steps x nj)
  std::vector<Joint> joints;
  std::vector<double> joint_error, joint_velocity_error, joint_force, joint_torque, joint_coordinate,
      motor_power;
  std::vector<int> actuation_solves;
  std::vector<int> projection_iterations, shake_iterations;

  void frame(const std::vector<Body>& bodies, long long step, double t);
  void step(const StepStats& s, double t, double energy_value, double wall);
  // The joint record of the step just recorded by step() (a run with joints calls both, every step).
  void jointStep(const StepStats& s, const Stepper& stepper, const std::vector<Body>& bodies);
  // Writes the body table and everything recorded (recorder_h5.cpp): /bodies, /frames, /steps, /splitting,
  // /friction_auto and /joints.
  PetscErrorCode write(H5Output& out, const std::vector<Body>& bodies) const;
};

} // namespace suite::contact
