// Building the conservative lattice hull (RegionVolume) of a BoundingRegion.
#include "geo/bounding_region.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::geo {

namespace {

constexpr double kPi = std::numbers::pi;
// Lattice cells of at most ~11.25 deg keep the bulge margin near 0.5% of the radius, and at most
// 8x8 cells keep big (level 0-2) tiles at <= 162 points; tiles from level 4 on need 8 points.
constexpr double kTargetCellRadians = kPi / 16.0;
constexpr int kMaxCells = 8;
constexpr double kLowestAllowedHeightMeters = -1e6;

int cellCount(double extentRadians) {
  // The tolerance keeps an exact 11.25 deg tile (level 4) at one cell despite rounding.
  const double cells = std::ceil(extentRadians / kTargetCellRadians - 1e-9);
  return std::clamp(static_cast<int>(std::min(cells, double{kMaxCells})), 1, kMaxCells);
}

// 1 - cos(t/2), written to avoid cancellation for small t.
double bulgeFactor(double turnRadians) {
  const double s = std::sin(turnRadians / 4.0);
  return 2.0 * s * s;
}

}  // namespace

bool BoundingRegion::isValid() const {
  const GlobeRectangle& r = rectangle;
  const bool finite = std::isfinite(r.westRadians) && std::isfinite(r.eastRadians) &&
                      std::isfinite(r.southRadians) && std::isfinite(r.northRadians) &&
                      std::isfinite(minimumHeightMeters) && std::isfinite(maximumHeightMeters);
  return finite && -kPi <= r.westRadians && r.westRadians <= r.eastRadians &&
         r.eastRadians <= kPi && -kPi / 2.0 <= r.southRadians && r.southRadians <= r.northRadians &&
         r.northRadians <= kPi / 2.0 && kLowestAllowedHeightMeters <= minimumHeightMeters &&
         minimumHeightMeters <= maximumHeightMeters;
}

RegionVolume RegionVolume::fromRegion(const BoundingRegion& region, const Ellipsoid& ellipsoid) {
  RegionVolume volume;
  volume.region = region;
  if (!region.isValid()) return volume;
  volume.bounded = true;

  const GlobeRectangle& r = region.rectangle;
  const int columns = cellCount(r.widthRadians());
  const int rows = cellCount(r.heightRadians());
  const double cellWidth = r.widthRadians() / columns;
  const double cellHeight = r.heightRadians() / rows;
  const bool flat = region.minimumHeightMeters == region.maximumHeightMeters;

  volume.pointsEcefMeters.reserve(static_cast<size_t>((columns + 1) * (rows + 1) * 2));
  for (const double height : {region.minimumHeightMeters, region.maximumHeightMeters}) {
    for (int j = 0; j <= rows; ++j) {
      // The last row/column use the exact edges, not an accumulated sum.
      const double latitude = j == rows ? r.northRadians : r.southRadians + j * cellHeight;
      for (int i = 0; i <= columns; ++i) {
        const double longitude = i == columns ? r.eastRadians : r.westRadians + i * cellWidth;
        volume.pointsEcefMeters.push_back(
            cartographicToEcef(ellipsoid, {longitude, latitude, height}));
      }
    }
    if (flat) break;
  }

  // Radii of curvature: meridian M + h and parallel (N + h) cos(lat), with M, N <= a^2/b (poles).
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  const double maxRadius = a * a / b + region.maximumHeightMeters;
  const double maxCosLatitude = (r.southRadians <= 0.0 && r.northRadians >= 0.0)
                                    ? 1.0
                                    : std::max(std::cos(r.southRadians), std::cos(r.northRadians));
  // Plus a rounding allowance (1e-9 relative, ~6 mm on earth) for the ECEF points themselves.
  const double roundingMeters = 1e-9 * (maxRadius + std::abs(region.minimumHeightMeters));
  volume.marginMeters =
      maxRadius * (maxCosLatitude * bulgeFactor(cellWidth) + bulgeFactor(cellHeight)) +
      roundingMeters;

  glm::dvec3 sum{0.0};
  for (const glm::dvec3& p : volume.pointsEcefMeters) sum += p;
  volume.centerEcefMeters = sum / static_cast<double>(volume.pointsEcefMeters.size());
  double maxDistance = 0.0;
  for (const glm::dvec3& p : volume.pointsEcefMeters) {
    maxDistance = std::max(maxDistance, glm::distance(p, volume.centerEcefMeters));
  }
  volume.radiusMeters = maxDistance + volume.marginMeters;
  volume.occluderRadiusMeters =
      b + std::min(kLowestTerrainHeightMeters, region.minimumHeightMeters);
  return volume;
}

}  // namespace globe::geo
