// CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID): the clock of the FEM phase timings and ordering
// times, because on a shared, loaded machine the wall clock measures the neighbours as much as the code.
#pragma once

#include <petsctime.h>

#include <ctime>

namespace suite::fem {
inline double threadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
// Wall-clock seconds (PetscTime), for the wall timings reported next to the CPU ones.
inline double wallSeconds() {
  PetscLogDouble t;
  PetscTime(&t);
  return t;
}
} // namespace suite::fem
