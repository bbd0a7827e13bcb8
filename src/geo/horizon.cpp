// Horizon culling of a RegionVolume against a sphere inside the solid earth.
#include <cmath>

#include <glm/geometric.hpp>

#include "geo/bounding_region.hpp"

namespace globe::geo {

bool isBelowHorizon(const glm::dvec3& cameraEcefMeters, const RegionVolume& volume) {
  if (!volume.bounded) return false;
  const glm::dvec3& camera = cameraEcefMeters;
  if (!std::isfinite(camera.x) || !std::isfinite(camera.y) || !std::isfinite(camera.z)) {
    return false;
  }
  const double r = volume.occluderRadiusMeters;
  const double d = glm::length(camera);
  if (!(d > r)) return false;  // inside the occluder: it hides nothing we can reason about

  // The hidden set contains the convex set H = (cone from the camera tangent to the sphere) cut
  // by the plane of the horizon circle: every ray into the cone enters the sphere before that
  // plane. The hull of the points lies in H when each point does, and the margin ball around
  // each point does when the point is at least the margin away from the plane and the cone.
  const glm::dvec3 axis = -camera / d;  // towards the centre
  const double tangentLength = std::sqrt((d - r) * (d + r));
  const double sinHalfAngle = r / d;
  const double cosHalfAngle = tangentLength / d;
  const double horizonPlaneDistance = tangentLength * cosHalfAngle;  // (d^2 - r^2) / d
  const double margin = volume.marginMeters;
  for (const glm::dvec3& point : volume.pointsEcefMeters) {
    const glm::dvec3 v = point - camera;
    const double along = glm::dot(v, axis);
    if (along < horizonPlaneDistance + margin) return false;
    const double across = glm::length(v - along * axis);
    // |v| sin(halfAngle - angle(v, axis)): the distance from the point to the cone's surface.
    if (sinHalfAngle * along - cosHalfAngle * across < margin) return false;
  }
  return true;
}

bool isBelowHorizon(const glm::dvec3& cameraEcefMeters, const BoundingRegion& region,
                    const Ellipsoid& ellipsoid) {
  return isBelowHorizon(cameraEcefMeters, RegionVolume::fromRegion(region, ellipsoid));
}

}  // namespace globe::geo
