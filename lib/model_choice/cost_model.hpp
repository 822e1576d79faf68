// The cost model of an accuracy-target run: seconds(n) = c n^b per candidate family, both c and the exponent
// b fitted by least squares in log-log to timed runs on this machine and rank count (the pilots, calibrated at
// run time), or to the pilots stored in an earlier run's /model_choice group (-cost_model FILE). Nothing of
// it is a constant written in the code: a 1D explicit scheme shows b near 2, a 2D one near 3, overheads less.
#pragma once

#include <petscsys.h>

#include <map>
#include <string>
#include <vector>

namespace suite::model_choice {

class CostModel {
public:
  void add(const std::string& family, double n, double seconds);
  // Loads the samples of FILE's /model_choice/pilots (datasets family, n, seconds; attribute families).
  PetscErrorCode load(MPI_Comm comm, const std::string& path);
  bool loaded() const { return !source_.empty(); }
  const std::string& source() const { return source_; }
  // Collective check: every family has samples at two or more resolutions.
  PetscErrorCode checkCovers(MPI_Comm comm, const std::vector<std::string>& families) const;
  double predict(const std::string& family, double n) const; // seconds
  double exponent(const std::string& family) const;          // b

private:
  struct Fit {
    double log_c = 0.0, b = 0.0;
  };
  Fit fit(const std::string& family) const;
  std::map<std::string, std::vector<std::pair<double, double>>> samples_; // family -> (n, seconds)
  std::string source_;                                                    // "" or the file loaded
};

} // namespace suite::model_choice
