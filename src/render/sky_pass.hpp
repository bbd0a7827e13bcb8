// Draws the sky (render/sky_model.hpp) behind everything: one screen-covering triangle at the far
// depth (1), drawn after the terrain with the depth test LEQUAL and writes off, so only pixels
// nothing else covered are shaded (early depth test; on llvmpipe the sky cost a fifth of a
// low oblique frame when it was drawn first under everything).
#pragma once

#include <filesystem>
#include <memory>
#include <utility>

#include "core/result.hpp"
#include "render/gl_object.hpp"
#include "render/shader_program.hpp"
#include "render/sky_model.hpp"
#include "terrain/render_view.hpp"

namespace globe::render {

class SkyPass {
 public:
  // Loads <shaderDirectory>/sky.vert and sky.frag (empty: the embedded ones); needs a current
  // GL 3.3 core context.
  static Result<std::unique_ptr<SkyPass>> create(const std::filesystem::path& shaderDirectory);
  // The sky for this view where the depth buffer still holds the cleared 1.0; leaves depth
  // testing as it found it (enabled or not), the depth function LESS and depth writes on.
  void draw(const terrain::RenderView& view, const SkyParameters& sky,
            double globeRadiusMeters) const;

  // Under the real Sun (--time): the physically based sky seen from this height with the Sun at
  // this zenith cosine (atmosphere/sky_view.hpp) instead of the model's gradient, made again on
  // the CPU when the height has moved by 1 % (or 10 m) or the Sun by ~0.06°. Returns its colour
  // at the horizon, square to the Sun (the terrain's fog).
  glm::vec3 usePhysicalSky(double heightMeters, double sunZenithCosine);
  // Back to the model's gradient (no --time).
  void useModelSky() { physical_ = false; }
  // The physical sky's image (0 under the model's sky) and its horizon's row (0..1): the
  // terrain's aerial perspective takes the sky's horizon colour in each direction from it.
  GLuint skyViewTexture() const { return physical_ ? skyViewTexture_.get() : 0; }
  float horizonRow() const;

 private:
  SkyPass() = default;
  ShaderProgram program_;
  GlObject vertexArray_;  // empty: the triangle comes from gl_VertexID
  struct Uniforms {
    GLint inverseViewProjection = -1, up = -1, cameraRadius = -1, globeRadius = -1;
    GLint atmosphereHeight = -1, zenith = -1, horizon = -1, glow = -1, spaceBlend = -1;
    GLint horizonCosine = -1, daylight = -1, sunDirection = -1, daylightBand = -1;
    GLint physical = -1, skyView = -1, horizonElevation = -1;
  } u_;
  GlObject skyViewTexture_;
  bool physical_ = false;
  double horizonElevationRadians_ = 0.0;
  std::pair<long, long> skyViewKey_{-1, -1};  // height bucket, Sun bucket
  glm::vec3 horizonRgb_{0.0f};
};

}  // namespace globe::render
