#include "render/sky_pass.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "render/shader_directory.hpp"

namespace globe::render {

Result<std::unique_ptr<SkyPass>> SkyPass::create(const std::filesystem::path& shaderDirectory) {
  auto program = loadNamedShaderProgram(shaderDirectory, "sky.vert", "sky.frag");
  if (!program) return Error{program.error()};
  std::unique_ptr<SkyPass> pass(new SkyPass());
  pass->program_ = std::move(*program);
  pass->vertexArray_ = makeGlVertexArray();
  const ShaderProgram& p = pass->program_;
  Uniforms& u = pass->u_;
  u.inverseViewProjection = p.uniformLocation("u_inverseViewProjection");
  u.up = p.uniformLocation("u_up");
  u.cameraRadius = p.uniformLocation("u_cameraRadius");
  u.globeRadius = p.uniformLocation("u_globeRadius");
  u.atmosphereHeight = p.uniformLocation("u_atmosphereHeight");
  u.zenith = p.uniformLocation("u_zenith");
  u.horizon = p.uniformLocation("u_horizon");
  u.glow = p.uniformLocation("u_glow");
  u.spaceBlend = p.uniformLocation("u_spaceBlend");
  u.horizonCosine = p.uniformLocation("u_horizonCosine");
  u.daylight = p.uniformLocation("u_daylight");
  u.sunDirection = p.uniformLocation("u_sunDirection");
  u.daylightBand = p.uniformLocation("u_daylightBand");
  if (u.inverseViewProjection < 0 || u.up < 0) {
    return makeError((shaderDirectory.empty() ? std::filesystem::path("embedded:sky.frag")
                                              : shaderDirectory / "sky.frag")
                         .string() +
                     ": the program lacks u_inverseViewProjection or u_up");
  }
  return pass;
}

void SkyPass::draw(const terrain::RenderView& view, const SkyParameters& sky,
                   double globeRadiusMeters) const {
  // Rotation only: directions from the camera, with no 6,400 km translation to lose in float.
  const glm::dmat4 rotation(glm::dmat3(view.viewMatrix));
  const glm::mat4 inverse(glm::inverse(view.projection * rotation));
  const double cameraRadius = glm::length(view.cameraEcefMeters);
  const glm::vec3 up = cameraRadius > 0.0 && std::isfinite(cameraRadius)
                           ? glm::vec3(view.cameraEcefMeters / cameraRadius)
                           : glm::vec3(0.0f, 0.0f, 1.0f);
  GLboolean depthTest = GL_FALSE;
  glGetBooleanv(GL_DEPTH_TEST, &depthTest);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);  // the triangle is at depth 1: where nothing was drawn
  glDepthMask(GL_FALSE);
  glUseProgram(program_.id());
  glUniformMatrix4fv(u_.inverseViewProjection, 1, GL_FALSE, glm::value_ptr(inverse));
  glUniform3fv(u_.up, 1, glm::value_ptr(up));
  glUniform1f(u_.cameraRadius, static_cast<float>(cameraRadius));
  glUniform1f(u_.globeRadius, static_cast<float>(globeRadiusMeters));
  glUniform1f(u_.atmosphereHeight, static_cast<float>(kAtmosphereHeightMeters));
  glUniform3fv(u_.zenith, 1, glm::value_ptr(sky.zenithRgb));
  glUniform3fv(u_.horizon, 1, glm::value_ptr(sky.horizonRgb));
  glUniform3fv(u_.glow, 1, glm::value_ptr(sky.glowRgb));
  glUniform1f(u_.spaceBlend, sky.spaceBlend);
  glUniform1f(u_.horizonCosine, sky.horizonCosine);
  // Under the real Sun the limb glows only where the air it grazes is lit.
  glUniform1i(u_.daylight, view.sunIsReal ? 1 : 0);
  glUniform3fv(u_.sunDirection, 1, glm::value_ptr(glm::vec3(view.sunDirectionEcef)));
  const DaylightBand band = daylightBand();
  glUniform3f(u_.daylightBand, band.nightLight, band.nightCosine, band.dayCosine);
  glBindVertexArray(vertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  if (depthTest != GL_TRUE) glDisable(GL_DEPTH_TEST);
}

}  // namespace globe::render
