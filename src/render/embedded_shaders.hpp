// The GLSL files of shaders/, compiled into the program at build time (cmake/EmbedShaders.cmake),
// so an installed or copied binary needs no shader files.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace globe::render {

// The text of shaders/<fileName> as built, or nullopt for no such shader.
std::optional<std::string_view> embeddedShader(std::string_view fileName);
std::vector<std::string_view> embeddedShaderNames();

}  // namespace globe::render
