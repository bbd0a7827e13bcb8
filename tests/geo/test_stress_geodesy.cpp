// Stress tests for geo/ecef.hpp over 10^7 points per globe model (a twentieth under the
// sanitizers): geodetic -> ECEF -> geodetic with exact poles, +-180 deg and one ulp around them,
// tile edges and corners of every level, heights from -430 m to 4e7 m; and ECEF -> geodetic ->
// ECEF from the geocentre out to 1e8 m. Reports the largest errors in metres and the time taken.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "stress_scale.hpp"

namespace globe::geo {
namespace {

using Scheme = GeographicTilingScheme;
constexpr double kHalfPi = std::numbers::pi / 2.0;
// Round trips must hold to a micrometre everywhere (the documented accuracy of ecefToCartographic).
constexpr double kRoundTripToleranceMeters = 1e-6;

template <size_t N>
double pick(std::mt19937_64& rng, const double (&values)[N]) {
  return values[rng() % N];
}

TileId randomTile(std::mt19937_64& rng) {
  const uint32_t level = static_cast<uint32_t>(rng() % (kMaxLevel + 1));
  return {level, static_cast<uint32_t>(rng() % Scheme::tilesX(level)),
          static_cast<uint32_t>(rng() % Scheme::tilesY(level))};
}

// Exactly on, or one ulp either side of, a value.
double aroundUlp(std::mt19937_64& rng, double value) {
  switch (rng() % 3) {
    case 0:
      return std::nextafter(value, -4.0);
    case 1:
      return std::nextafter(value, 4.0);
    default:
      return value;
  }
}

double randomLongitude(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const uint64_t kind = rng() % 20;
  if (kind < 12) return -std::numbers::pi + 2.0 * std::numbers::pi * unit(rng);
  if (kind < 15) {  // +-180 deg and the other special meridians, one ulp either side
    static const double special[] = {std::numbers::pi, -std::numbers::pi, 0.0,   -0.0,
                                     kHalfPi,          -kHalfPi,          1e-300};
    return aroundUlp(rng, pick(rng, special));
  }
  if (kind < 19) {  // a tile's west or east edge at any level, one ulp either side
    const GlobeRectangle r = Scheme::tileRectangle(randomTile(rng));
    return aroundUlp(rng, (rng() & 1) ? r.westRadians : r.eastRadians);
  }
  return (unit(rng) - 0.5) * 2000.0;  // far outside [-pi, pi]: wrapped by the conversions
}

double randomLatitude(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const uint64_t kind = rng() % 20;
  if (kind < 6) return -kHalfPi + std::numbers::pi * unit(rng);
  if (kind < 12) return std::asin(2.0 * unit(rng) - 1.0);  // uniform over the surface
  if (kind < 16) {  // the poles exactly and one ulp inside, the equator
    static const double special[] = {kHalfPi,
                                     -kHalfPi,
                                     std::nextafter(kHalfPi, 0.0),
                                     std::nextafter(-kHalfPi, 0.0),
                                     kHalfPi - 1e-9,
                                     -kHalfPi + 1e-9,
                                     0.0,
                                     -0.0,
                                     1e-300};
    return pick(rng, special);
  }
  // A tile's north or south edge at any level, one ulp either side but never beyond a pole.
  const GlobeRectangle r = Scheme::tileRectangle(randomTile(rng));
  return std::clamp(aroundUlp(rng, (rng() & 1) ? r.southRadians : r.northRadians), -kHalfPi,
                    kHalfPi);
}

// -430 m (the lowest land) to 4e7 m: uniform near the ground, log-uniform above, exact extremes.
double randomHeight(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const uint64_t kind = rng() % 10;
  if (kind < 3) return -430.0 + 9430.0 * unit(rng);
  if (kind < 7) return std::pow(10.0, std::log10(4e7) * unit(rng));     // 1 m .. 4e7 m
  if (kind < 9) return -std::pow(10.0, std::log10(430.0) * unit(rng));  // -1 m .. -430 m
  static const double extremes[] = {-430.0, 4e7, 0.0, -0.0, 1e-9, -1e-9, 8848.0};
  return pick(rng, extremes);
}

bool isFinite(const Cartographic& c) {
  return std::isfinite(c.longitudeRadians) && std::isfinite(c.latitudeRadians) &&
         std::isfinite(c.heightMeters);
}

void geodeticRoundTrip(const Ellipsoid& ellipsoid, const char* name, uint64_t seed) {
  const stress::Stopwatch stopwatch;
  const uint64_t count = stress::stressCount(stress::kStressPoints);
  std::mt19937_64 rng(seed);
  double maxPositionError = 0.0;
  double maxHeightError = 0.0;
  uint64_t poles = 0;
  for (uint64_t i = 0; i < count; ++i) {
    const Cartographic in{randomLongitude(rng), randomLatitude(rng), randomHeight(rng)};
    poles += std::abs(in.latitudeRadians) == kHalfPi;
    const glm::dvec3 p = cartographicToEcef(ellipsoid, in);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
        << in.longitudeRadians << " " << in.latitudeRadians << " " << in.heightMeters;
    const std::optional<Cartographic> out = ecefToCartographic(ellipsoid, p);
    ASSERT_TRUE(out.has_value()) << in.longitudeRadians << " " << in.latitudeRadians << " "
                                 << in.heightMeters;
    ASSERT_TRUE(isFinite(*out));
    ASSERT_LE(std::abs(out->longitudeRadians), std::numbers::pi);
    ASSERT_LE(std::abs(out->latitudeRadians), kHalfPi);
    const double positionError = glm::distance(cartographicToEcef(ellipsoid, *out), p);
    const double heightError = std::abs(out->heightMeters - in.heightMeters);
    if (!(positionError <= kRoundTripToleranceMeters && heightError <= kRoundTripToleranceMeters)) {
      FAIL() << name << " lon " << in.longitudeRadians << " lat " << in.latitudeRadians << " h "
             << in.heightMeters << ": position error " << positionError << " m, height error "
             << heightError << " m";
    }
    maxPositionError = std::max(maxPositionError, positionError);
    maxHeightError = std::max(maxHeightError, heightError);
  }
  char summary[200];
  std::snprintf(summary, sizeof summary,
                "%llu points (%llu at an exact pole): max position error %.3g m, max height "
                "error %.3g m, %s",
                static_cast<unsigned long long>(count), static_cast<unsigned long long>(poles),
                maxPositionError, maxHeightError, stopwatch.elapsed().c_str());
  stress::reportStress(std::string(name) + " geodetic round trip", summary);
  EXPECT_GT(poles, count / 200);
}

TEST(StressGeodesy, GeodeticRoundTripWgs84) { geodeticRoundTrip(Ellipsoid::wgs84(), "wgs84", 101); }
TEST(StressGeodesy, GeodeticRoundTripSphere) {
  geodeticRoundTrip(Ellipsoid::sphere(), "sphere", 102);
}

// Near the evolute of the meridian ellipse (the astroid (p / e^2 a)^(2/3) + (z / c)^(2/3) = 1,
// c = (a^2 - b^2) / b; its cusp p = e^2 a is ~42.7 km out on WGS84), where the latitude
// iteration converges slowest: relative offsets down to 1e-12, both sides.
glm::dvec3 nearEvolute(std::mt19937_64& rng, const Ellipsoid& ellipsoid) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  const double t = unit(rng) * kHalfPi;
  const double scale = 1.0 + (unit(rng) - 0.5) * std::pow(10.0, -12.0 * unit(rng));
  const double p = ellipsoid.eccentricitySquared() * a * std::pow(std::cos(t), 3) * scale;
  const double z = (a * a - b * b) / b * std::pow(std::sin(t), 3) * scale;
  const double longitude = 2.0 * std::numbers::pi * unit(rng);
  return {p * std::cos(longitude), p * std::sin(longitude), (rng() & 1) ? z : -z};
}

// A random ECEF position: uniform directions and the axes and planes where a coordinate is
// exactly (+-)0; radii near the surface, log-uniform from 1e-12 m to 1e8 m, within 5 km of the
// centre, and the geocentre itself; and points near the evolute.
glm::dvec3 randomEcef(std::mt19937_64& rng, const Ellipsoid& ellipsoid) {
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // (On a sphere the evolute is the centre itself.)
  if (!ellipsoid.isSphere() && rng() % 16 == 0) return nearEvolute(rng, ellipsoid);
  glm::dvec3 direction{gauss(rng), gauss(rng), gauss(rng)};
  switch (rng() % 8) {
    case 0:  // an axis, either sign of zero elsewhere
      direction = {0.0, 0.0, 0.0};
      direction[static_cast<int>(rng() % 3)] = (rng() & 1) ? 1.0 : -1.0;
      if (rng() & 1) direction.y = -0.0;
      break;
    case 1:  // the equator plane
      direction.z = (rng() & 1) ? 0.0 : -0.0;
      break;
    case 2:  // the 180 deg meridian plane, y = +-0
      direction.y = (rng() & 1) ? 0.0 : -0.0;
      direction.x = -std::abs(direction.x);
      break;
    case 3:  // a hair off the polar axis
      direction = {std::pow(10.0, -300.0 * unit(rng)) * gauss(rng),
                   std::pow(10.0, -300.0 * unit(rng)) * gauss(rng), (rng() & 1) ? 1.0 : -1.0};
      break;
    default:
      break;
  }
  const double length = glm::length(direction);
  if (!(length > 0.0)) return {0.0, 0.0, 0.0};
  direction /= length;
  double radius = 0.0;
  switch (rng() % 10) {
    case 0:
    case 1:
    case 2:
    case 3:
    case 4:
    case 5:  // -430 m .. 9 km around the ellipsoid
      radius = ellipsoid.semiMinorAxisMeters - 430.0 +
               (ellipsoid.semiMajorAxisMeters - ellipsoid.semiMinorAxisMeters + 9430.0) * unit(rng);
      break;
    case 6:
    case 7:
      radius = std::pow(10.0, -12.0 + 20.0 * unit(rng));
      break;
    case 8:
      radius = 5000.0 * unit(rng);
      break;
    default: {
      static const double fixed[] = {0.0,
                                     kGeocentreThresholdMeters,
                                     std::nextafter(kGeocentreThresholdMeters, 1.0),
                                     2.0 * kGeocentreThresholdMeters,
                                     1.0,
                                     ellipsoid.semiMinorAxisMeters + 4e7,
                                     ellipsoid.semiMajorAxisMeters + 4e7};
      radius = pick(rng, fixed);
    }
  }
  return direction * radius;
}

// Largest ECEF round-trip error in three regions.
struct EcefErrors {
  double interiorMeters = 0.0;  // below -430 m (deep inside, down to the geocentre)
  double nearSurfaceMeters = 0.0;
  double aboveMeters = 0.0;  // above 9 km
  uint64_t undefined = 0;
  uint64_t defined = 0;
};

void ecefRoundTrip(const Ellipsoid& ellipsoid, const char* name, uint64_t seed) {
  const stress::Stopwatch stopwatch;
  const uint64_t count = stress::stressCount(stress::kStressPoints);
  std::mt19937_64 rng(seed);
  EcefErrors errors;
  for (uint64_t i = 0; i < count; ++i) {
    const glm::dvec3 p = randomEcef(rng, ellipsoid);
    const double radius = glm::length(p);
    const std::optional<Cartographic> c = ecefToCartographic(ellipsoid, p);
    const glm::dvec3 up = geodeticSurfaceNormal(ellipsoid, p);
    ASSERT_NEAR(glm::length(up), 1.0, 1e-15) << p.x << " " << p.y << " " << p.z;
    if (!c) {
      // Only the geocentre (within the threshold, with rounding of |p|) is undefined.
      ASSERT_LT(radius, 2.0 * kGeocentreThresholdMeters) << p.x << " " << p.y << " " << p.z;
      ASSERT_EQ(up, glm::dvec3(0.0, 0.0, 1.0));
      ++errors.undefined;
      continue;
    }
    ++errors.defined;
    ASSERT_TRUE(isFinite(*c)) << p.x << " " << p.y << " " << p.z;
    ASSERT_LE(std::abs(c->longitudeRadians), std::numbers::pi);
    ASSERT_LE(std::abs(c->latitudeRadians), kHalfPi);
    const double error = glm::distance(cartographicToEcef(ellipsoid, *c), p);
    ASSERT_LE(error, kRoundTripToleranceMeters)
        << name << " " << p.x << " " << p.y << " " << p.z << " (radius " << radius << " m) -> lon "
        << c->longitudeRadians << " lat " << c->latitudeRadians << " h " << c->heightMeters;
    double& region = c->heightMeters < -430.0  ? errors.interiorMeters
                     : c->heightMeters <= 9000 ? errors.nearSurfaceMeters
                                               : errors.aboveMeters;
    region = std::max(region, error);
  }
  char summary[240];
  std::snprintf(summary, sizeof summary,
                "%llu points (%llu undefined at the geocentre): max position error %.3g m deep "
                "inside, %.3g m at -430 m..9 km, %.3g m above, %s",
                static_cast<unsigned long long>(count),
                static_cast<unsigned long long>(errors.undefined), errors.interiorMeters,
                errors.nearSurfaceMeters, errors.aboveMeters, stopwatch.elapsed().c_str());
  stress::reportStress(std::string(name) + " ECEF round trip", summary);
  EXPECT_GT(errors.undefined, 0u);
  EXPECT_GT(errors.defined, count * 8 / 10);
}

TEST(StressGeodesy, EcefRoundTripWgs84) { ecefRoundTrip(Ellipsoid::wgs84(), "wgs84", 103); }
TEST(StressGeodesy, EcefRoundTripSphere) { ecefRoundTrip(Ellipsoid::sphere(), "sphere", 104); }

}  // namespace
}  // namespace globe::geo
