// Default AddressSanitizer options of the sanitizer build (see sanitizer_defaults.hpp).
#include "core/sanitizer_defaults.hpp"

#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __asan_default_options() {
  return "detect_leaks=0";
}
#endif

namespace suite {
int keepSanitizerDefaults() {
  return 0;
}
} // namespace suite
