// PetscLogStage registration so -log_view splits the run into Setup / Solve / Output.
#pragma once

#include <petsclog.h>

namespace suite {

struct LogStages {
  PetscLogStage setup = -1, solve = -1, output = -1;
  // Registers the three standard stages once per process; later calls return the same ids.
  static PetscErrorCode get(LogStages* stages);
};

// RAII push/pop of a log stage. Use only in code paths that return normally (pops in the destructor).
class StageScope {
public:
  explicit StageScope(PetscLogStage stage);
  ~StageScope();
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;

private:
  bool pushed_ = false;
};

} // namespace suite
