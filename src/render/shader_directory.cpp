// The shader directory: an environment override, else the shaders compiled into the program.
#include "render/shader_directory.hpp"

#include <cstdlib>
#include <string>

#include "render/embedded_shaders.hpp"

namespace globe::render {

std::filesystem::path defaultShaderDirectory() {
  if (const char* fromEnvironment = std::getenv("GLOBE_SHADER_DIR");
      fromEnvironment != nullptr && fromEnvironment[0] != '\0') {
    return fromEnvironment;
  }
  return {};
}

Result<ShaderProgram> loadNamedShaderProgram(const std::filesystem::path& directory,
                                             std::string_view vertexName,
                                             std::string_view fragmentName,
                                             std::string_view defines) {
  if (!directory.empty()) {
    return loadShaderProgram(directory / vertexName, directory / fragmentName, defines);
  }
  const auto vertex = embeddedShader(vertexName);
  const auto fragment = embeddedShader(fragmentName);
  for (const auto& [name, text] : {std::pair{vertexName, vertex}, {fragmentName, fragment}}) {
    if (!text) return makeError("embedded:" + std::string(name) + ": no such shader in the build");
  }
  return buildShaderProgram(*vertex, "embedded:" + std::string(vertexName), *fragment,
                            "embedded:" + std::string(fragmentName), defines);
}

}  // namespace globe::render
