// Geodetic <-> ECEF conversions; the inverse uses Bowring's iteration on WGS84.
#include "geo/ecef.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace globe::geo {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr int kMaximumBowringIterations = 50;

// sqrt(c² + s²) where the squares cannot overflow (every position on or near a globe), hypot
// beyond: glibc's hypot guards against overflow at ~50 ns a call, the plain form costs ~5 ns.
double length(double c, double s) {
  constexpr double kSafe = 1e150;
  if (std::abs(c) < kSafe && std::abs(s) < kSafe) return std::sqrt(c * c + s * s);
  return std::hypot(c, s);
}

bool isFinite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// (cos, sin) of an angle held as a unit vector, so the iteration needs no trigonometry.
struct Direction {
  double cos;
  double sin;
};

// Normalises (c, s); a zero vector maps to angle 0, which only happens deep inside the evolute.
Direction direction(double c, double s) {
  const double norm = length(c, s);
  if (!(norm > 0.0)) return {1.0, 0.0};
  return {c / norm, s / norm};
}

// Geodetic latitude of a point at distance p from the polar axis and height z above the equator
// plane, for p > 0. Bowring (1976): iterate the parametric latitude beta, with
// tan(lat) = (z + e'^2 b sin^3 beta) / (p - e^2 a cos^3 beta), tan(beta) = (b/a) tan(lat).
// One step is ~1e-10 rad off on the surface. Convergence is fast, so once a step moves the
// latitude by < 1e-14 the new value is at the rounding level: 2-3 iterations in practice.
// Near the evolute (within ~43 km of the centre on WGS84) convergence slows down: a cap of 6
// steps left points there up to 64 m off their round trip; 30 reach the rounding level, the cap
// of 50 leaves a margin. Down to 6,200 km below the surface at most 5 steps are taken.
Direction bowringLatitude(double a, double b, double p, double z) {
  const double e2 = 1.0 - (b / a) * (b / a);
  const double ep2 = (a / b) * (a / b) - 1.0;
  // tan(beta0) = (a/b) z/p, scaled so that nothing overflows below ~1e308 m.
  Direction beta = direction(p, z * (a / b));
  Direction lat{1.0, 0.0};
  for (int iteration = 0; iteration < kMaximumBowringIterations; ++iteration) {
    const double numerator = z + ep2 * b * beta.sin * beta.sin * beta.sin;
    // Negative only inside the evolute (p < e^2 a); clamping keeps |lat| <= pi/2.
    const double denominator = std::max(0.0, p - e2 * a * beta.cos * beta.cos * beta.cos);
    const Direction next = direction(denominator, numerator);
    const bool converged = iteration > 0 && std::abs(next.sin - lat.sin) <= 1e-14 &&
                           std::abs(next.cos - lat.cos) <= 1e-14;
    lat = next;
    if (converged) break;
    beta = direction(a * lat.cos, b * lat.sin);
  }
  return lat;
}

}  // namespace

glm::dvec3 cartographicToEcef(const Ellipsoid& ellipsoid, const Cartographic& cartographic) {
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  const double sinLat = std::sin(cartographic.latitudeRadians);
  const double cosLat = std::cos(cartographic.latitudeRadians);
  // Prime vertical radius of curvature N; N (1 - e^2) = N b^2 / a^2.
  const double n = a / std::sqrt(1.0 - ellipsoid.eccentricitySquared() * sinLat * sinLat);
  const double h = cartographic.heightMeters;
  const double rho = (n + h) * cosLat;
  return {rho * std::cos(cartographic.longitudeRadians),
          rho * std::sin(cartographic.longitudeRadians), (n * (b / a) * (b / a) + h) * sinLat};
}

namespace {

// The inverse conversion; the normal too when asked for (one division more).
std::optional<Cartographic> solveGeodetic(const Ellipsoid& ellipsoid, const glm::dvec3& ecefMeters,
                                          glm::dvec3* normal) {
  if (!isFinite(ecefMeters)) return std::nullopt;
  const double x = ecefMeters.x;
  const double y = ecefMeters.y;
  const double z = ecefMeters.z;
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  const double p = length(x, y);
  const double r = length(p, z);
  if (r < kGeocentreThresholdMeters) return std::nullopt;

  Cartographic result{};
  if (p == 0.0) {
    // Exactly on the polar axis: the longitude is arbitrary, pick 0.
    result = {0.0, z > 0.0 ? kHalfPi : -kHalfPi, std::abs(z) - b};
    if (normal != nullptr) *normal = {0.0, 0.0, z > 0.0 ? 1.0 : -1.0};
  } else if (ellipsoid.isSphere()) {
    result = {std::atan2(y, x), std::atan2(z, p), r - a};
    if (normal != nullptr) *normal = ecefMeters / r;
  } else {
    const Direction lat = bowringLatitude(a, b, p, z);
    // Sum of projections onto the normal: no division by cos(lat), so well conditioned at the
    // poles; a sqrt(1 - e^2 sin^2 lat) is the distance from the surface point to the same line.
    const double e2 = ellipsoid.eccentricitySquared();
    const double height = p * lat.cos + z * lat.sin - a * std::sqrt(1.0 - e2 * lat.sin * lat.sin);
    result = {std::atan2(y, x), std::atan2(lat.sin, lat.cos), height};
    if (normal != nullptr) {
      // (cos lon, sin lon) = (x, y) / p.
      const double cosLatOverP = lat.cos / p;
      *normal = {x * cosLatOverP, y * cosLatOverP, lat.sin};
    }
  }
  // Overflow of huge (> ~1e307 m) inputs is the only way to get here without a finite height.
  if (!std::isfinite(result.heightMeters)) return std::nullopt;
  return result;
}

}  // namespace

std::optional<Cartographic> ecefToCartographic(const Ellipsoid& ellipsoid,
                                               const glm::dvec3& ecefMeters) {
  return solveGeodetic(ellipsoid, ecefMeters, nullptr);
}

std::optional<GeodeticFrame> ecefToGeodeticFrame(const Ellipsoid& ellipsoid,
                                                 const glm::dvec3& ecefMeters) {
  GeodeticFrame frame{};
  const std::optional<Cartographic> cartographic =
      solveGeodetic(ellipsoid, ecefMeters, &frame.normal);
  if (!cartographic) return std::nullopt;
  frame.cartographic = *cartographic;
  return frame;
}

glm::dvec3 geodeticSurfaceNormal(const Ellipsoid&, const Cartographic& cartographic) {
  const double cosLat = std::cos(cartographic.latitudeRadians);
  return {cosLat * std::cos(cartographic.longitudeRadians),
          cosLat * std::sin(cartographic.longitudeRadians), std::sin(cartographic.latitudeRadians)};
}

glm::dvec3 geodeticSurfaceNormal(const Ellipsoid& ellipsoid, const glm::dvec3& ecefMeters) {
  const std::optional<Cartographic> cartographic = ecefToCartographic(ellipsoid, ecefMeters);
  if (!cartographic) return {0.0, 0.0, 1.0};
  return geodeticSurfaceNormal(ellipsoid, *cartographic);
}

}  // namespace globe::geo
