// Draws 3D models placed on the globe (3D Tiles' contents): opaque triangles uploaded once under
// a number of the caller's (a streamed content's), drawn each frame by those numbers, each set
// around an origin of its own (float offsets from it, the origin's distance from the
// camera taken in double each frame: centimetres stay centimetres anywhere on the globe), lit
// by the frame's light with their faces' normals, depth-tested and written against the terrain
// drawn before (the terrain's logarithmic depth). Textures are mipmapped; a model's white
// (glTF's default colour) untextured is drawn a light stone grey.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/result.hpp"
#include "terrain/render_view.hpp"

namespace globe::render {

// Triangles that wear one surface: a colour, times a texture where there is one. Everything is
// borrowed for add() (copied to the GPU there, never kept).
struct ModelPart {
  std::span<const glm::vec3> offsetsMeters;  // from the mesh's origin, three per triangle
  std::span<const glm::vec3> normals;        // per corner, unit; zero (or none): the triangle's own
  std::span<const glm::vec2> uvs;            // per corner, with a texture
  glm::vec4 rgba{1.0f};
  float alphaCutoff = 0;  // fragments whose alpha falls below are not drawn; 0: opaque
  // RGBA8 rows top-down ((0, 0) its top-left); null: untextured.
  const uint8_t* texturePixels = nullptr;
  int textureWidth = 0, textureHeight = 0;
};

struct ModelMesh {
  glm::dvec3 originEcefMeters{0.0};
  std::vector<ModelPart> parts;
};

// Needs a current GL 3.3 core context for its whole life, like TerrainRenderer.
class ModelRenderer {
 public:
  // Loads <shaderDirectory>/model.vert and .frag (empty: the embedded ones).
  static Result<std::unique_ptr<ModelRenderer>> create(
      const std::filesystem::path& shaderDirectory);
  ~ModelRenderer();
  ModelRenderer(const ModelRenderer&) = delete;
  ModelRenderer& operator=(const ModelRenderer&) = delete;

  // Uploads a mesh under `id` (its triangles' flat normals made here), replacing any before.
  void add(uint64_t id, const ModelMesh& mesh);
  bool has(uint64_t id) const;
  void remove(uint64_t id);
  // Triangles uploaded, and drawn by the last draw().
  size_t triangleCount() const;
  size_t trianglesDrawn() const;

  // The meshes of these ids (those not uploaded are skipped), with the view the terrain was
  // drawn with. Leaves depth test and culling as TerrainRenderer does (enabled).
  void draw(const terrain::RenderView& view, std::span<const uint64_t> ids);

 private:
  struct Impl;
  explicit ModelRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
