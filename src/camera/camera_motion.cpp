// Motion classification, rotation about the geocentre and the near plane's corners.
#include "camera/camera_motion.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

constexpr double kSameHeightMeters = 1e-6;
constexpr double kSamePositionMeters = 1e-6;

}  // namespace

std::string_view toString(MotionKind kind) {
  switch (kind) {
    case MotionKind::Auto:
      return "auto";
    case MotionKind::None:
      return "none";
    case MotionKind::Jump:
      return "jump";
    case MotionKind::Linear:
      return "linear";
    case MotionKind::Angular:
      return "angular";
  }
  return "unknown";
}

bool isSamePosition(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& a,
                    const geo::Cartographic& b) {
  const double distance =
      glm::length(geo::cartographicToEcef(ellipsoid, a) - geo::cartographicToEcef(ellipsoid, b));
  return distance <= kSamePositionMeters;
}

MotionKind classifyMotion(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& from,
                          const geo::Cartographic& to, double jumpDistanceMeters) {
  const double distance = glm::length(geo::cartographicToEcef(ellipsoid, to) -
                                      geo::cartographicToEcef(ellipsoid, from));
  if (!(distance > kSamePositionMeters) || distance > jumpDistanceMeters) return MotionKind::Jump;
  if (std::abs(to.heightMeters - from.heightMeters) <= kSameHeightMeters) {
    return MotionKind::Angular;
  }
  return MotionKind::Linear;
}

glm::dvec3 rotateAboutGeocentre(const glm::dvec3& pointEcefMeters,
                                const glm::dvec3& rotationRadians) {
  const double angle = glm::length(rotationRadians);
  if (!(angle > 0.0) || !std::isfinite(angle)) return pointEcefMeters;
  const glm::dvec3 axis = rotationRadians / angle;
  const double c = std::cos(angle), s = std::sin(angle);
  return pointEcefMeters * c + glm::cross(axis, pointEcefMeters) * s +
         axis * glm::dot(axis, pointEcefMeters) * (1.0 - c);
}

std::array<glm::dvec3, 4> nearPlaneCornerOffsets(const CameraFrame& frame,
                                                 const NearPlane& nearPlane) {
  const double halfHeight = nearPlane.nearMeters * std::tan(0.5 * nearPlane.fovYRadians);
  const double halfWidth = halfHeight * nearPlane.aspect;
  const glm::dvec3 centre = nearPlane.nearMeters * frame.forward;
  const glm::dvec3 up = halfHeight * frame.up, right = halfWidth * frame.right;
  return {centre + up - right, centre + up + right, centre - up - right, centre - up + right};
}

}  // namespace globe::camera
