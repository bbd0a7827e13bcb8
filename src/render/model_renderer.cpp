#include "render/model_renderer.hpp"

#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "render/gl_object.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"

namespace globe::render {
namespace model_detail {

struct Vertex {
  glm::vec3 offset;
  glm::vec3 normal;
};

// One uploaded set.
struct Uploaded {
  glm::dvec3 origin;
  glm::vec3 rgb;
  GlObject vertexArray, vertexBuffer;
  GLsizei vertexCount = 0;
};

}  // namespace model_detail

using model_detail::Uploaded;
using model_detail::Vertex;

struct ModelRenderer::Impl {
  ShaderProgram program;
  GLint originFromCamera = -1, view = -1, projection = -1, rgb = -1, sun = -1, logDepth = -1;
  std::unordered_map<uint64_t, Uploaded> sets;
  size_t triangles = 0, trianglesDrawn = 0;
};

ModelRenderer::ModelRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ModelRenderer::~ModelRenderer() = default;

Result<std::unique_ptr<ModelRenderer>> ModelRenderer::create(
    const std::filesystem::path& shaderDirectory) {
  const std::filesystem::path dir =
      shaderDirectory.empty() ? defaultShaderDirectory() : shaderDirectory;
  auto program = loadNamedShaderProgram(dir, "model.vert", "model.frag");
  if (!program) return makeError(program.error());
  auto impl = std::make_unique<Impl>();
  impl->program = std::move(*program);
  const auto uniform = [&](const char* name) { return impl->program.uniformLocation(name); };
  impl->originFromCamera = uniform("u_originFromCamera");
  impl->view = uniform("u_view");
  impl->projection = uniform("u_projection");
  impl->rgb = uniform("u_rgb");
  impl->sun = uniform("u_sunDirection");
  impl->logDepth = uniform("u_logDepthScale");
  for (const GLint u : {impl->originFromCamera, impl->view, impl->projection, impl->rgb, impl->sun,
                        impl->logDepth}) {
    if (u < 0) return makeError((dir / "model.vert").string() + ": a uniform is missing");
  }
  return std::unique_ptr<ModelRenderer>(new ModelRenderer(std::move(impl)));
}

void ModelRenderer::add(uint64_t id, const ModelMesh& mesh) {
  remove(id);
  std::vector<Vertex> vertices;
  vertices.reserve(mesh.offsetsMeters.size());
  for (size_t t = 0; t + 2 < mesh.offsetsMeters.size(); t += 3) {
    const glm::vec3 &a = mesh.offsetsMeters[t], &b = mesh.offsetsMeters[t + 1],
                    &c = mesh.offsetsMeters[t + 2];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    const glm::vec3 normal = length > 0 ? n / length : glm::vec3(0, 0, 1);
    vertices.insert(vertices.end(), {{a, normal}, {b, normal}, {c, normal}});
  }
  if (vertices.empty()) return;
  Uploaded set{mesh.originEcefMeters, mesh.rgb, makeGlVertexArray(), makeGlBuffer(),
               static_cast<GLsizei>(vertices.size())};
  glBindVertexArray(set.vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, set.vertexBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, offset)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, normal)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  impl_->triangles += vertices.size() / 3;
  impl_->sets.emplace(id, std::move(set));
}

bool ModelRenderer::has(uint64_t id) const { return impl_->sets.contains(id); }

void ModelRenderer::remove(uint64_t id) {
  const auto it = impl_->sets.find(id);
  if (it == impl_->sets.end()) return;
  impl_->triangles -= static_cast<size_t>(it->second.vertexCount) / 3;
  impl_->sets.erase(it);
}

size_t ModelRenderer::triangleCount() const { return impl_->triangles; }
size_t ModelRenderer::trianglesDrawn() const { return impl_->trianglesDrawn; }

void ModelRenderer::draw(const terrain::RenderView& view, std::span<const uint64_t> ids) {
  impl_->trianglesDrawn = 0;
  if (ids.empty() || view.widthPixels <= 0 || view.heightPixels <= 0) return;
  glm::dmat4 rotation = view.viewMatrix;
  rotation[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);  // positions are relative to the eye already
  const glm::mat4 viewFloat(rotation);
  const glm::mat4 projection(view.projection);
  glViewport(0, 0, view.widthPixels, view.heightPixels);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // models' windings are not to be trusted
  glUseProgram(impl_->program.id());
  glUniformMatrix4fv(impl_->view, 1, GL_FALSE, glm::value_ptr(viewFloat));
  glUniformMatrix4fv(impl_->projection, 1, GL_FALSE, glm::value_ptr(projection));
  const glm::vec3 sun(glm::normalize(view.sunDirectionEcef));
  glUniform3f(impl_->sun, sun.x, sun.y, sun.z);
  glUniform1f(impl_->logDepth, static_cast<float>(1.0 / std::log2(1.0 + view.farMeters)));
  for (const uint64_t id : ids) {
    const auto it = impl_->sets.find(id);
    if (it == impl_->sets.end()) continue;
    const Uploaded& set = it->second;
    impl_->trianglesDrawn += static_cast<size_t>(set.vertexCount) / 3;
    const glm::vec3 origin(set.origin - view.cameraEcefMeters);
    glUniform3f(impl_->originFromCamera, origin.x, origin.y, origin.z);
    glUniform3f(impl_->rgb, set.rgb.r, set.rgb.g, set.rgb.b);
    glBindVertexArray(set.vertexArray.get());
    glDrawArrays(GL_TRIANGLES, 0, set.vertexCount);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glEnable(GL_CULL_FACE);
}

}  // namespace globe::render
