// Option range and memory estimate checks (see resource_checks.hpp).
#include "core/resource_checks.hpp"

#include "core/option_text.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

namespace suite {

PetscErrorCode checkIntOptionRange(MPI_Comm comm, const char* name, long long lo) {
  std::string s;
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(name, &s, &set));
  if (!set) PetscFunctionReturn(0);
  const char* text = s.c_str();
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text, &end, 10);
  const bool ok = errno == 0 && end != text && *end == '\0' && v >= lo && v <= (long long)PETSC_MAX_INT;
  PetscCheck(ok, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: must be an integer in [%lld, %lld] (PetscInt is %d-bit)", name, shownValue(s).c_str(),
             lo, (long long)PETSC_MAX_INT, (int)(8 * sizeof(PetscInt)));
  PetscFunctionReturn(0);
}

PetscErrorCode checkIntListOptionRange(MPI_Comm comm, const char* name, long long lo) {
  std::string s;
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(findOptionText(name, &s, &set));
  if (!set) PetscFunctionReturn(0);
  const char* text = s.c_str();
  bool ok = true;
  for (const char* p = text; ok;) {
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(p, &end, 10);
    ok = errno == 0 && end != p && (*end == '\0' || *end == ',') && v >= lo && v <= (long long)PETSC_MAX_INT;
    if (!ok || *end == '\0') break;
    p = end + 1;
  }
  PetscCheck(ok, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: every entry must be an integer in [%lld, %lld] (PetscInt is %d-bit)", name,
             shownValue(s).c_str(), lo, (long long)PETSC_MAX_INT, (int)(8 * sizeof(PetscInt)));
  PetscFunctionReturn(0);
}

PetscErrorCode checkIndexCount(MPI_Comm comm, double count, const char* what, const char* options) {
  PetscFunctionBeginUser;
  PetscCheck(count <= (double)PETSC_MAX_INT, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s: %.4g %s, more than the largest PetscInt %lld (PetscInt is %d-bit)", options, count, what,
             (long long)PETSC_MAX_INT, (int)(8 * sizeof(PetscInt)));
  PetscFunctionReturn(0);
}

PetscErrorCode checkChoice(MPI_Comm comm, const char* name, const char* value, const char* const* choices,
                           int n, PetscInt* index) {
  std::string list;
  PetscFunctionBeginUser;
  *index = -1;
  for (int i = 0; i < n; ++i) {
    if (!std::strcmp(value, choices[i])) *index = i;
    list += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(choices[i]);
  }
  PetscCheck(*index >= 0, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown %s '%s': %s", name, value, list.c_str());
  PetscFunctionReturn(0);
}

namespace {
// The limit per node in bytes: -max_memory_gib if given (> 0), else 90% of nodeMemoryBytes(); *source says
// which. Options are replicated on every rank: every rank takes the same path.
PetscErrorCode memoryLimit(double* limit, std::string* source) {
  PetscReal gib = 0.0;
  PetscBool set = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-max_memory_gib", &gib, &set));
  if (set && gib > 0) {
    *limit = gib * 1073741824.0;
    *source = "the -max_memory_gib limit";
    PetscFunctionReturn(0);
  }
  std::string which;
  const double have = nodeMemoryBytes(&which);
  *limit = have > 0 ? 0.9 * have : 0.0;
  *source = "90% of the node's " + bytesText(have) + " of " + which;
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode checkMemoryEstimate(MPI_Comm comm, double bytes_this_rank, const char* what) {
  MPI_Comm node;
  double need = bytes_this_rank, limit = 0.0;
  PetscBool check = PETSC_TRUE;
  std::string source;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-memory_check", &check, nullptr));
  if (!check) PetscFunctionReturn(0);
  PetscCall(memoryLimit(&limit, &source));
  PetscCallMPI(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &need, 1, MPI_DOUBLE, MPI_SUM, node));
  PetscCallMPI(MPI_Comm_free(&node));
  // The worst node over the limit (largest need), so that every rank reports the same numbers.
  double worst[2] = {limit > 0 && !(need <= limit) ? need : 0.0, 0.0};
  worst[1] = worst[0] > 0 ? limit : 0.0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(
      worst[0] == 0.0, comm, PETSC_ERR_MEM,
      "%s needs about %s of memory on one node, more than %s (%s): use more nodes or a smaller problem, "
      "or override the check with -max_memory_gib GIB or -memory_check false",
      what, bytesText(worst[0]).c_str(), bytesText(worst[1]).c_str(), source.c_str());
  PetscFunctionReturn(0);
}

double nodeMemoryBytes(std::string* source) {
  double have = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
  if (!(have > 0)) have = 0.0;
  std::string which = "physical memory";
  for (const std::string& f : cgroupLimitFiles("/proc/self/cgroup", "/sys/fs/cgroup")) {
    const double limit = cgroupLimitBytes(f);
    if (limit > 0 && (have == 0.0 || limit < have)) {
      have = limit;
      which = "cgroup limit (" + f + ")";
    }
  }
  if (source) *source = which;
  return have;
}

double cgroupLimitBytes(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return 0.0;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (errno != 0 || end == text.c_str() || *end != '\0' || text[0] == '-' || v == 0) return 0.0;
  return v >= (1ULL << 62) ? 0.0 : (double)v; // cgroup v1 writes "no limit" as about 2^63
}

std::vector<std::string> cgroupLimitFiles(const std::string& proc_cgroup, const std::string& mount) {
  std::vector<std::string> files = {mount + "/memory.max", mount + "/memory/memory.limit_in_bytes"};
  std::ifstream in(proc_cgroup);
  std::string line;
  while (std::getline(in, line)) {
    const size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
    if (b == std::string::npos) continue;
    const std::string controllers = "," + line.substr(a + 1, b - a - 1) + ",", path = line.substr(b + 1);
    if (path.empty() || path == "/" || path.find("..") != std::string::npos) continue;
    if (line.compare(0, a, "0") == 0 && controllers == ",,") files.push_back(mount + path + "/memory.max");
    if (controllers.find(",memory,") != std::string::npos)
      files.push_back(mount + "/memory" + path + "/memory.limit_in_bytes");
  }
  return files;
}

std::string bytesText(double bytes) {
  const char* units[] = {"bytes", "kiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (u < 6 && bytes >= 1024.0) {
    bytes /= 1024.0;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, units[u]);
  return buf;
}

} // namespace suite
