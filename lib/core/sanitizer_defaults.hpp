// Default AddressSanitizer options of the sanitizer build (SUITE_SANITIZE=ON): leak detection off, because
// Open MPI and PETSc keep allocations alive until exit by design; ASAN_OPTIONS in the environment overrides.
// A program's main file includes this header and calls suite::keepSanitizerDefaults() once so that the
// linker keeps the object that defines __asan_default_options (RunContext does this for every app).
#pragma once

namespace suite {
int keepSanitizerDefaults();
} // namespace suite
