// A copy of the bundled pyramid whose finer blocks fail their CRC: the packs open, the tiles a
// close view needs fail to load (what a damaged disk or a bad transfer gives).
#pragma once

#include <filesystem>

namespace globe::testing {

// Copies the bundled pyramid to dir/damaged and damages every block of levels 8 and finer past
// each pack's first third (the index stays readable). Returns the copy.
std::filesystem::path damagedPyramid(const std::filesystem::path& dir);

}  // namespace globe::testing
