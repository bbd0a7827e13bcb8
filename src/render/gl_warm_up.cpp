// The throw-away warm-up draw; its two tiny shaders are inline because nothing else uses them.
#include "render/gl_warm_up.hpp"

#include <string>

#include "render/gl_object.hpp"

namespace globe::render {
namespace {

constexpr const char* kVertexSource = R"(#version 330 core
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  gl_Position = vec4(corner * 0.1 - 0.05, 0.0, 1.0);
})";
constexpr const char* kFragmentSource = R"(#version 330 core
out vec4 color;
void main() { color = vec4(1.0); })";

bool compile(const GlObject& shader, const char* source) {
  glShaderSource(shader.get(), 1, &source, nullptr);
  glCompileShader(shader.get());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  return ok == GL_TRUE;
}

}  // namespace

Result<void> warmUpGl() {
  GlObject vertex = makeGlShader(GL_VERTEX_SHADER);
  GlObject fragment = makeGlShader(GL_FRAGMENT_SHADER);
  if (!compile(vertex, kVertexSource) || !compile(fragment, kFragmentSource)) {
    return makeError("GL warm-up: the trivial shaders did not compile");
  }
  GlObject program = makeGlProgram();
  glAttachShader(program.get(), vertex.get());
  glAttachShader(program.get(), fragment.get());
  glLinkProgram(program.get());
  GLint linked = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) return makeError("GL warm-up: the trivial program did not link");

  GlObject vertexArray = makeGlVertexArray();
  glUseProgram(program.get());
  glBindVertexArray(vertexArray.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glFinish();
  glBindVertexArray(0);
  glUseProgram(0);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    return makeError("GL warm-up: GL error " + std::to_string(error));
  }
  return {};
}

}  // namespace globe::render
