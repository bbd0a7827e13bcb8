#include "shader_variants.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "render/embedded_shaders.hpp"

namespace globe::bench {

Result<std::filesystem::path> shadersWithoutFragDepth(const std::filesystem::path& scratch) {
  const auto to = scratch / "shaders-no-frag-depth";
  std::filesystem::create_directories(to);
  bool removed = false;
  for (const std::string_view name : render::embeddedShaderNames()) {
    std::istringstream in{std::string(*render::embeddedShader(name))};
    std::ofstream out(to / name);
    std::string line;
    while (std::getline(in, line)) {
      if (name == "terrain.frag" && line.find("gl_FragDepth") != std::string::npos) {
        // Keeps u_logDepthScale in use (the renderer requires it) without writing the depth.
        out << "  o_color.a = min(1.0, 1.0 + u_logDepthScale * v_logDepth);\n";
        removed = true;
        continue;
      }
      out << line << '\n';
    }
    if (!out) return makeError("cannot write " + (to / name).string());
  }
  if (!removed) return makeError("no gl_FragDepth line in the embedded terrain.frag");
  return to;
}

}  // namespace globe::bench
