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
  glm::vec2 uv;
};

// Untextured white (glTF's default) is drawn as a light stone grey: models without materials.
constexpr glm::vec4 kDefaultColor{0.82f, 0.80f, 0.76f, 1.0f};

struct UploadedPart {
  glm::vec4 rgba;
  float alphaCutoff;
  GlObject vertexArray, vertexBuffer, texture;  // texture 0: untextured
  GLsizei vertexCount = 0;
};

// One uploaded mesh.
struct Uploaded {
  glm::dvec3 origin;
  std::vector<UploadedPart> parts;
  size_t triangles = 0;
};

std::vector<Vertex> verticesOf(const ModelPart& part) {
  std::vector<Vertex> vertices;
  vertices.reserve(part.offsetsMeters.size());
  for (size_t t = 0; t + 2 < part.offsetsMeters.size(); t += 3) {
    const glm::vec3 &a = part.offsetsMeters[t], &b = part.offsetsMeters[t + 1],
                    &c = part.offsetsMeters[t + 2];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    const glm::vec3 flat = length > 0 ? n / length : glm::vec3(0, 0, 1);
    for (size_t k = t; k < t + 3; ++k) {
      const glm::vec3 given = k < part.normals.size() ? part.normals[k] : glm::vec3(0.0f);
      const glm::vec2 uv = k < part.uvs.size() ? part.uvs[k] : glm::vec2(0.0f);
      vertices.push_back({part.offsetsMeters[k], given == glm::vec3(0.0f) ? flat : given, uv});
    }
  }
  return vertices;
}

GlObject uploadTexture(const ModelPart& part) {
  if (part.texturePixels == nullptr || part.textureWidth <= 0 || part.textureHeight <= 0)
    return GlObject();
  // Premultiplied, so that mipmaps average colours by their alpha (model.frag divides it out).
  const size_t bytes = size_t(part.textureWidth) * size_t(part.textureHeight) * 4;
  std::vector<uint8_t> premultiplied(part.texturePixels, part.texturePixels + bytes);
  for (size_t i = 0; i < bytes; i += 4) {
    for (size_t c = 0; c < 3; ++c)
      premultiplied[i + c] =
          static_cast<uint8_t>((premultiplied[i + c] * premultiplied[i + 3] + 127) / 255);
  }
  GlObject texture = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, part.textureWidth, part.textureHeight, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, premultiplied.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

UploadedPart uploadPart(const ModelPart& part) {
  const std::vector<Vertex> vertices = verticesOf(part);
  const bool white = part.rgba == glm::vec4(1.0f);
  UploadedPart up{white && part.texturePixels == nullptr ? kDefaultColor : part.rgba,
                  part.alphaCutoff,
                  makeGlVertexArray(),
                  makeGlBuffer(),
                  uploadTexture(part),
                  static_cast<GLsizei>(vertices.size())};
  glBindVertexArray(up.vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, up.vertexBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  const std::pair<GLint, size_t> attributes[] = {
      {3, offsetof(Vertex, offset)}, {3, offsetof(Vertex, normal)}, {2, offsetof(Vertex, uv)}};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, attributes[a].first, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(attributes[a].second));
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return up;
}

}  // namespace model_detail

using model_detail::Uploaded;
using model_detail::UploadedPart;
using model_detail::uploadPart;
using model_detail::Vertex;

struct ModelRenderer::Impl {
  ShaderProgram program;
  GLint originFromCamera = -1, view = -1, projection = -1, rgba = -1, sun = -1, logDepth = -1,
        textured = -1, texture = -1, alphaCutoff = -1;
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
  impl->rgba = uniform("u_rgba");
  impl->textured = uniform("u_textured");
  impl->texture = uniform("u_texture");
  impl->alphaCutoff = uniform("u_alphaCutoff");
  impl->sun = uniform("u_sunDirection");
  impl->logDepth = uniform("u_logDepthScale");
  for (const GLint u : {impl->originFromCamera, impl->view, impl->projection, impl->rgba, impl->sun,
                        impl->logDepth, impl->textured, impl->texture, impl->alphaCutoff}) {
    if (u < 0) return makeError((dir / "model.vert").string() + ": a uniform is missing");
  }
  return std::unique_ptr<ModelRenderer>(new ModelRenderer(std::move(impl)));
}

void ModelRenderer::add(uint64_t id, const ModelMesh& mesh) {
  remove(id);
  Uploaded set{mesh.originEcefMeters, {}, 0};
  for (const ModelPart& part : mesh.parts) {
    if (part.offsetsMeters.size() < 3) continue;
    set.parts.push_back(uploadPart(part));
    set.triangles += static_cast<size_t>(set.parts.back().vertexCount) / 3;
  }
  impl_->triangles += set.triangles;
  impl_->sets.emplace(id, std::move(set));
}

bool ModelRenderer::has(uint64_t id) const { return impl_->sets.contains(id); }

void ModelRenderer::remove(uint64_t id) {
  const auto it = impl_->sets.find(id);
  if (it == impl_->sets.end()) return;
  impl_->triangles -= it->second.triangles;
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
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(impl_->texture, 0);
  glUniformMatrix4fv(impl_->view, 1, GL_FALSE, glm::value_ptr(viewFloat));
  glUniformMatrix4fv(impl_->projection, 1, GL_FALSE, glm::value_ptr(projection));
  const glm::vec3 sun(glm::normalize(view.sunDirectionEcef));
  glUniform3f(impl_->sun, sun.x, sun.y, sun.z);
  glUniform1f(impl_->logDepth, static_cast<float>(1.0 / std::log2(1.0 + view.farMeters)));
  for (const uint64_t id : ids) {
    const auto it = impl_->sets.find(id);
    if (it == impl_->sets.end()) continue;
    const Uploaded& set = it->second;
    impl_->trianglesDrawn += set.triangles;
    const glm::vec3 origin(set.origin - view.cameraEcefMeters);
    glUniform3f(impl_->originFromCamera, origin.x, origin.y, origin.z);
    for (const UploadedPart& part : set.parts) {
      glUniform4f(impl_->rgba, part.rgba.r, part.rgba.g, part.rgba.b, part.rgba.a);
      glUniform1i(impl_->textured, part.texture.get() != 0 ? 1 : 0);
      glUniform1f(impl_->alphaCutoff, part.alphaCutoff);
      glBindTexture(GL_TEXTURE_2D, part.texture.get());
      glBindVertexArray(part.vertexArray.get());
      glDrawArrays(GL_TRIANGLES, 0, part.vertexCount);
    }
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  glEnable(GL_CULL_FACE);
}

}  // namespace globe::render
