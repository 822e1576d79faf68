// Checkpoint/restart of the contact app with lib/io/checkpoint.hpp: the state the next step
// depends on: every body's position, orientation, linear and angular velocity (nb x 13), the sleeping
// counters (nb x 2) and the last step's contacts with their impulses (warm start and the scaled_box /
// splitting estimates; (nc + 1) x 8, row 0 holds nc), plus step and time in the header. The state is
// replicated on every rank: rank 0 writes it and reads it, then broadcasts, so a restart may use any rank
// count and gives bitwise the same trajectory.
#pragma once

#include "contact/stepper.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace contact_app {

// Header tag that must match on restart: scene and friction model.
std::string checkpointScheme(const std::string& scene, suite::contact::FrictionModel f);

PetscErrorCode writeContactCheckpoint(MPI_Comm comm, const std::string& path, const std::string& scheme,
                                      long long step, double time, double dt,
                                      const std::vector<suite::contact::Body>& bodies,
                                      const suite::contact::Stepper& stepper);
// Restores bodies (dynamic state only; shapes and masses come from the scene) and the stepper state.
PetscErrorCode readContactCheckpoint(MPI_Comm comm, const std::string& path, const std::string& scheme,
                                     double dt, std::vector<suite::contact::Body>* bodies,
                                     suite::contact::Stepper* stepper, long long* step, double* time);

} // namespace contact_app
