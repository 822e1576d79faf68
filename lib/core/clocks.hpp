// The suite's clocks. CPU time is the clock of the phase timings (FEM phases, orderings, LCP solves, the time
// loop), because on a shared, loaded machine the wall clock measures the neighbours as much as the code; wall
// times are reported next to it.
#pragma once

#include <petsctime.h>

#include <ctime>

namespace suite {
// CPU seconds of the calling thread (CLOCK_THREAD_CPUTIME_ID).
inline double threadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
// CPU seconds of this process, all threads (CLOCK_PROCESS_CPUTIME_ID).
inline double processCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
// Wall-clock seconds (PetscTime).
inline double wallSeconds() {
  PetscLogDouble t;
  PetscTime(&t);
  return t;
}
} // namespace suite
