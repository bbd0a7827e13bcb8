// Heading and pitch towards a point; a KML LookAt's camera (look_at.hpp).
#include "camera/look_at.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::camera {

CameraPose lookingAt(const geo::Ellipsoid& ellipsoid, CameraPose pose,
                     const glm::dvec3& targetEcefMeters) {
  const glm::dvec3 eye = geo::cartographicToEcef(ellipsoid, pose.position);
  const glm::dvec3 toTarget = targetEcefMeters - eye;
  const double distance = glm::length(toTarget);
  if (!(distance > 1e-6)) return pose;
  const glm::dvec3 d = toTarget / distance;
  const EastNorthUp enu = eastNorthUp(ellipsoid, pose.position);
  const double east = glm::dot(d, enu.east), north = glm::dot(d, enu.north);
  pose.pitchRadians = std::asin(std::clamp(glm::dot(d, enu.up), -1.0, 1.0));
  if (std::hypot(east, north) > 1e-12) pose.headingRadians = std::atan2(east, north);
  return pose;
}

CameraPose cameraOfLookAt(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& target,
                          double headingDegrees, double tiltDegrees, double rangeMeters) {
  const EastNorthUp enu = eastNorthUp(ellipsoid, target);
  const double heading = headingDegrees * std::numbers::pi / 180.0, tilt = tiltDegrees * std::numbers::pi / 180.0;
  const glm::dvec3 horizontal = std::sin(heading) * enu.east + std::cos(heading) * enu.north;
  // The view points along heading, tilt away from straight down; the camera sits back along it.
  const glm::dvec3 view = std::sin(tilt) * horizontal - std::cos(tilt) * enu.up;
  const glm::dvec3 targetEcef = geo::cartographicToEcef(ellipsoid, target);
  const auto position = geo::ecefToCartographic(ellipsoid, targetEcef - rangeMeters * view);
  CameraPose pose;
  pose.position = position.value_or(target);
  pose.headingRadians = heading;
  pose.pitchRadians = tilt - std::numbers::pi / 2.0;
  return lookingAt(ellipsoid, pose, targetEcef);
}

}  // namespace globe::camera
