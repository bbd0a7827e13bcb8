// What one frame is drawn from: camera pose and projection in double, viewport, sun direction.
#pragma once

#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace globe::terrain {

// Farthest distance drawn by default: 100,000 km (the whole globe from 40,000 km fits).
inline constexpr double kDefaultFarMeters = 1.0e8;
// Nearest distance drawn by default: 5 cm, so a camera 1 m above the ground sees it.
inline constexpr double kDefaultNearMeters = 0.05;

struct RenderView {
  glm::dvec3 cameraEcefMeters{0.0};
  glm::dmat4 viewMatrix{1.0};  // ECEF → camera (eye) space, rigid, the full transform in double
  glm::dmat4 projection{1.0};  // eye → clip space, OpenGL conventions (looks down −z, z in [−w, w])
  // Depth is logarithmic in the eye distance w (see terrain_renderer.hpp); this is the w mapped to
  // depth 1: anything farther is not drawn. The projection's own far plane does not matter.
  double farMeters = kDefaultFarMeters;
  int widthPixels = 0;
  int heightPixels = 0;
  glm::dvec3 sunDirectionEcef{1.0, 0.0, 0.0};  // unit vector from the ground towards the sun
  // The direction is the real Sun's at an instant (--time): the night side is dark, the sky too.
  // Otherwise it is a light that follows the camera and every place is lit as by day.
  bool sunIsReal = false;
  // The camera's height above the globe's surface, for the sky; NaN: its WGS84 geodetic height.
  double cameraHeightMeters = std::numeric_limits<double>::quiet_NaN();
};

// Perspective projection (glm::perspective in double); nearMeters > 0.
glm::dmat4 makePerspective(double fovYRadians, double aspect, double nearMeters, double farMeters);

// A view from `eyeEcefMeters` looking at `targetEcefMeters` with `upEcef` roughly up on screen,
// projection from the vertical field of view and the viewport's aspect.
RenderView makeLookAtView(const glm::dvec3& eyeEcefMeters, const glm::dvec3& targetEcefMeters,
                          const glm::dvec3& upEcef, double fovYRadians, int widthPixels,
                          int heightPixels, const glm::dvec3& sunDirectionEcef,
                          double nearMeters = kDefaultNearMeters,
                          double farMeters = kDefaultFarMeters);

}  // namespace globe::terrain
