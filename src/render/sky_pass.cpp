#include "render/sky_pass.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "atmosphere/sky_view.hpp"
#include "render/shader_directory.hpp"

namespace globe::render {
namespace {

// Past the terrain's units (0 the global image, 1..4 layers, 5 the water mask).
constexpr GLuint kSkyViewUnit = 6;

}  // namespace

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
  u.physical = p.uniformLocation("u_physical");
  u.skyView = p.uniformLocation("u_skyView");
  u.horizonElevation = p.uniformLocation("u_horizonElevation");
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
  glUniform1i(u_.physical, physical_ ? 1 : 0);
  glUniform1f(u_.horizonElevation, static_cast<float>(horizonElevationRadians_));
  glUniform1i(u_.skyView, static_cast<GLint>(kSkyViewUnit));
  glActiveTexture(GL_TEXTURE0 + kSkyViewUnit);
  glBindTexture(GL_TEXTURE_2D, physical_ ? skyViewTexture_.get() : 0);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(vertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0 + kSkyViewUnit);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  if (depthTest != GL_TRUE) glDisable(GL_DEPTH_TEST);
}

float SkyPass::horizonRow() const {
  return static_cast<float>(atmosphere::skyViewRow(std::max(0.0, horizonElevationRadians_),
                                                   horizonElevationRadians_));
}

glm::vec3 SkyPass::usePhysicalSky(double heightMeters, double sunZenithCosine) {
  physical_ = true;
  const double height = std::isfinite(heightMeters) ? std::clamp(heightMeters, 0.0, 1e9) : 0.0;
  const std::pair<long, long> key{std::lround(std::log(10.0 + height) / std::log(1.01)),
                                  std::lround(std::clamp(sunZenithCosine, -1.0, 1.0) * 1000.0)};
  if (key == skyViewKey_ && skyViewTexture_) return horizonRgb_;
  skyViewKey_ = key;
  const auto& tables = atmosphere::SkyTables::earth();
  const atmosphere::SkyViewImage image =
      atmosphere::skyView(tables, tables.atmosphere().groundRadiusMeters + height, sunZenithCosine);
  horizonElevationRadians_ = image.horizonElevationRadians;
  horizonRgb_ =
      glm::vec3(image.at(0.5, atmosphere::skyViewRow(std::max(0.0, horizonElevationRadians_),
                                                     horizonElevationRadians_)));
  if (!skyViewTexture_) skyViewTexture_ = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, skyViewTexture_.get());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.rgba.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return horizonRgb_;
}

}  // namespace globe::render
