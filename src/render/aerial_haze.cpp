// Aerial perspective's uniforms for the terrain programs (aerial_haze.hpp).
#include "render/aerial_haze.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "atmosphere/aerial_perspective.hpp"
#include "render/sky_pass.hpp"

namespace globe::render {

AerialHazeUniforms AerialHazeUniforms::locate(const ShaderProgram& p) {
  AerialHazeUniforms u;
  u.aerial = p.uniformLocation("u_aerial");
  u.rayleigh = p.uniformLocation("u_rayleighPerMeter");
  u.mie = p.uniformLocation("u_mieExtinctionPerMeter");
  u.scaleHeights = p.uniformLocation("u_scaleHeightsMeters");
  u.cameraHeight = p.uniformLocation("u_cameraHeightMeters");
  u.skyView = p.uniformLocation("u_hazeSkyView");
  u.up = p.uniformLocation("u_hazeUpEye");
  u.sunAcross = p.uniformLocation("u_hazeSunAcrossEye");
  u.row = p.uniformLocation("u_hazeRow");
  return u;
}

AerialHaze aerialHazeFor(const terrain::RenderView& view, const SkyPass& sky,
                         double cameraHeightMeters) {
  AerialHaze haze;
  haze.skyView = sky.skyViewTexture();
  if (haze.skyView == 0) return haze;
  haze.horizonRow = sky.horizonRow();
  haze.cameraHeightMeters = static_cast<float>(cameraHeightMeters);
  const glm::dmat3 toEye(view.viewMatrix);
  const glm::dvec3 up = glm::normalize(toEye * glm::normalize(view.cameraEcefMeters));
  const glm::dvec3 sun = toEye * glm::normalize(view.sunDirectionEcef);
  const glm::dvec3 across = sun - up * glm::dot(sun, up);
  haze.upEye = glm::vec3(up);
  if (glm::length(across) > 1e-9) haze.sunAcrossEye = glm::vec3(glm::normalize(across));
  return haze;
}

void setAerialHaze(const AerialHaze& haze, const AerialHazeUniforms& u, GLuint unit) {
  if (u.aerial < 0) return;
  glUniform1i(u.aerial, haze.skyView != 0 ? 1 : 0);
  if (haze.skyView == 0) return;
  const atmosphere::Atmosphere air;
  const glm::vec3 rayleigh(air.rayleighScatteringPerMeter);
  glUniform3fv(u.rayleigh, 1, glm::value_ptr(rayleigh));
  glUniform1f(u.mie, static_cast<float>(air.mieExtinctionPerMeter));
  glUniform2f(u.scaleHeights, static_cast<float>(air.rayleighScaleHeightMeters),
              static_cast<float>(air.mieScaleHeightMeters));
  glUniform1f(u.cameraHeight, haze.cameraHeightMeters);
  glUniform3fv(u.up, 1, glm::value_ptr(haze.upEye));
  glUniform3fv(u.sunAcross, 1, glm::value_ptr(haze.sunAcrossEye));
  glUniform1f(u.row, haze.horizonRow);
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, haze.skyView);
  glBindSampler(unit, 0);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(u.skyView, static_cast<GLint>(unit));
}

}  // namespace globe::render
