// The loader tests' pyramid: the bundled real data tiled once per test process by the tiler's
// fixture, and removed when the process exits (CTest runs every test in its own process).
#pragma once

#include <filesystem>
#include <system_error>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

inline const std::filesystem::path& loaderTestPyramid() {
  const std::filesystem::path& dir = globe::testing::bundledPyramid();
  // Constructed after the fixture's path, so destroyed (at exit) before it.
  static const struct Remover {
    std::filesystem::path scratch;
    ~Remover() {
      std::error_code ignored;
      std::filesystem::remove_all(scratch, ignored);
    }
  } remover{dir.parent_path()};
  return dir;
}

}  // namespace globe::testing
