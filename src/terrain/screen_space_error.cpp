// Geometric error per level, the distance lower bound to a region, and screen-space error.
#include "terrain/screen_space_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::terrain {

double geometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                            const geo::Ellipsoid& ellipsoid) {
  const double cells = verticesPerSide < 2 ? 1.0 : static_cast<double>(verticesPerSide - 1);
  const double spacingRadians = std::ldexp(std::numbers::pi / cells, -static_cast<int>(level));
  return kTerrainQuality * ellipsoid.semiMajorAxisMeters * spacingRadians;
}

double tileGeometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                                const geo::Ellipsoid& ellipsoid,
                                double measuredGeometricErrorMeters, double faceOn) {
  const double nominal = geometricErrorMeters(level, verticesPerSide, ellipsoid);
  if (!(measuredGeometricErrorMeters >= 0.0) || !std::isfinite(measuredGeometricErrorMeters) ||
      level < kMeasuredErrorMinimumLevel) {
    return nominal;
  }
  const double a = ellipsoid.semiMajorAxisMeters;
  const double spacingMeters = nominal / kTerrainQuality;  // a × the spacing in radians
  const double measured = measuredGeometricErrorMeters + spacingMeters * spacingMeters / (8 * a);
  const double floor = std::isnan(faceOn) ? 1.0 : std::clamp(faceOn, kMeasuredErrorFloor, 1.0);
  return std::clamp(measured, floor * nominal, nominal);
}

double faceOnFraction(const glm::dvec3& cameraEcefMeters, const std::vector<glm::dvec3>& points,
                      const geo::Ellipsoid& ellipsoid) {
  double largest = 0.0;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 toCamera = cameraEcefMeters - p;
    const double length = glm::length(toCamera);
    if (!(length > 0.0)) return 1.0;  // the camera on the region: as if from above
    const double cosine = glm::dot(geo::geodeticSurfaceNormal(ellipsoid, p), toCamera) / length;
    if (cosine > largest) largest = cosine;
  }
  return std::isfinite(largest) ? std::min(largest, 1.0) : 1.0;
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
