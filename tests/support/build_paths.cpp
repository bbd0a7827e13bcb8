// The one file compiled with the build's absolute paths (build_paths.hpp says why).
#include "tests/support/build_paths.hpp"

namespace globe::build_paths {

const char* sourceDir() { return GLOBE_BUILD_SOURCE_DIR; }
const char* binaryDir() { return GLOBE_BUILD_BINARY_DIR; }
const char* globeExe() { return GLOBE_BUILD_GLOBE_EXE; }
const char* tilerExe() { return GLOBE_BUILD_TILER_EXE; }

}  // namespace globe::build_paths
