// Where GLSL files are read from at run time.
#pragma once

#include <filesystem>

namespace globe::render {

// $GLOBE_SHADER_DIR when set and non-empty, else the build's default: the GLOBE_SHADER_DIR CMake
// cache variable, which defaults to the source tree's shaders/ folder.
std::filesystem::path defaultShaderDirectory();

}  // namespace globe::render
