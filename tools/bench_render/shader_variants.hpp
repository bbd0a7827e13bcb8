// Shader variants the frame-time benchmark compares against the shipped (embedded) shaders.
#pragma once

#include <filesystem>

#include "core/result.hpp"

namespace globe::bench {

// The embedded shaders written to `scratch`/shaders-no-frag-depth with the per-fragment depth
// write removed (an experiment: the image is wrong, the cost of gl_FragDepth is the difference
// in frame time); the directory.
Result<std::filesystem::path> shadersWithoutFragDepth(const std::filesystem::path& scratch);

}  // namespace globe::bench
