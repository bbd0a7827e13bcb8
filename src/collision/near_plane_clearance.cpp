// The worst miss of the near-plane points and the push that removes it.
#include "collision/near_plane_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "collision/clearance_settings.hpp"
#include "geo/ecef.hpp"

namespace globe::collision {
namespace {

// The lowest clearance of the points above the surface; nullopt if a point is invalid.
std::optional<double> lowestClearance(const RenderingTileArray& array,
                                      const geo::Ellipsoid& ellipsoid, const glm::dvec3& eye,
                                      std::span<const glm::dvec3> offsets, SurfaceModel model) {
  if (offsets.empty()) return std::nullopt;
  double lowest = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& offset : offsets) {
    const auto point = geo::ecefToCartographic(ellipsoid, eye + offset);
    if (!point) return std::nullopt;
    const auto surface =
        surfaceHeightAt(array, ellipsoid, point->longitudeRadians, point->latitudeRadians, model);
    if (!surface) return std::nullopt;
    lowest = std::min(lowest, point->heightMeters - surface->heightMeters);
  }
  return lowest;
}

}  // namespace

std::optional<double> lowestPointClearance(const RenderingTileArray& array,
                                           const geo::Ellipsoid& ellipsoid,
                                           const geo::Cartographic& eye,
                                           std::span<const glm::dvec3> offsetsEcefMeters,
                                           SurfaceModel model) {
  if (!std::isfinite(eye.heightMeters)) return std::nullopt;
  return lowestClearance(array, ellipsoid, geo::cartographicToEcef(ellipsoid, eye),
                         offsetsEcefMeters, model);
}

NearPlaneResult pushAboveNearPlane(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                                   const geo::Cartographic& eye,
                                   std::span<const glm::dvec3> offsetsEcefMeters,
                                   double clearanceMeters, SurfaceModel model) {
  NearPlaneResult result;
  result.position = eye;
  if (!std::isfinite(eye.heightMeters) || !std::isfinite(eye.longitudeRadians) ||
      !std::isfinite(eye.latitudeRadians) || !std::isfinite(clearanceMeters)) {
    return result;
  }
  if (offsetsEcefMeters.empty()) {
    result.valid = true;
    return result;
  }
  geo::Cartographic position = eye;
  std::optional<double> lowest = lowestClearance(
      array, ellipsoid, geo::cartographicToEcef(ellipsoid, position), offsetsEcefMeters, model);
  if (!lowest) return result;
  result.lowestClearanceBeforeMeters = *lowest;
  for (int k = 0; k < kMaximumClearancePushes && *lowest < clearanceMeters; ++k) {
    position.heightMeters += clearanceMeters - *lowest + kClearancePushMarginMeters;
    lowest = lowestClearance(array, ellipsoid, geo::cartographicToEcef(ellipsoid, position),
                             offsetsEcefMeters, model);
    if (!lowest) return result;
  }
  result.valid = true;
  result.position = position;
  result.pushMeters = position.heightMeters - eye.heightMeters;
  result.lowestClearanceAfterMeters = *lowest;
  return result;
}

}  // namespace globe::collision
