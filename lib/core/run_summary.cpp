// The status and the end-of-run summary line of every program (see run_summary.hpp).
#include "core/run_summary.hpp"

#include "core/log.hpp"

#include <cstdio>

namespace suite {

std::string runStatus(const LoopSummary& s) {
  if (s.failed) return "failed at step " + std::to_string((long long)s.steps + 1);
  if (s.stopped) return s.stop_reason == "max_walltime" ? "stopped by walltime" : "stopped by signal";
  return "completed";
}

std::string stepsText(const LoopSummary& s) {
  char buf[256];
  const long long taken = (long long)s.stepsTaken();
  if (s.restarted && taken == 0)
    std::snprintf(buf, sizeof buf, "no step left after the restart at step %lld, t = %.6g",
                  (long long)s.first_step, s.t);
  else if (s.restarted)
    std::snprintf(buf, sizeof buf, "%lld steps from step %lld to %lld, t = %.6g, in %.3f s", taken,
                  (long long)s.first_step, (long long)s.steps, s.t, s.wall);
  else
    std::snprintf(buf, sizeof buf, "%lld steps to t = %.6g in %.3f s", taken, s.t, s.wall);
  return buf;
}

PetscErrorCode logRunSummary(const RunContext& ctx, const std::string& status, const std::string& what,
                             const std::vector<std::string>& written) {
  std::string files;
  for (const std::string& f : written) files += (files.empty() ? "" : ", ") + f;
  const std::string tail = files.empty() ? "no output file (-output FILE writes one)" : "wrote " + files;
  PetscFunctionBeginUser;
  PetscCall(logInfo(ctx.comm(), ctx.quiet(), "%s: %s: %s; %s", ctx.program().c_str(), status.c_str(),
                    what.c_str(), tail.c_str()));
  PetscFunctionReturn(0);
}

} // namespace suite
