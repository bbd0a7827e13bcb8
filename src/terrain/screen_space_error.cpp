// Geometric error per level, the distance lower bound to a region, and screen-space error.
#include "terrain/screen_space_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

namespace globe::terrain {

double geometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                            const geo::Ellipsoid& ellipsoid) {
  const double cells = verticesPerSide < 2 ? 1.0 : static_cast<double>(verticesPerSide - 1);
  const double spacingRadians = std::ldexp(std::numbers::pi / cells, -static_cast<int>(level));
  return kTerrainQuality * ellipsoid.semiMajorAxisMeters * spacingRadians;
}

double tileGeometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                                const geo::Ellipsoid& ellipsoid,
                                double measuredGeometricErrorMeters) {
  const double nominal = geometricErrorMeters(level, verticesPerSide, ellipsoid);
  if (!(measuredGeometricErrorMeters >= 0.0) || !std::isfinite(measuredGeometricErrorMeters)) {
    return nominal;
  }
  const double a = ellipsoid.semiMajorAxisMeters;
  const double spacingMeters = nominal / kTerrainQuality;  // a × the spacing in radians
  const double measured = measuredGeometricErrorMeters + spacingMeters * spacingMeters / (8 * a);
  return std::clamp(measured, kMeasuredErrorFloor * nominal, nominal);
}

double screenSpaceErrorPixels(double geometricErrorMeters, double distanceMeters,
                              const SelectionView& view) {
  if (geometricErrorMeters == 0.0) return 0.0;
  const double distance =
      distanceMeters >= kMinimumDistanceMeters ? distanceMeters : kMinimumDistanceMeters;
  return geometricErrorMeters * view.viewportHeightPixels /
         (2.0 * distance * std::tan(view.fovYRadians / 2.0));
}

double distanceLowerBoundMeters(const glm::dvec3& cameraEcefMeters, double cameraHeightMeters,
                                const geo::RegionVolume& volume) {
  if (!volume.bounded || volume.pointsEcefMeters.empty()) return 0.0;
  double bound = 0.0;
  if (std::isfinite(cameraHeightMeters)) {
    bound = cameraHeightMeters - std::max(volume.region.maximumHeightMeters, 0.0);
  }
  const glm::dvec3 toCenter = volume.centerEcefMeters - cameraEcefMeters;
  const double length = glm::length(toCenter);
  if (length > 0.0 && std::isfinite(length)) {
    const glm::dvec3 direction = toCenter / length;
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& point : volume.pointsEcefMeters) {
      nearest = std::min(nearest, glm::dot(direction, point - cameraEcefMeters));
    }
    bound = std::max(bound, nearest - volume.marginMeters);
  }
  return bound > 0.0 ? bound : 0.0;
}

}  // namespace globe::terrain
