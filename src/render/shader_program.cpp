// Shader file reading, compilation and linking with info-log error reporting.
#include "render/shader_program.hpp"

#include <string>

#include "transport/read_file.hpp"

namespace globe::render {
namespace {

constexpr std::uintmax_t kMaxShaderFileBytes = 1 << 20;

Result<std::string> readTextFile(const std::filesystem::path& path) {
  auto text = transport::readFileBounded(path, kMaxShaderFileBytes);
  if (!text) return makeError(text.error() + " (a shader file)");
  if (text->empty()) return makeError(path.string() + ": shader file is empty");
  return text;
}

// `defines` go on the line after the "#version" line (no code may precede it), or first without
// one.
std::string withDefines(std::string source, std::string_view defines) {
  if (defines.empty()) return source;
  std::string text(defines);
  if (text.back() != '\n') text.push_back('\n');
  size_t at = 0;
  if (const size_t version = source.find("#version"); version != std::string::npos) {
    const size_t end = source.find('\n', version);
    if (end == std::string::npos) source.push_back('\n');
    at = end == std::string::npos ? source.size() : end + 1;
  }
  source.insert(at, text);
  return source;
}

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) glGetProgramInfoLog(program, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

Result<GlObject> compileShader(GLenum type, std::string_view source, std::string_view name) {
  GlObject shader = makeGlShader(type);
  if (!shader) return makeError(std::string(name) + ": glCreateShader failed");
  const char* text = source.data();
  const auto length = static_cast<GLint>(source.size());
  glShaderSource(shader.get(), 1, &text, &length);
  glCompileShader(shader.get());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    return makeError(std::string(name) + ": GLSL compile error:\n" + shaderLog(shader.get()));
  }
  return shader;
}

}  // namespace

Result<ShaderProgram> buildShaderProgram(std::string_view vertexSource, std::string_view vertexName,
                                         std::string_view fragmentSource,
                                         std::string_view fragmentName, std::string_view defines) {
  auto vertex =
      compileShader(GL_VERTEX_SHADER, withDefines(std::string(vertexSource), defines), vertexName);
  if (!vertex) return makeError(vertex.error());
  auto fragment = compileShader(GL_FRAGMENT_SHADER,
                                withDefines(std::string(fragmentSource), defines), fragmentName);
  if (!fragment) return makeError(fragment.error());
  GlObject program = makeGlProgram();
  glAttachShader(program.get(), vertex->get());
  glAttachShader(program.get(), fragment->get());
  glLinkProgram(program.get());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  glDetachShader(program.get(), vertex->get());
  glDetachShader(program.get(), fragment->get());
  if (ok != GL_TRUE) {
    return makeError(std::string(vertexName) + " + " + std::string(fragmentName) +
                     ": GLSL link error:\n" + programLog(program.get()));
  }
  return ShaderProgram(std::move(program));
}

Result<ShaderProgram> loadShaderProgram(const std::filesystem::path& vertexPath,
                                        const std::filesystem::path& fragmentPath,
                                        std::string_view defines) {
  auto vertexSource = readTextFile(vertexPath);
  if (!vertexSource) return makeError(vertexSource.error());
  auto fragmentSource = readTextFile(fragmentPath);
  if (!fragmentSource) return makeError(fragmentSource.error());
  return buildShaderProgram(*vertexSource, vertexPath.string(), *fragmentSource,
                            fragmentPath.string(), defines);
}

}  // namespace globe::render
