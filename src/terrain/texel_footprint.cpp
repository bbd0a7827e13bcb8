#include "terrain/texel_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/tiling_scheme.hpp"

namespace globe::terrain {

double shortestTexelMeters(const geo::TileId& tile, int widthPixels, int heightPixels,
                           const geo::Ellipsoid& ellipsoid) {
  if (!geo::GeographicTilingScheme::isValid(tile) || widthPixels <= 0 || heightPixels <= 0)
    return 0.0;
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  const double northSouth = (b * b / a) * rect.heightRadians() / heightPixels;
  const double farthestLatitude =
      std::max(std::abs(rect.northRadians), std::abs(rect.southRadians));
  if (farthestLatitude >= std::numbers::pi / 2) return 0.0;  // cos(pi/2) is not quite 0
  const double eastWest = a * std::cos(farthestLatitude) * rect.widthRadians() / widthPixels;
  return std::min(northSouth, eastWest);
}

double pixelAngleRadians(const RenderView& view) {
  if (view.widthPixels <= 0 || view.heightPixels <= 0)
    return std::numeric_limits<double>::quiet_NaN();
  const double tanHalfY = 1.0 / view.projection[1][1];
  const double tanHalfX = 1.0 / view.projection[0][0];
  const double angle = std::max(2.0 * std::atan(tanHalfY / view.heightPixels),
                                2.0 * std::atan(tanHalfX / view.widthPixels));
  return std::isfinite(angle) && angle > 0.0 ? angle : std::numeric_limits<double>::quiet_NaN();
}

double surfaceTiltRadians(double radiusMeters, const geo::Ellipsoid& ellipsoid) {
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  // The geocentric and geodetic latitudes differ by at most about e²/2 (+1 % for the higher
  // order terms).
  return radiusMeters / (b * b / a) + ellipsoid.eccentricitySquared() / 2.0 * 1.01;
}

double maxTexelsPerPixel(const glm::dvec3& cameraEcefMeters, const TileBounds& tile,
                         double texelMeters, double pixelAngleRadians,
                         const geo::Ellipsoid& ellipsoid) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const glm::dvec3 toCamera = cameraEcefMeters - tile.centerEcefMeters;
  const double heightMeters = glm::dot(toCamera, tile.upEcef) - tile.topMeters;
  const double farthestMeters = glm::length(toCamera) + tile.radiusMeters;
  const double tilt = surfaceTiltRadians(tile.radiusMeters, ellipsoid);
  // A ray at θ from the normal and the next one α further meet the plane d·sin α / cos(θ + α)
  // apart; cos(θ + tilt + α) >= cos θ·cos(tilt + α) − sin(tilt + α), and cos θ >= h / d.
  const double turn = tilt + pixelAngleRadians;
  const double cosine = heightMeters / farthestMeters * std::cos(turn) - std::sin(turn);
  // (cosine > 0) also rejects NaN; the rest must be finite and positive where divided by.
  if (!(cosine > 0.0) || !(texelMeters > 0.0) || !(pixelAngleRadians > 0.0) ||
      !(tile.radiusMeters >= 0.0) || !std::isfinite(farthestMeters) ||
      !std::isfinite(tile.topMeters) || !(std::abs(glm::length(tile.upEcef) - 1.0) < 1e-6)) {
    return kUnbounded;
  }
  const double rho = farthestMeters * pixelAngleRadians / (cosine * texelMeters);
  return std::isfinite(rho) ? rho : kUnbounded;
}

}  // namespace globe::terrain
