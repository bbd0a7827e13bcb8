// Draws overlays that are not on the ground (KML lines and polygons at an altitude, extruded
// walls, a point's stalk) in the 3D scene: depth-tested against the terrain drawn before, lines
// a constant width in pixels, everything translucent as its colour says.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/result.hpp"
#include "terrain/render_view.hpp"

namespace globe::render {

struct WorldLine {
  std::vector<glm::dvec3> ecefMeters;  // the vertices in order
  glm::vec4 rgba{1.0f};                // straight alpha
  float widthPixels = 1.0f;
};

struct WorldTriangles {
  std::vector<glm::dvec3> ecefMeters;  // three per triangle
  glm::vec4 rgba{1.0f};
};

// Needs a current GL 3.3 core context for its whole life, like TerrainRenderer.
class WorldOverlayRenderer {
 public:
  // Loads <shaderDirectory>/world_overlay.vert and .frag (empty: the embedded ones).
  static Result<std::unique_ptr<WorldOverlayRenderer>> create(
      const std::filesystem::path& shaderDirectory);
  ~WorldOverlayRenderer();
  WorldOverlayRenderer(const WorldOverlayRenderer&) = delete;
  WorldOverlayRenderer& operator=(const WorldOverlayRenderer&) = delete;

  // Triangles first, then lines, blended over the frame with the depth test on and depth writes
  // off; the view must be the one the terrain was drawn with. Leaves depth test and culling
  // enabled and blending disabled, as TerrainRenderer does.
  void draw(const terrain::RenderView& view, std::span<const WorldTriangles> triangles,
            std::span<const WorldLine> lines);

 private:
  struct Impl;
  explicit WorldOverlayRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
