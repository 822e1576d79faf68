// Periodic checkpoint policy and restart-file selection (see checkpoint_policy.hpp).
#include "io/checkpoint_policy.hpp"

#include "core/option_text.hpp"
#include "core/option_value.hpp"
#include "io/h5_output.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <sys/stat.h>
#include <vector>

namespace suite {
namespace {

// Step numbers of the complete checkpoints DIR/<app>_<digits>.h5, ascending ("*.tmp" files are partial).
std::vector<long long> listCheckpointSteps(const std::string& dir, const std::string& app) {
  std::vector<long long> steps;
  DIR* d = opendir(dir.c_str());
  if (!d) return steps;
  const std::string prefix = app + "_";
  while (dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (name.size() <= prefix.size() + 3 || name.compare(0, prefix.size(), prefix) != 0) continue;
    if (name.compare(name.size() - 3, 3, ".h5") != 0) continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 3);
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit)) continue;
    steps.push_back(std::stoll(digits));
  }
  closedir(d);
  std::sort(steps.begin(), steps.end());
  return steps;
}

// Creates dir (one level) if missing; returns an errno-style message or "".
std::string ensureDirectory(const std::string& dir) {
  struct stat st;
  if (stat(dir.c_str(), &st) == 0) return S_ISDIR(st.st_mode) ? "" : "exists and is not a directory";
  if (mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST) return std::strerror(errno);
  return "";
}

} // namespace

PetscErrorCode CheckpointPolicy::setFromOptions(MPI_Comm comm, const std::string& app) {
  std::string dir, restart;
  PetscInt every = 0, keep = 2;
  PetscReal wall = 0.0;
  PetscFunctionBeginUser;
  comm_ = comm;
  app_ = app;
  PetscOptionsBegin(comm, nullptr, "Checkpoint/restart options", nullptr);
  PetscCall(suite::optionsString(PetscOptionsObject, "-checkpoint_dir",
                                 "Directory for periodic and final checkpoints", &dir));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-checkpoint_every", "Checkpoint every N steps (0: off)",
                              nullptr, every, &every, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-checkpoint_wall",
                               "Checkpoint every S seconds of wall time (0: off)", nullptr, wall, &wall,
                               nullptr));
  PetscCall(suite::optionsInt(PetscOptionsObject, "-checkpoint_keep",
                              "Number of newest checkpoint files kept", nullptr, keep, &keep, nullptr));
  PetscCall(suite::optionsString(PetscOptionsObject, "-restart",
                                 "Checkpoint file to restart from, or 'latest' in -checkpoint_dir",
                                 &restart));
  PetscOptionsEnd();
  PetscCheck(every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %d: must be >= 0", (int)every);
  PetscCheck(wall >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_wall %g: must be >= 0", (double)wall);
  PetscCheck(keep >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_keep %d: must be >= 1", (int)keep);
  PetscCheck(!dir.empty() || (every == 0 && wall == 0), comm, PETSC_ERR_ARG_WRONG,
             "-checkpoint_every/-checkpoint_wall need -checkpoint_dir");
  PetscCheck(restart != "latest" || !dir.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-restart latest needs -checkpoint_dir");
  dir_ = dir;
  restart_ = restart;
  every_ = every;
  wall_ = wall;
  keep_ = (int)keep;
  if (enabled()) {
    int rank;
    char msg[256] = "";
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (rank == 0) std::snprintf(msg, sizeof msg, "%s", ensureDirectory(dir_).c_str());
    PetscCallMPI(MPI_Bcast(msg, sizeof msg, MPI_CHAR, 0, comm));
    PetscCheck(!msg[0], comm, PETSC_ERR_FILE_OPEN, "-checkpoint_dir %s: %s", shownValue(dir_).c_str(), msg);
    PetscCall(checkOutputWritable(comm, pathForStep(0), "checkpoint_dir"));
  }
  last_wall_ = MPI_Wtime();
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointPolicy::due(long long step, bool* yes) const {
  PetscFunctionBeginUser;
  int flag = 0;
  if (enabled()) {
    flag = every_ > 0 && step > 0 && step % every_ == 0;
    if (wall_ > 0 && MPI_Wtime() - last_wall_ >= wall_) flag = 1;
    PetscCallMPI(MPI_Bcast(&flag, 1, MPI_INT, 0, comm_)); // rank 0's clock decides for everyone
  }
  *yes = flag != 0;
  PetscFunctionReturn(0);
}

std::string CheckpointPolicy::pathForStep(long long step) const {
  char name[64];
  std::snprintf(name, sizeof name, "_%010lld.h5", step);
  return dir_ + "/" + app_ + name;
}

PetscErrorCode CheckpointPolicy::written(long long step) {
  int rank;
  PetscFunctionBeginUser;
  last_wall_ = MPI_Wtime();
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) {
    const std::vector<long long> steps = listCheckpointSteps(dir_, app_);
    const size_t n = steps.size();
    for (size_t i = 0; i + keep_ < n; ++i)
      if (steps[i] != step) std::remove(pathForStep(steps[i]).c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointPolicy::restartPath(std::string* path) const {
  PetscFunctionBeginUser;
  PetscCheck(restartRequested(), comm_, PETSC_ERR_ARG_WRONG, "no -restart given");
  std::string p; // rank 0's answer, whole
  int rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) {
    p = restart_;
    if (restart_ == "latest") {
      const std::vector<long long> steps = listCheckpointSteps(dir_, app_);
      p = steps.empty() ? "" : pathForStep(steps.back());
    }
    struct stat st;
    if (!p.empty() && stat(p.c_str(), &st) != 0) p.clear();
  }
  PetscCall(broadcastString(comm_, &p));
  PetscCheck(!p.empty(), comm_, PETSC_ERR_FILE_OPEN, "-restart %s: %s", shownValue(restart_).c_str(),
             restart_ == "latest" ? ("no checkpoint " + app_ + "_*.h5 in " + shownValue(dir_)).c_str()
                                  : "no such file");
  *path = p;
  PetscFunctionReturn(0);
}

} // namespace suite
