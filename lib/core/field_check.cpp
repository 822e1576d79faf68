// Collective field checks: non-finite values and values below a floor stop the run on all ranks.
#include "core/field_check.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <limits>

namespace suite {
namespace {

// First offending global index (or INT_MAX) and its value, agreed on by all ranks.
struct Bad {
  PetscInt index;
  double value, coord;
};

PetscErrorCode firstBad(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride, PetscInt comp,
                        double floor, bool use_floor, const FieldLocation& w, Bad* bad) {
  PetscFunctionBeginUser;
  long long local = std::numeric_limits<long long>::max();
  double val = 0.0, coord = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const double v = data[i * stride + comp];
    if (!std::isfinite(v) || (use_floor && !(v > floor))) {
      local = (long long)w.global_offset + i;
      val = v;
      coord = w.coords ? w.coords[i] : 0.0;
      break;
    }
  }
  long long global = 0;
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_LONG_LONG, MPI_MIN, comm));
  bad->index = global == std::numeric_limits<long long>::max() ? -1 : (PetscInt)global;
  if (bad->index >= 0) {
    // The owner of the first bad entry broadcasts its value and position.
    double mine[2] = {local == global ? val : 0.0, local == global ? coord : 0.0};
    double both[2];
    int has = local == global ? 1 : 0, nhas = 0;
    PetscCallMPI(MPI_Allreduce(&has, &nhas, 1, MPI_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(mine, both, 2, MPI_DOUBLE, MPI_SUM, comm));
    bad->value = both[0] / (nhas ? nhas : 1);
    bad->coord = both[1] / (nhas ? nhas : 1);
  }
  PetscFunctionReturn(0);
}

std::string place(const FieldLocation& w, const Bad& bad) {
  char buf[128];
  if (w.coords)
    std::snprintf(buf, sizeof buf, "step %d, time %g, cell %d (x = %g)", (int)w.step, w.time, (int)bad.index,
                  bad.coord);
  else
    std::snprintf(buf, sizeof buf, "step %d, time %g, cell %d", (int)w.step, w.time, (int)bad.index);
  return buf;
}

} // namespace

PetscErrorCode findNonFinite(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride,
                             PetscInt component, const FieldLocation& where, std::string* message) {
  PetscFunctionBeginUser;
  Bad bad{};
  PetscCall(firstBad(comm, data, n, stride, component, 0.0, false, where, &bad));
  message->clear();
  if (bad.index < 0) PetscFunctionReturn(0);
  char buf[256];
  std::snprintf(buf, sizeof buf, "non-finite %s = %g at %s", where.field, bad.value,
                place(where, bad).c_str());
  *message = buf;
  PetscFunctionReturn(0);
}

PetscErrorCode findNotAbove(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride,
                            PetscInt component, double floor, const FieldLocation& where,
                            std::string* message) {
  PetscFunctionBeginUser;
  Bad bad{};
  PetscCall(firstBad(comm, data, n, stride, component, floor, true, where, &bad));
  message->clear();
  if (bad.index < 0) PetscFunctionReturn(0);
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s %s = %g (must be > %g) at %s",
                std::isfinite(bad.value) ? "invalid" : "non-finite", where.field, bad.value, floor,
                place(where, bad).c_str());
  *message = buf;
  PetscFunctionReturn(0);
}

PetscErrorCode checkFinite(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride, PetscInt component,
                           const FieldLocation& where) {
  std::string message;
  PetscFunctionBeginUser;
  PetscCall(findNonFinite(comm, data, n, stride, component, where, &message));
  PetscCheck(message.empty(), comm, PETSC_ERR_FP, "%s: stopping the run", message.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode checkAbove(MPI_Comm comm, const double* data, PetscInt n, PetscInt stride, PetscInt component,
                          double floor, const FieldLocation& where) {
  std::string message;
  PetscFunctionBeginUser;
  PetscCall(findNotAbove(comm, data, n, stride, component, floor, where, &message));
  PetscCheck(message.empty(), comm, PETSC_ERR_FP, "%s: stopping the run", message.c_str());
  PetscFunctionReturn(0);
}

} // namespace suite
