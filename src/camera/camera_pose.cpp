#include "camera/camera_pose.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geo/ecef.hpp"

namespace globe::camera {

CameraPose CameraPose::fromDegrees(double longitudeDegrees, double latitudeDegrees,
                                   double heightMeters, double headingDegrees, double pitchDegrees,
                                   double rollDegrees) {
  return {geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, heightMeters),
          geo::degreesToRadians(headingDegrees), geo::degreesToRadians(pitchDegrees),
          geo::degreesToRadians(rollDegrees)};
}

bool CameraPose::isFinite() const {
  return std::isfinite(position.longitudeRadians) && std::isfinite(position.latitudeRadians) &&
         std::isfinite(position.heightMeters) && std::isfinite(headingRadians) &&
         std::isfinite(pitchRadians) && std::isfinite(rollRadians);
}

bool samePose(const CameraPose& a, const CameraPose& b) {
  return a.position.longitudeRadians == b.position.longitudeRadians &&
         a.position.latitudeRadians == b.position.latitudeRadians &&
         a.position.heightMeters == b.position.heightMeters &&
         a.headingRadians == b.headingRadians && a.pitchRadians == b.pitchRadians &&
         a.rollRadians == b.rollRadians;
}

EastNorthUp eastNorthUp(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& position) {
  const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, position);
  const double lon = position.longitudeRadians;
  const glm::dvec3 east(-std::sin(lon), std::cos(lon), 0.0);
  return {east, glm::normalize(glm::cross(up, east)), up};
}

CameraFrame cameraFrame(const geo::Ellipsoid& ellipsoid, const CameraPose& pose) {
  const EastNorthUp enu = eastNorthUp(ellipsoid, pose.position);
  const double ch = std::cos(pose.headingRadians), sh = std::sin(pose.headingRadians);
  const double cp = std::cos(pose.pitchRadians), sp = std::sin(pose.pitchRadians);
  const glm::dvec3 horizontal = sh * enu.east + ch * enu.north;
  const glm::dvec3 forward = cp * horizontal + sp * enu.up;
  // Up is forward turned 90° upwards in the heading plane: at pitch −90° it points along heading.
  const glm::dvec3 up0 = -sp * horizontal + cp * enu.up;
  const glm::dvec3 right0 = glm::cross(forward, up0);
  const double cr = std::cos(pose.rollRadians), sr = std::sin(pose.rollRadians);
  const glm::dvec3 right = cr * right0 - sr * up0;
  const glm::dvec3 up = cr * up0 + sr * right0;
  return {geo::cartographicToEcef(ellipsoid, pose.position), glm::normalize(forward),
          glm::normalize(up), glm::normalize(right)};
}

glm::dmat4 viewMatrix(const CameraFrame& frame) {
  glm::dmat4 view(1.0);
  view[0][0] = frame.right.x;
  view[1][0] = frame.right.y;
  view[2][0] = frame.right.z;
  view[0][1] = frame.up.x;
  view[1][1] = frame.up.y;
  view[2][1] = frame.up.z;
  view[0][2] = -frame.forward.x;
  view[1][2] = -frame.forward.y;
  view[2][2] = -frame.forward.z;
  view[3][0] = -glm::dot(frame.right, frame.positionEcefMeters);
  view[3][1] = -glm::dot(frame.up, frame.positionEcefMeters);
  view[3][2] = glm::dot(frame.forward, frame.positionEcefMeters);
  return view;
}

glm::dmat4 projectionMatrix(const PerspectiveProjection& p) {
  return glm::perspective(p.fovYRadians, p.aspect, p.nearMeters, p.farMeters);
}

PerspectiveProjection projectionForHeight(double heightAboveEllipsoidMeters,
                                          double heightAboveTerrainMeters, double fovYRadians,
                                          double aspect, const geo::Ellipsoid& ellipsoid) {
  constexpr double kHighestTerrainMeters = 9000.0;
  const double r = ellipsoid.semiMinorAxisMeters;
  const double h = std::max(heightAboveEllipsoidMeters, 0.0);
  const double cameraHorizon = std::sqrt(h * (2 * r + h));
  const double mountainHorizon = std::sqrt(kHighestTerrainMeters * (2 * r + kHighestTerrainMeters));
  PerspectiveProjection p;
  p.fovYRadians = fovYRadians;
  p.aspect = aspect;
  // Logarithmic depth keeps precision across the range, so near can stay small near the ground.
  p.nearMeters = std::clamp(0.25 * heightAboveTerrainMeters, 0.1, 1000.0);
  p.farMeters = cameraHorizon + mountainHorizon + ellipsoid.semiMajorAxisMeters * 0.01;
  return p;
}

}  // namespace globe::camera
