// Version of the suite for provenance: "<project version>-<git describe>" at configure time.
// Defined in a generated source (cmake/version.cpp.in), so a new commit recompiles one file, not the library.
#pragma once

namespace suite {
const char* versionString();
} // namespace suite
