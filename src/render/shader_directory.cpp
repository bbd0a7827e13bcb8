// The shader directory: environment override, else the compile-time default.
#include "render/shader_directory.hpp"

#include <cstdlib>

#ifndef GLOBE_SHADER_DIR
#error "GLOBE_SHADER_DIR must be defined by the build (src/render/CMakeLists.txt)"
#endif

namespace globe::render {

std::filesystem::path defaultShaderDirectory() {
  if (const char* fromEnvironment = std::getenv("GLOBE_SHADER_DIR");
      fromEnvironment != nullptr && fromEnvironment[0] != '\0') {
    return fromEnvironment;
  }
  return GLOBE_SHADER_DIR;
}

}  // namespace globe::render
