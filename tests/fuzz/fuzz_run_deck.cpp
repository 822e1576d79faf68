// Fuzz target: run decks (-options_file, YAML) as the suite checks them (lib/core/options_file_check, before
// PETSc reads them: plain and YAML rules on the raw bytes, NULs included) and as PETSc parses them for every
// app. A malformed deck must give a message or an error code, never a crash or a hang.
#include "core/options_file_check.hpp"

#include <petscsys.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool ready = [] {
    PetscInitializeNoArguments();
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); // errors are expected: no messages
    return true;
  }();
  (void)ready;
  const std::string text(reinterpret_cast<const char*>(data), size); // NUL-terminated copy
  std::vector<suite::IncludedFile> included;
  (void)suite::checkPlainOptionsText(text, &included);
  (void)suite::checkYamlOptionsText(text);
  for (const std::string& line : {text.substr(0, text.find('\n')), text})
    (void)suite::classifyOptionsLine(line);
  PetscOptions opts = nullptr;
  if (PetscOptionsCreate(&opts)) return 0;
  PetscOptionsInsertStringYAML(opts, text.c_str());
  PetscOptionsDestroy(&opts);
  return 0;
}
