// Where GLSL sources come from at run time.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/result.hpp"
#include "render/shader_program.hpp"

namespace globe::render {

// $GLOBE_SHADER_DIR when set and non-empty (to try shader edits without rebuilding), else empty:
// the shaders compiled into the program (render/embedded_shaders.hpp).
std::filesystem::path defaultShaderDirectory();

// Builds <directory>/<vertexName> + <fragmentName>, or the embedded shaders of those names when
// `directory` is empty (error messages then name them "embedded:<name>").
Result<ShaderProgram> loadNamedShaderProgram(const std::filesystem::path& directory,
                                             std::string_view vertexName,
                                             std::string_view fragmentName,
                                             std::string_view defines = {});

}  // namespace globe::render
