// glad2 loading behind a loader-agnostic function pointer type.
#include "render/gl_loader.hpp"

#include <string>

#include "render/gl.hpp"

namespace globe::render {

Result<void> loadGlFunctions(GlProcLoader loader) {
  if (loader == nullptr) return makeError("GL loader: no proc-address function");
  const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
  if (version == 0) return makeError("GL loader: gladLoadGL failed (no current context?)");
  const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
  if (major < 3 || (major == 3 && minor < 3)) {
    return makeError("GL loader: OpenGL 3.3 core needed, context has " + std::to_string(major) +
                     "." + std::to_string(minor));
  }
  return {};
}

GlInfo currentGlInfo() {
  GlInfo info;
  glGetIntegerv(GL_MAJOR_VERSION, &info.major);
  glGetIntegerv(GL_MINOR_VERSION, &info.minor);
  auto text = [](GLenum name) {
    const auto* value = reinterpret_cast<const char*>(glGetString(name));
    return std::string(value != nullptr ? value : "");
  };
  info.version = text(GL_VERSION);
  info.renderer = text(GL_RENDERER);
  info.vendor = text(GL_VENDOR);
  return info;
}

}  // namespace globe::render
