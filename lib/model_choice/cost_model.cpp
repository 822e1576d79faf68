// Cost law fitted to timed runs (see cost_model.hpp).
#include "model_choice/cost_model.hpp"

#include "core/comma_list.hpp"
#include "io/h5_input.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace suite::model_choice {

void CostModel::add(const std::string& family, double n, double seconds) {
  samples_[family].push_back({n, std::max(seconds, 1e-9)}); // a run below the clock's resolution: 1 ns
}

CostModel::Fit CostModel::fit(const std::string& family) const {
  Fit f;
  auto it = samples_.find(family);
  if (it == samples_.end() || it->second.empty()) return f;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = (double)it->second.size();
  for (const auto& [n, t] : it->second) {
    const double x = std::log(n), y = std::log(t);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double den = m * sxx - sx * sx;
  f.b = den > 0 ? (m * sxy - sx * sy) / den : 0.0;
  f.log_c = (sy - f.b * sx) / m;
  return f;
}

double CostModel::predict(const std::string& family, double n) const {
  const Fit f = fit(family);
  return std::exp(f.log_c + f.b * std::log(n));
}

double CostModel::exponent(const std::string& family) const { return fit(family).b; }

PetscErrorCode CostModel::checkCovers(MPI_Comm comm, const std::vector<std::string>& families) const {
  PetscFunctionBeginUser;
  for (const std::string& name : families) {
    std::set<double> ns;
    auto it = samples_.find(name);
    if (it != samples_.end())
      for (const auto& s : it->second) ns.insert(s.first);
    PetscCheck(ns.size() >= 2, comm, PETSC_ERR_ARG_WRONG,
               "-cost_model %s: no timed runs of %s at two resolutions or more (it has %zu)",
               source_.empty() ? "(pilots)" : source_.c_str(), name.c_str(), ns.size());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CostModel::load(MPI_Comm comm, const std::string& path) {
  suite::H5Input in;
  bool has = false;
  std::string names;
  std::vector<double> fam, n, sec;
  suite::Dims dims;
  PetscFunctionBeginUser;
  PetscCall(in.open(comm, path));
  PetscCall(in.hasObject("/model_choice/pilots/seconds", &has));
  PetscCheck(has, comm, PETSC_ERR_FILE_UNEXPECTED,
             "-cost_model %s: no /model_choice/pilots (write one with a -target_error run's -output)",
             path.c_str());
  PetscCall(in.readAttribute("/model_choice", "families", &names));
  PetscCall(in.readAll("/model_choice/pilots/family", &fam, &dims));
  PetscCall(in.readAll("/model_choice/pilots/n", &n, &dims));
  PetscCall(in.readAll("/model_choice/pilots/seconds", &sec, &dims));
  PetscCall(in.close());
  const std::vector<std::string> list = splitCommaList(names);
  PetscCheck(fam.size() == n.size() && n.size() == sec.size(), comm, PETSC_ERR_FILE_UNEXPECTED,
             "-cost_model %s: /model_choice/pilots datasets of different lengths", path.c_str());
  for (size_t i = 0; i < fam.size(); ++i) {
    const long long f = (long long)fam[i];
    PetscCheck(f >= 0 && f < (long long)list.size() && n[i] > 0 && std::isfinite(sec[i]) && sec[i] >= 0,
               comm, PETSC_ERR_FILE_UNEXPECTED, "-cost_model %s: pilot %zu is malformed", path.c_str(), i);
    add(list[(size_t)f], n[i], sec[i]);
  }
  source_ = path;
  PetscFunctionReturn(0);
}

} // namespace suite::model_choice
