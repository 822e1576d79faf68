// Wall time of each phase of the contact steps on this process, summed over the steps (the contact app's
// -contact_phase_times prints them per rank): how much of a step is the work dealt over ranks (the islands'
// solves) and how much every rank repeats (collision, matching, integration), and how long a rank waits for
// the others at the gather. Timing only: nothing of the physics depends on it. With islands off (or with
// -dump_problems, which solves every island on every rank) nothing is dealt: the solve is the step's rest.
#pragma once

#include <chrono>
#include <ctime>

namespace suite::contact {

struct PhaseTimes {
  double collision = 0.0;   // broad + narrow phase and tangent frames (findContacts)
  double match = 0.0;       // previous impulses matched to the contacts, islands split
  double own_solves = 0.0;  // the islands this process solved (each: its problem built and solved)
  double dealing = 0.0;     // the whole dealing: own solves + waiting for the other ranks + the gather
  double unpack = 0.0;      // every island's answer put back into the step's velocities and impulses
  double integration = 0.0; // integration, force measures, the state kept for the next step
  long long own_islands = 0, islands = 0, steps = 0;
  // CPU time of this process's thread (not inflated by other jobs sharing the core): the whole steps, the
  // dealing, and the islands it solved. The dealing's CPU less the own solves' is the polling while waiting
  // for the other ranks plus the gather; a step's CPU less that polling is what the rank would need of a
  // free core.
  double cpu_steps = 0.0, cpu_dealing = 0.0, cpu_own_solves = 0.0;
};

// CPU seconds of the calling thread so far (CLOCK_THREAD_CPUTIME_ID).
inline double threadCpu() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// Seconds since a steady-clock time point, and restarts it (t = now).
inline double lap(std::chrono::steady_clock::time_point* t) {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - *t).count();
  *t = now;
  return s;
}

} // namespace suite::contact
