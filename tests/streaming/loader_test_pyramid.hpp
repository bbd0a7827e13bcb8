// The loader tests' pyramid: the bundled real data, tiled once per CTest run and shared by the
// test processes (tests/support/shared_fixture.hpp). Read it only; copy it to change it.
#pragma once

#include <filesystem>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

inline const std::filesystem::path& loaderTestPyramid() { return globe::testing::bundledPyramid(); }

}  // namespace globe::testing
