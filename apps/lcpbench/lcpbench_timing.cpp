// lcpbench's timing of one (solver, problem) by repetition (-time_repeat T, -time_batches B; see lcpbench.hpp).
// One solve of a small problem (~1 us at n = 10) is as short as one read of the thread CPU clock (a system
// call, ~0.5 to 1 us), so a single timed run measures the clock and the cache state as much as the solver.
// The usual remedy of micro-benchmark harnesses (e.g. Google Benchmark, Python's timeit): repeat the same
// call in batches of R runs, R grown until one batch takes >= T CPU seconds, then time B batches of R runs
// and keep the fastest batch's time per run. Every solver and auto are timed by the same rule; the record's
// status, counts and residual come from a first, separately timed run (the solvers are deterministic). With or
// without repetition, every solver is timed after the same untimed warm-up (-warmup) and in an order per
// problem that does not favour any place in -solvers (warmUp and solverAt, lcpbench_batch.cpp).
#include "lcpbench.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

namespace lcpbench_app {

using suite::lcp::Result;

namespace {

double threadCpuSeconds() {
  timespec c{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c);
  return static_cast<double>(c.tv_sec) + 1e-9 * static_cast<double>(c.tv_nsec);
}

// CPU and wall seconds of reps untimed runs.
void timeBatch(const std::function<Result(bool)>& run, long long reps, double* cpu, double* wall) {
  const double w0 = MPI_Wtime(), c0 = threadCpuSeconds();
  for (long long k = 0; k < reps; ++k) run(false);
  *cpu = threadCpuSeconds() - c0;
  *wall = MPI_Wtime() - w0;
}

} // namespace

long long repetitionsFor(double batch_cpu, long long reps, double repeat_time) {
  if (batch_cpu >= repeat_time || reps >= kMaxRepetitions) return reps;
  const double grow = std::ceil(1.2 * repeat_time / std::max(batch_cpu, 1e-9));
  return std::min(kMaxRepetitions, reps * std::max(2LL, static_cast<long long>(std::min(grow, 1e9))));
}

Result timedRun(const std::function<Result(bool timed)>& run, const Timing& t) {
  Result r = run(true);
  if (t.repeat_time <= 0) return r;
  long long reps = 1;
  double cpu = 0, wall = 0;
  for (;;) { // calibration: the last batch (at the final R) is the first of the B
    timeBatch(run, reps, &cpu, &wall);
    const long long next = repetitionsFor(cpu, reps, t.repeat_time);
    if (next == reps) break;
    reps = next;
  }
  double best_cpu = cpu, best_wall = wall;
  for (int b = 1; b < t.batches; ++b) {
    timeBatch(run, reps, &cpu, &wall);
    best_cpu = std::min(best_cpu, cpu);
    best_wall = std::min(best_wall, wall);
  }
  r.cpu_time = best_cpu / static_cast<double>(reps);
  r.time = best_wall / static_cast<double>(reps);
  return r;
}

} // namespace lcpbench_app
