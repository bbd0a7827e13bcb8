// Where the source checkout, its build directory and the built programs are, for the tests and
// the benchmark tools that run them. The absolute paths are compiled into build_paths.cpp alone,
// not onto every file's command line: a second checkout in another folder then compiles the
// same commands, and the compiler cache gives it the first checkout's objects
// (docs/performance/ci-time.md).
#pragma once

namespace globe::build_paths {

const char* sourceDir();  // the checkout (CMake's PROJECT_SOURCE_DIR)
const char* binaryDir();  // the build directory (CMake's PROJECT_BINARY_DIR)
const char* globeExe();   // the built `globe`
const char* tilerExe();   // the built `globe-tiler`

}  // namespace globe::build_paths

// The names the tests have always used, as expressions (not string literals: no concatenation).
#define GLOBE_SOURCE_DIR (::globe::build_paths::sourceDir())
#define GLOBE_EXE (::globe::build_paths::globeExe())
#define GLOBE_TILER_EXE (::globe::build_paths::tilerExe())
