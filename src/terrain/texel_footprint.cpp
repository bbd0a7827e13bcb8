#include "terrain/texel_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/tiling_scheme.hpp"

namespace globe::terrain {

double meridianSpacingMeters(const geo::TileId& tile, int intervals,
                             const geo::Ellipsoid& ellipsoid) {
  if (!geo::GeographicTilingScheme::isValid(tile) || intervals <= 0) return 0.0;
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  return (b * b / a) * rect.heightRadians() / intervals;
}

double shortestTexelMeters(const geo::TileId& tile, int widthPixels, int heightPixels,
                           const geo::Ellipsoid& ellipsoid) {
  const double northSouth = meridianSpacingMeters(tile, heightPixels, ellipsoid);
  if (northSouth <= 0.0 || widthPixels <= 0) return 0.0;
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double a = ellipsoid.semiMajorAxisMeters;
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

TileBox makeTileBox(const glm::dvec3& centerEcefMeters, std::span<const glm::dvec3> offsetsMeters) {
  TileBox box;
  box.centerEcefMeters = centerEcefMeters;
  const glm::dvec3 up = glm::normalize(centerEcefMeters);
  // East, except at a pole where any direction across will do.
  const glm::dvec3 pole(0.0, 0.0, 1.0);
  const glm::dvec3 across = glm::cross(pole, up);
  const glm::dvec3 east = glm::length(across) > 1e-9 ? glm::normalize(across) : glm::dvec3(1, 0, 0);
  box.axes = {east, glm::cross(up, east), up};
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  box.minMeters = glm::dvec3(kInfinity);
  box.maxMeters = glm::dvec3(-kInfinity);
  for (const glm::dvec3& offset : offsetsMeters) {
    for (int i = 0; i < 3; ++i) {
      const double along = glm::dot(offset, box.axes[static_cast<size_t>(i)]);
      box.minMeters[i] = std::min(box.minMeters[i], along);
      box.maxMeters[i] = std::max(box.maxMeters[i], along);
    }
  }
  return box;
}

double maxTexelsPerPixel(const glm::dvec3& cameraEcefMeters, const TileBox& tile,
                         double texelMeters, double pixelAngleRadians,
                         const geo::Ellipsoid& ellipsoid) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const glm::dvec3 toCamera = cameraEcefMeters - tile.centerEcefMeters;
  const double heightMeters = glm::dot(toCamera, tile.axes[2]) - tile.maxMeters.z;
  // The farthest corner (distance is convex: no point of the box is farther).
  double farthestSquared = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 at = tile.centerEcefMeters;
    for (int i = 0; i < 3; ++i) {
      at += tile.axes[static_cast<size_t>(i)] *
            ((corner >> i) & 1 ? tile.maxMeters[i] : tile.minMeters[i]);
    }
    farthestSquared =
        std::max(farthestSquared, glm::dot(cameraEcefMeters - at, cameraEcefMeters - at));
  }
  const double farthestMeters = std::sqrt(farthestSquared);
  const double acrossMeters =
      std::hypot(std::max(std::abs(tile.minMeters.x), std::abs(tile.maxMeters.x)),
                 std::max(std::abs(tile.minMeters.y), std::abs(tile.maxMeters.y)));
  const double tilt = surfaceTiltRadians(acrossMeters, ellipsoid);
  // A ray at θ from the normal and the next one α further meet the plane d·sin α / cos(θ + α)
  // apart; cos(θ + tilt + α) >= cos θ·cos(tilt + α) − sin(tilt + α), and cos θ >= h / d.
  const double turn = tilt + pixelAngleRadians;
  const double cosine = heightMeters / farthestMeters * std::cos(turn) - std::sin(turn);
  // (cosine > 0) also rejects NaN; the rest must be finite and positive where divided by.
  if (!(cosine > 0.0) || !(texelMeters > 0.0) || !(pixelAngleRadians > 0.0) ||
      !std::isfinite(farthestMeters) || !std::isfinite(acrossMeters) ||
      !(std::abs(glm::length(tile.axes[2]) - 1.0) < 1e-6)) {
    return kUnbounded;
  }
  const double rho = farthestMeters * pixelAngleRadians / (cosine * texelMeters);
  return std::isfinite(rho) ? rho : kUnbounded;
}

}  // namespace globe::terrain
