// Fuzz target: run decks (-options_file, YAML) as PETSc parses them for every app. A malformed deck must
// give an error code, never a crash or a hang.
#include <petscsys.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool ready = [] {
    PetscInitializeNoArguments();
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); // errors are expected: no messages
    return true;
  }();
  (void)ready;
  const std::string text(reinterpret_cast<const char*>(data), size); // NUL-terminated copy
  PetscOptions opts = nullptr;
  if (PetscOptionsCreate(&opts)) return 0;
  PetscOptionsInsertStringYAML(opts, text.c_str());
  PetscOptionsDestroy(&opts);
  return 0;
}
