// The terrain's aerial perspective under the physical sky (--time): the air's coefficients
// (atmosphere/aerial_perspective.hpp, evaluated per vertex in terrain.vert) and the sky's image
// for the colour it scatters in, set on a terrain program. Private to globe_render.
#pragma once

#include <glm/vec3.hpp>

#include "render/gl_loader.hpp"
#include "render/shader_program.hpp"
#include "terrain/render_view.hpp"

namespace globe::render {

class SkyPass;

struct AerialHaze {
  GLuint skyView = 0;  // 0: no aerial perspective (the fog instead)
  float horizonRow = 0.0f;
  float cameraHeightMeters = 0.0f;
  glm::vec3 upEye{0.0f}, sunAcrossEye{0.0f};  // eye space
};

struct AerialHazeUniforms {
  GLint aerial = -1, rayleigh = -1, mie = -1, scaleHeights = -1, cameraHeight = -1;
  GLint skyView = -1, up = -1, sunAcross = -1, row = -1;
  static AerialHazeUniforms locate(const ShaderProgram& program);
};

// The haze for this view with the sky's current image (none under the model's sky).
AerialHaze aerialHazeFor(const terrain::RenderView& view, const SkyPass& sky,
                         double cameraHeightMeters);
// Sets the uniforms and binds the sky's image to `unit` (a program without them is left alone).
void setAerialHaze(const AerialHaze& haze, const AerialHazeUniforms& u, GLuint unit);

}  // namespace globe::render
