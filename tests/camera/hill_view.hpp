// What the orbit-controls and navigator tests share: a 1280x720 view with a 45-degree field over a
// smooth real-sized hill near Mount Fuji, and how far a point lies from a pixel's ray.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "camera/camera_pose.hpp"
#include "camera/fly_to.hpp"
#include "geo/cartographic.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera::testing {

inline constexpr int kWidth = 1280, kHeight = 720;

// A smooth real-sized hill (3,700 m, 20 km wide) on the ellipsoid, around Mount Fuji.
inline std::optional<double> hill(double lon, double lat) {
  const double dLon = (lon - geo::degreesToRadians(138.73)) * 6.4e6 * std::cos(lat);
  const double dLat = (lat - geo::degreesToRadians(35.36)) * 6.4e6;
  return 3700.0 * std::exp(-(dLon * dLon + dLat * dLat) / (2 * 8000.0 * 8000.0));
}

// How far (in pixels at this field of view) the point lies from the ray through the pixel.
inline double pixelsOff(const CameraPose& pose, glm::dvec2 pixel, const glm::dvec3& point) {
  using test::kFovY;
  const CameraFrame frame = cameraFrame(test::kWgs84, pose);
  const glm::dvec3 ray = pixelRayEcef(frame, pixel.x, pixel.y, kWidth, kHeight, kFovY);
  const glm::dvec3 toPoint = glm::normalize(point - frame.positionEcefMeters);
  const double angle = std::acos(std::clamp(glm::dot(ray, toPoint), -1.0, 1.0));
  return angle / (kFovY / kHeight);
}

}  // namespace globe::camera::testing
