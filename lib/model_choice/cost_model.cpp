// Cost law fitted to timed runs (see cost_model.hpp).
#include "model_choice/cost_model.hpp"

#include "core/comma_list.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace suite::model_choice {

void CostModel::add(const std::string& family, const TimedRun& run) {
  TimedRun r = run;
  r.seconds = std::max(r.seconds, 1e-9); // a run below the clock's resolution: 1 ns
  r.steps = std::max(r.steps, 1.0);
  runs_[family].push_back(r);
}

namespace {
// steps = s n^q by least squares in log-log over the complete runs.
void fitSteps(const std::vector<TimedRun>& runs, double* log_s, double* q) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (const TimedRun& r : runs)
    if (r.complete) {
      const double x = std::log(r.n), y = std::log(r.steps);
      sx += x, sy += y, sxx += x * x, sxy += x * y, m += 1;
    }
  const double den = m * sxx - sx * sx;
  *q = den > 0 ? (m * sxy - sx * sy) / den : 0.0;
  *log_s = m > 0 ? (sy - *q * sx) / m : 0.0;
}

// y = c0 + c1 n^b, c0 >= 0, c1 > 0: for each b on a grid, c0 and c1 by linear least squares relative to y; the b
// of the smallest relative residual.
void fitPerStep(const std::vector<TimedRun>& runs, double* c0, double* c1, double* b) {
  double best = INFINITY;
  for (double e = 0.25; e <= 4.0 + 1e-9; e += 0.01) {
    double s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0; // normal equations of sum ((c0 + c1 x) / y - 1)^2
    for (const TimedRun& r : runs) {
      const double x = std::pow(r.n, e), y = r.seconds / r.steps, w = 1.0 / (y * y);
      s00 += w, s01 += w * x, s11 += w * x * x, r0 += w * y, r1 += w * x * y;
    }
    const double det = s00 * s11 - s01 * s01;
    double a0 = det > 0 ? (r0 * s11 - r1 * s01) / det : 0.0, a1 = det > 0 ? (s00 * r1 - s01 * r0) / det : 0.0;
    if (a0 < 0) a0 = 0.0, a1 = r1 / s11; // no negative overhead
    if (!(a1 > 0)) continue;
    double res = 0;
    for (const TimedRun& r : runs)
      res += std::pow((a0 + a1 * std::pow(r.n, e)) * r.steps / r.seconds - 1.0, 2);
    if (res < best - 1e-12) best = res, *c0 = a0, *c1 = a1, *b = e;
  }
}
} // namespace

CostModel::Fit CostModel::fit(const std::string& family) const {
  Fit f;
  auto it = runs_.find(family);
  if (it == runs_.end() || it->second.empty()) return f;
  fitSteps(it->second, &f.log_s, &f.q);
  fitPerStep(it->second, &f.c0, &f.c1, &f.b);
  return f;
}

double CostModel::predict(const std::string& family, double n) const {
  const Fit f = fit(family);
  return std::exp(f.log_s + f.q * std::log(n)) * (f.c0 + f.c1 * std::pow(n, f.b));
}

double CostModel::exponent(const std::string& family) const {
  const Fit f = fit(family);
  double n = 1;
  auto it = runs_.find(family);
  if (it != runs_.end())
    for (const TimedRun& r : it->second) n = std::max(n, r.n);
  const double per_step = f.c0 + f.c1 * std::pow(n, f.b);
  return f.q + (per_step > 0 ? f.b * f.c1 * std::pow(n, f.b) / per_step : 0.0);
}

namespace {
size_t completeResolutions(const std::map<std::string, std::vector<TimedRun>>& runs,
                           const std::string& name) {
  std::set<double> ns;
  auto it = runs.find(name);
  if (it != runs.end())
    for (const TimedRun& r : it->second)
      if (r.complete) ns.insert(r.n);
  return ns.size();
}
} // namespace

bool CostModel::covers(const std::string& family) const {
  return completeResolutions(runs_, family) >= 2;
}

PetscErrorCode CostModel::checkCoversAny(MPI_Comm comm, const std::vector<std::string>& families) const {
  std::string names;
  PetscFunctionBeginUser;
  for (const std::string& name : families) {
    if (covers(name)) PetscFunctionReturn(0);
    names += (names.empty() ? "" : ",") + name;
  }
  PetscCheck(
      families.empty(), comm, PETSC_ERR_ARG_WRONG,
      "-cost_model %s has no complete runs at two resolutions of any family asked for (%s): give a file "
      "whose target run piloted one of them, or drop -cost_model",
      source_.c_str(), names.c_str());
  PetscFunctionReturn(0);
}

namespace {
// The runs of one table (pilots: complete; timings: a few steps) of /model_choice; cols[4]: the failed flag
// (a file without that column: none failed).
PetscErrorCode readRuns(const suite::H5Input& in, const std::string& table, std::vector<double> cols[5]) {
  const char* names[5] = {"family", "n", "seconds", "steps", "failed"};
  suite::Dims dims;
  bool has_failed = false;
  PetscFunctionBeginUser;
  for (int c = 0; c < 4; ++c)
    PetscCall(in.readAll("/model_choice/" + table + "/" + names[c], &cols[c], &dims));
  PetscCall(in.hasObject("/model_choice/" + table + "/failed", &has_failed));
  if (has_failed) PetscCall(in.readAll("/model_choice/" + table + "/failed", &cols[4], &dims));
  cols[4].resize(cols[0].size(), 0.0);
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode CostModel::load(MPI_Comm comm, const std::string& path) {
  suite::H5Input in;
  bool has = false;
  std::string names;
  std::vector<double> cols[2][5];
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(in.hasObject("/model_choice/timings/steps", &has));
  PetscCheck(
      has, comm, PETSC_ERR_FILE_UNEXPECTED,
      "-cost_model %s: no /model_choice/pilots and /timings (write one with a -target_error run's -output)",
      path.c_str());
  PetscCall(in.readAttribute("/model_choice", "families", &names));
  PetscCall(readRuns(in, "pilots", cols[0]));
  PetscCall(readRuns(in, "timings", cols[1]));
  PetscCall(in.close());
  const std::vector<std::string> list = splitCommaList(names);
  for (int t = 0; t < 2; ++t)
    for (size_t i = 0; i < cols[t][0].size(); ++i) {
      if (cols[t][4][i] != 0.0) continue; // a failed run: its time says nothing of the family's cost
      const long long f = (long long)cols[t][0][i];
      const double n = cols[t][1][i], sec = cols[t][2][i], steps = cols[t][3][i];
      PetscCheck(f >= 0 && f < (long long)list.size() && n > 0 && std::isfinite(sec) && sec >= 0 &&
                     steps >= 1,
                 comm, PETSC_ERR_FILE_UNEXPECTED, "-cost_model %s: run %zu of /model_choice/%s is malformed",
                 path.c_str(), i, t ? "timings" : "pilots");
      add(list[(size_t)f], {n, sec, steps, t == 0});
    }
  source_ = path;
  PetscFunctionReturn(0);
}

} // namespace suite::model_choice
