// PetscLogStage registration: Setup / Solve / Output in -log_view.
#include "core/log_stages.hpp"

namespace suite {

PetscErrorCode LogStages::get(LogStages* stages) {
  static LogStages registered;
  static bool done = false;
  PetscFunctionBeginUser;
  if (!done) {
    PetscCall(PetscLogStageRegister("Setup", &registered.setup));
    PetscCall(PetscLogStageRegister("Solve", &registered.solve));
    PetscCall(PetscLogStageRegister("Output", &registered.output));
    done = true;
  }
  *stages = registered;
  PetscFunctionReturn(0);
}

StageScope::StageScope(PetscLogStage stage) {
  if (stage >= 0 && !PetscLogStagePush(stage)) pushed_ = true;
}

StageScope::~StageScope() {
  if (pushed_) PetscLogStagePop();
}

} // namespace suite
