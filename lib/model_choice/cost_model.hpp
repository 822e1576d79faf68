// The cost model of an accuracy-target run, per candidate family: seconds(n) = steps(n) x seconds_per_step(n),
//   steps(n) = s n^q                  fitted in log-log to the step counts of complete runs (the pilots),
//   seconds_per_step(n) = c0 + c1 n^b  c0 >= 0 the per-step overhead that dominates small grids, fitted by
//                                      least squares relative to the measured seconds per step of every timed
//                                      run: the pilots and short timing runs (a few steps) on finer grids,
// so that the cost of a fine candidate is interpolated from timings near it rather than extrapolated from the
// pilots alone. Calibrated at run time on this machine and rank count, or loaded from the runs stored in an
// earlier run's /model_choice (-cost_model FILE). None of q, b, c0, c1 is a constant written in the code.
#pragma once

#include <petscsys.h>

#include <map>
#include <string>
#include <vector>

namespace suite::model_choice {

struct TimedRun {
  double n = 0, seconds = 0, steps = 0;
  bool complete = false; // ran to t_final (its steps count for steps(n))
};

class CostModel {
public:
  void add(const std::string& family, const TimedRun& run);
  // Loads the timed runs of FILE's /model_choice/pilots and /model_choice/timings (datasets family, n, seconds,
  // steps; attribute families).
  PetscErrorCode load(MPI_Comm comm, const std::string& path);
  bool loaded() const { return !source_.empty(); }
  const std::string& source() const { return source_; }
  // Collective check: at least one of the families has complete runs at two resolutions or more (covers).
  PetscErrorCode checkCoversAny(MPI_Comm comm, const std::vector<std::string>& families) const;
  bool covers(const std::string& family) const;              // complete runs at two resolutions or more
  double predict(const std::string& family, double n) const; // seconds
  double exponent(const std::string& family) const;          // d log seconds / d log n at the finest sample

private:
  struct Fit {
    double log_s = 0.0, q = 0.0;        // steps
    double c0 = 0.0, c1 = 0.0, b = 0.0; // seconds per step
  };
  Fit fit(const std::string& family) const;
  std::map<std::string, std::vector<TimedRun>> runs_;
  std::string source_; // "" or the file loaded
};

} // namespace suite::model_choice
