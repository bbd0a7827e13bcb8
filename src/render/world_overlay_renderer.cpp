#include "render/world_overlay_renderer.hpp"

#include <cmath>
#include <cstddef>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "render/gl_object.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"

namespace globe::render {
// Named (not anonymous): Impl, which has external linkage, holds a vector of them.
namespace world_overlay_detail {

struct WorldVertex {
  glm::vec3 start;
  glm::vec3 end;
  float t;
  float side;
  glm::vec4 rgba;
  float widthPixels;
};

}  // namespace world_overlay_detail

namespace {

using world_overlay_detail::WorldVertex;

void appendSegment(std::vector<WorldVertex>& out, const glm::vec3& a, const glm::vec3& b,
                   const glm::vec4& rgba, float width) {
  const WorldVertex v00{a, b, 0, -1, rgba, width}, v01{a, b, 0, 1, rgba, width};
  const WorldVertex v10{a, b, 1, -1, rgba, width}, v11{a, b, 1, 1, rgba, width};
  out.insert(out.end(), {v00, v10, v11, v00, v11, v01});
}

}  // namespace

using world_overlay_detail::WorldVertex;

struct WorldOverlayRenderer::Impl {
  ShaderProgram program;
  GLint view = -1, projection = -1, viewport = -1, logDepthScale = -1;
  GlObject vertexArray;
  GlObject vertexBuffer;
  std::vector<WorldVertex> vertices;  // reused each frame
};

WorldOverlayRenderer::WorldOverlayRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
WorldOverlayRenderer::~WorldOverlayRenderer() = default;

Result<std::unique_ptr<WorldOverlayRenderer>> WorldOverlayRenderer::create(
    const std::filesystem::path& shaderDirectory) {
  const std::filesystem::path dir =
      shaderDirectory.empty() ? defaultShaderDirectory() : shaderDirectory;
  auto program = loadNamedShaderProgram(dir, "world_overlay.vert", "world_overlay.frag");
  if (!program) return makeError(program.error());
  auto impl = std::make_unique<Impl>();
  impl->program = std::move(*program);
  impl->view = impl->program.uniformLocation("u_view");
  impl->projection = impl->program.uniformLocation("u_projection");
  impl->viewport = impl->program.uniformLocation("u_viewportPixels");
  impl->logDepthScale = impl->program.uniformLocation("u_logDepthScale");
  if (impl->view < 0 || impl->projection < 0 || impl->viewport < 0 || impl->logDepthScale < 0) {
    return makeError((dir / "world_overlay.vert").string() +
                     ": the program lacks u_view, u_projection, u_viewportPixels or "
                     "u_logDepthScale");
  }
  impl->vertexArray = makeGlVertexArray();
  impl->vertexBuffer = makeGlBuffer();
  glBindVertexArray(impl->vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, impl->vertexBuffer.get());
  const auto attribute = [](GLuint index, GLint size, size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(WorldVertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(WorldVertex, start));
  attribute(1, 3, offsetof(WorldVertex, end));
  attribute(2, 1, offsetof(WorldVertex, t));
  attribute(3, 1, offsetof(WorldVertex, side));
  attribute(4, 4, offsetof(WorldVertex, rgba));
  attribute(5, 1, offsetof(WorldVertex, widthPixels));
  glBindVertexArray(0);
  return std::unique_ptr<WorldOverlayRenderer>(new WorldOverlayRenderer(std::move(impl)));
}

void WorldOverlayRenderer::draw(const terrain::RenderView& view,
                                std::span<const WorldTriangles> triangles,
                                std::span<const WorldLine> lines) {
  if ((triangles.empty() && lines.empty()) || view.widthPixels <= 0 || view.heightPixels <= 0) {
    return;
  }
  // Camera-relative in double, then float: centimetres stay centimetres anywhere on the globe.
  const glm::dvec3 eye = view.cameraEcefMeters;
  std::vector<WorldVertex>& vertices = impl_->vertices;
  vertices.clear();
  for (const WorldTriangles& set : triangles) {
    for (const glm::dvec3& p : set.ecefMeters) {
      const glm::vec3 local(p - eye);
      vertices.push_back({local, local, 0, 0, set.rgba, 0});
    }
    vertices.resize(vertices.size() - set.ecefMeters.size() % 3);
  }
  for (const WorldLine& line : lines) {
    for (size_t i = 0; i + 1 < line.ecefMeters.size(); ++i) {
      appendSegment(vertices, glm::vec3(line.ecefMeters[i] - eye),
                    glm::vec3(line.ecefMeters[i + 1] - eye), line.rgba, line.widthPixels);
    }
  }
  if (vertices.empty()) return;

  glm::dmat4 rotation = view.viewMatrix;
  rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);  // positions are relative to the eye already
  const glm::mat4 viewFloat(rotation);
  const glm::mat4 projection(view.projection);
  glViewport(0, 0, view.widthPixels, view.heightPixels);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glUseProgram(impl_->program.id());
  glUniformMatrix4fv(impl_->view, 1, GL_FALSE, glm::value_ptr(viewFloat));
  glUniformMatrix4fv(impl_->projection, 1, GL_FALSE, glm::value_ptr(projection));
  glUniform2f(impl_->viewport, static_cast<float>(view.widthPixels),
              static_cast<float>(view.heightPixels));
  glUniform1f(impl_->logDepthScale, static_cast<float>(1.0 / std::log2(1.0 + view.farMeters)));
  glBindVertexArray(impl_->vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, impl_->vertexBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(WorldVertex)),
               vertices.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
}

}  // namespace globe::render
