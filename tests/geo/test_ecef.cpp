// Tests for geo/ecef.hpp: known positions, the million-point round trip on both models, the
// undefined cases and surface normals.
#include "geo/ecef.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace globe::geo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Ecef, KnownPositionsWgs84) {
  const Ellipsoid e = Ellipsoid::wgs84();
  const glm::dvec3 origin = cartographicToEcef(e, Cartographic::fromDegrees(0, 0));
  EXPECT_EQ(origin, glm::dvec3(6378137.0, 0.0, 0.0));
  const glm::dvec3 east = cartographicToEcef(e, Cartographic::fromDegrees(90, 0, 1000));
  EXPECT_NEAR(east.x, 0.0, 1e-9);
  EXPECT_EQ(east.y, 6379137.0);
  EXPECT_EQ(east.z, 0.0);
  const glm::dvec3 north = cartographicToEcef(e, Cartographic::fromDegrees(0, 90, 10));
  EXPECT_NEAR(north.x, 0.0, 1e-9);
  EXPECT_NEAR(north.z, e.semiMinorAxisMeters + 10.0, 1e-8);
  const glm::dvec3 south = cartographicToEcef(e, Cartographic::fromDegrees(0, -90));
  EXPECT_NEAR(south.z, -e.semiMinorAxisMeters, 1e-8);
  // Reference values computed independently with 40-digit arithmetic (mpmath).
  struct Reference {
    Cartographic cartographic;
    glm::dvec3 ecef;
  };
  for (const Reference& r :
       {Reference{Cartographic::fromDegrees(45, 45),
                  {3194419.1450605740, 3194419.1450605740, 4487348.4088659198}},
        Reference{Cartographic::fromDegrees(151.2093, -33.8688, 58),
                  {-4646093.4772883031, 2553229.5358170704, -3534404.7109103693}},
        Reference{Cartographic::fromDegrees(-70.5, 89.9, 35786000),
                  {24577.435653342911, -69404.537236499584, 42142688.061928228}}}) {
    EXPECT_LT(glm::distance(cartographicToEcef(e, r.cartographic), r.ecef), 1e-8);
    const std::optional<Cartographic> c = ecefToCartographic(e, r.ecef);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->longitudeRadians, r.cartographic.longitudeRadians, 1e-15);
    EXPECT_NEAR(c->latitudeRadians, r.cartographic.latitudeRadians, 1e-15);
    EXPECT_NEAR(c->heightMeters, r.cartographic.heightMeters, 1e-8);
  }
}

TEST(Ecef, KnownPositionsSphere) {
  const Ellipsoid s = Ellipsoid::sphere();
  const glm::dvec3 p = cartographicToEcef(s, Cartographic::fromDegrees(-90, 30, 29000));
  EXPECT_NEAR(p.x, 0.0, 1e-9);
  EXPECT_NEAR(p.y, -6400000.0 * std::sqrt(3.0) / 2.0, 1e-8);
  EXPECT_NEAR(p.z, 3200000.0, 1e-8);
  const std::optional<Cartographic> c = ecefToCartographic(s, {0.0, 0.0, -7000000.0});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->latitudeRadians, -std::numbers::pi / 2.0);
  EXPECT_EQ(c->heightMeters, 629000.0);
}

TEST(Ecef, ExactPolesAreHandledExplicitly) {
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    const double b = e.semiMinorAxisMeters;
    for (const double h : {-11000.0, 0.0, 1.5, 4e7}) {
      const std::optional<Cartographic> north = ecefToCartographic(e, {0.0, 0.0, b + h});
      ASSERT_TRUE(north);
      EXPECT_EQ(north->latitudeRadians, std::numbers::pi / 2.0);
      EXPECT_EQ(north->longitudeRadians, 0.0);
      EXPECT_NEAR(north->heightMeters, h, 1e-8);
      const std::optional<Cartographic> south = ecefToCartographic(e, {-0.0, 0.0, -(b + h)});
      ASSERT_TRUE(south);
      EXPECT_EQ(south->latitudeRadians, -std::numbers::pi / 2.0);
      EXPECT_NEAR(south->heightMeters, h, 1e-8);
    }
  }
}

TEST(Ecef, UndefinedInputsGiveNullopt) {
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    EXPECT_EQ(ecefToCartographic(e, {0.0, 0.0, 0.0}), std::nullopt) << "geocentre";
    EXPECT_EQ(ecefToCartographic(e, {-0.0, 0.0, -0.0}), std::nullopt);
    EXPECT_EQ(ecefToCartographic(e, {1e-10, -1e-10, 1e-10}), std::nullopt);
    EXPECT_EQ(ecefToCartographic(e, {1e-300, 0.0, 0.0}), std::nullopt);
    for (const double bad : {kNaN, kInf, -kInf}) {
      EXPECT_EQ(ecefToCartographic(e, {bad, 1.0e6, 1.0e6}), std::nullopt);
      EXPECT_EQ(ecefToCartographic(e, {1.0e6, bad, 1.0e6}), std::nullopt);
      EXPECT_EQ(ecefToCartographic(e, {1.0e6, 1.0e6, bad}), std::nullopt);
    }
  }
}

// Never NaN: anything that is not nullopt is a valid cartographic, down to just outside the
// geocentre threshold, inside the evolute and up to overflow.
TEST(Ecef, RobustEverywhere) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(-8.9, 308.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    for (int i = 0; i < 200000; ++i) {
      const glm::dvec3 direction{unit(rng), unit(rng), i % 7 == 0 ? 0.0 : unit(rng)};
      const glm::dvec3 p = direction * std::pow(10.0, exponent(rng));
      const std::optional<Cartographic> c = ecefToCartographic(e, p);
      if (!c) {
        const double r = std::hypot(std::hypot(p.x, p.y), p.z);
        ASSERT_TRUE(r < 2e-9 || r > 1e306) << p.x << " " << p.y << " " << p.z;
        continue;
      }
      ASSERT_TRUE(std::isfinite(c->longitudeRadians) && std::isfinite(c->latitudeRadians) &&
                  std::isfinite(c->heightMeters));
      ASSERT_LE(std::abs(c->longitudeRadians), std::numbers::pi);
      ASSERT_LE(std::abs(c->latitudeRadians), std::numbers::pi / 2.0);
      // Far away the geodetic latitude tends to the geocentric one and the height to |p| - a.
      const double r = std::hypot(std::hypot(p.x, p.y), p.z);
      if (r > 1e12) {
        ASSERT_NEAR(c->latitudeRadians, std::atan2(p.z, std::hypot(p.x, p.y)), 1e-7) << r;
        ASSERT_NEAR(c->heightMeters / r, 1.0, 1e-5) << r;
      }
    }
    // Near the centre, on and off the equator plane and the axis.
    for (const glm::dvec3 p : {glm::dvec3{1e-6, 0, 0}, glm::dvec3{0, 0, 1e-6},
                               glm::dvec3{1000, 0, 0}, glm::dvec3{3e4, 1e4, 1e-3},
                               glm::dvec3{1e-9, 1e-9, 1e-9}, glm::dvec3{1e300, 1e300, 1e300}}) {
      const std::optional<Cartographic> c = ecefToCartographic(e, p);
      ASSERT_TRUE(c);
      EXPECT_TRUE(std::isfinite(c->latitudeRadians) && std::isfinite(c->heightMeters));
    }
  }
}

// Latitudes and longitudes that are exactly on, or one ulp next to, the hard places.
double specialLatitude(std::mt19937_64& rng) {
  static const double values[] = {std::numbers::pi / 2.0,
                                  -std::numbers::pi / 2.0,
                                  std::nextafter(std::numbers::pi / 2.0, 0.0),
                                  std::nextafter(-std::numbers::pi / 2.0, 0.0),
                                  std::numbers::pi / 2.0 - 1e-9,
                                  0.0,
                                  -0.0,
                                  std::nextafter(0.0, 1.0),
                                  1e-300,
                                  -1e-12,
                                  std::nextafter(std::numbers::pi / 4.0, 1.0)};
  return values[std::uniform_int_distribution<size_t>(0, std::size(values) - 1)(rng)];
}
double specialLongitude(std::mt19937_64& rng) {
  static const double values[] = {std::numbers::pi,
                                  -std::numbers::pi,
                                  std::nextafter(std::numbers::pi, 0.0),
                                  std::nextafter(-std::numbers::pi, 0.0),
                                  0.0,
                                  -0.0,
                                  std::numbers::pi / 2.0,
                                  -std::numbers::pi / 2.0,
                                  1e-300};
  return values[std::uniform_int_distribution<size_t>(0, std::size(values) - 1)(rng)];
}

struct RoundTripErrors {
  double position = 0.0;
  double height = 0.0;
  int count = 0;
};

RoundTripErrors roundTrip(const Ellipsoid& e, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> longitude(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> latitude(-std::numbers::pi / 2.0, std::numbers::pi / 2.0);
  std::uniform_real_distribution<double> uniformHeight(-11000.0, 4e7);
  std::uniform_real_distribution<double> logHeight(-9.0, std::log10(4e7));
  RoundTripErrors errors;
  for (int i = 0; i < count; ++i) {
    const double lon = unit(rng) < 0.1 ? specialLongitude(rng) : longitude(rng);
    const double lat = unit(rng) < 0.1 ? specialLatitude(rng) : latitude(rng);
    double h = 0.0;
    const double kind = unit(rng);
    if (kind < 0.5) {
      h = uniformHeight(rng);
    } else if (kind < 0.9) {  // log-spaced small heights, both signs (negative down to -11 km)
      h = std::pow(10.0, logHeight(rng));
      if (unit(rng) < 0.5) h = -std::min(h, 11000.0);
    } else {
      const double fixed[] = {0.0, -11000.0, 4e7, 1e-9, -1e-9};
      h = fixed[i % 5];
    }
    const glm::dvec3 p1 = cartographicToEcef(e, {lon, lat, h});
    const std::optional<Cartographic> c = ecefToCartographic(e, p1);
    if (!c) {
      ADD_FAILURE() << "nullopt for " << lon << " " << lat << " " << h;
      return errors;
    }
    const glm::dvec3 p2 = cartographicToEcef(e, *c);
    errors.position = std::max(errors.position, glm::distance(p1, p2));
    errors.height = std::max(errors.height, std::abs(c->heightMeters - h));
    ++errors.count;
  }
  return errors;
}

void checkRoundTrip(const Ellipsoid& e, const char* name, uint64_t seed) {
  const RoundTripErrors errors = roundTrip(e, 1000000, seed);
  std::cout << "[ " << name << " round trip ] " << errors.count << " points: max position error "
            << errors.position << " m, max height error " << errors.height << " m\n";
  ::testing::Test::RecordProperty("max_position_error_m", std::to_string(errors.position));
  ::testing::Test::RecordProperty("max_height_error_m", std::to_string(errors.height));
  EXPECT_EQ(errors.count, 1000000);
  EXPECT_LT(errors.position, 1e-6);
  EXPECT_LT(errors.height, 1e-6);
}

TEST(Ecef, RoundTripMillionPointsWgs84) { checkRoundTrip(Ellipsoid::wgs84(), "wgs84", 1); }
TEST(Ecef, RoundTripMillionPointsSphere) { checkRoundTrip(Ellipsoid::sphere(), "sphere", 2); }

TEST(Ecef, SurfaceNormalFromCartographic) {
  const Ellipsoid e = Ellipsoid::wgs84();
  const glm::dvec3 equator = geodeticSurfaceNormal(e, Cartographic::fromDegrees(90, 0));
  EXPECT_NEAR(equator.x, 0.0, 1e-15);
  EXPECT_NEAR(equator.y, 1.0, 1e-15);
  EXPECT_NEAR(equator.z, 0.0, 1e-15);
  const glm::dvec3 pole = geodeticSurfaceNormal(e, Cartographic::fromDegrees(10, 90));
  EXPECT_NEAR(pole.z, 1.0, 1e-15);
  // Perpendicular to the surface: orthogonal to small steps along the meridian and parallel.
  const Cartographic c = Cartographic::fromDegrees(30, 50);
  const glm::dvec3 n = geodeticSurfaceNormal(e, c);
  EXPECT_NEAR(glm::length(n), 1.0, 1e-15);
  const glm::dvec3 p = cartographicToEcef(e, c);
  const glm::dvec3 northStep =
      cartographicToEcef(e, {c.longitudeRadians, c.latitudeRadians + 1e-7, 0.0}) - p;
  const glm::dvec3 eastStep =
      cartographicToEcef(e, {c.longitudeRadians + 1e-7, c.latitudeRadians, 0.0}) - p;
  EXPECT_NEAR(glm::dot(n, glm::normalize(northStep)), 0.0, 1e-7);
  EXPECT_NEAR(glm::dot(n, glm::normalize(eastStep)), 0.0, 1e-7);
}

TEST(Ecef, SurfaceNormalFromEcefAtAnyHeight) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> longitude(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> latitude(-std::numbers::pi / 2.0, std::numbers::pi / 2.0);
  std::uniform_real_distribution<double> height(-11000.0, 4e7);
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    for (int i = 0; i < 10000; ++i) {
      const Cartographic c{longitude(rng), latitude(rng), height(rng)};
      const glm::dvec3 expected = geodeticSurfaceNormal(e, c);
      const glm::dvec3 actual = geodeticSurfaceNormal(e, cartographicToEcef(e, c));
      ASSERT_NEAR(glm::length(actual), 1.0, 1e-15);
      ASSERT_LT(glm::distance(actual, expected), 1e-12);
    }
    EXPECT_EQ(geodeticSurfaceNormal(e, glm::dvec3{0.0}), glm::dvec3(0, 0, 1));
    EXPECT_EQ(geodeticSurfaceNormal(e, glm::dvec3{kNaN, 0, 0}), glm::dvec3(0, 0, 1));
  }
}

// The frame's normal comes from the iteration (no trigonometry): it must be the normal at the
// returned coordinates, and the coordinates exactly ecefToCartographic's, everywhere including the
// polar axis, the equator, deep inside and far out; undefined where the conversion is.
TEST(Ecef, GeodeticFrameIsTheConversionAndItsNormal) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> longitude(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> latitude(-std::numbers::pi / 2.0, std::numbers::pi / 2.0);
  std::uniform_real_distribution<double> height(-6000e3, 4e7);
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
      Cartographic c{longitude(rng), latitude(rng), height(rng)};
      if (i % 10 == 0)
        c.latitudeRadians = (i % 20 == 0) ? 0.0 : std::numbers::pi / 2.0;  // equator, pole
      const glm::dvec3 ecef = cartographicToEcef(e, c);
      const auto frame = ecefToGeodeticFrame(e, ecef);
      const auto plain = ecefToCartographic(e, ecef);
      ASSERT_TRUE(frame && plain);
      ASSERT_EQ(frame->cartographic.longitudeRadians, plain->longitudeRadians);
      ASSERT_EQ(frame->cartographic.latitudeRadians, plain->latitudeRadians);
      ASSERT_EQ(frame->cartographic.heightMeters, plain->heightMeters);
      const glm::dvec3 expected = geodeticSurfaceNormal(e, frame->cartographic);
      worst = std::max(worst, glm::distance(frame->normal, expected));
      ASSERT_LT(glm::distance(frame->normal, expected), 1e-15) << i;
    }
    std::cout << "[ frame normal ] worst distance to geodeticSurfaceNormal: " << worst << "\n";
    // Exactly on the polar axis.
    EXPECT_EQ(ecefToGeodeticFrame(e, {0.0, 0.0, 7e6})->normal, glm::dvec3(0, 0, 1));
    EXPECT_EQ(ecefToGeodeticFrame(e, {0.0, 0.0, -7e6})->normal, glm::dvec3(0, 0, -1));
    EXPECT_FALSE(ecefToGeodeticFrame(e, glm::dvec3{0.0}));
    EXPECT_FALSE(ecefToGeodeticFrame(e, glm::dvec3{kNaN, 1.0, 1.0}));
    EXPECT_FALSE(ecefToGeodeticFrame(e, glm::dvec3{kInf, 1.0, 1.0}));
  }
}

}  // namespace
}  // namespace globe::geo
