// The Sun's position: the SPA paper's worked example (its intermediate values too), 400 instants
// of 1900-2100 against pvlib's implementation of SPA, and a table of our own: equinoxes and
// solstices (declination 0 and ±obliquity), the poles (elevation = declination), the date line,
// and the whole-globe light direction against each observer's elevation.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "sun/solar_position.hpp"
#include "sun/utc_time.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::sun {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

double timeOf(const std::string& text) {
  auto t = parseUtcTime(text);
  EXPECT_TRUE(t) << t.error();
  return t ? *t : 0;
}

// Reda and Andreas's example (NREL/TP-560-34302, table A5.1; ΔT 67 s, 820 mbar, 11 °C).
TEST(SolarPosition, ThePapersExample) {
  const Observer golden{-105.1786, 39.742476, 1830.14};
  const SolarPosition p = solarPosition(timeOf("2003-10-17T12:30:30-07:00"), golden, 67.0);
  EXPECT_NEAR(p.terms.julianDay, 2452930.312847, 1e-6);
  EXPECT_NEAR(p.terms.heliocentricLongitudeDegrees, 24.0182616917, 1e-9);
  EXPECT_NEAR(p.terms.heliocentricLatitudeDegrees, -0.0001011219, 1e-10);
  EXPECT_NEAR(p.terms.radiusAu, 0.9965422974, 1e-10);
  EXPECT_NEAR(p.terms.nutationLongitudeDegrees, -0.00399840, 1e-8);
  EXPECT_NEAR(p.terms.nutationObliquityDegrees, 0.00166657, 1e-8);
  EXPECT_NEAR(p.terms.obliquityDegrees, 23.440465, 1e-6);
  EXPECT_NEAR(p.hourAngleDegrees, 11.105902, 1e-6);
  const double zenith = 90 - (p.elevationDegrees + refractionDegrees(p.elevationDegrees, 820, 11));
  EXPECT_NEAR(zenith, 50.11162, 1e-5);
  EXPECT_NEAR(p.azimuthDegrees, 194.34024, 1e-5);
}

// tests/data/sun/spa_pvlib.csv: pvlib's SPA (solar_position_numpy, no refraction) at random
// instants of 1900-2100 and places, with the ΔT it was given (SOURCES.md there).
TEST(SolarPosition, WithinAHundredthOfADegreeOfSpaFrom1900To2100) {
  std::ifstream file(std::string(GLOBE_SOURCE_DIR) + "/tests/data/sun/spa_pvlib.csv");
  ASSERT_TRUE(file) << "tests/data/sun/spa_pvlib.csv";
  std::string line;
  std::getline(file, line);  // header
  size_t rows = 0;
  double worstDegrees = 0;
  while (std::getline(file, line)) {
    std::istringstream in(line);
    double t, lon, lat, height, deltaT, azimuth, elevation;
    char c;
    ASSERT_TRUE(in >> t >> c >> lon >> c >> lat >> c >> height >> c >> deltaT >> c >> azimuth >>
                c >> elevation)
        << line;
    const SolarPosition p = solarPosition(t, {lon, lat, height}, deltaT);
    // The angle between the two directions on the sky, so the azimuth near the zenith counts
    // for what it moves the Sun.
    const double cosine =
        std::sin(elevation * kDegree) * std::sin(p.elevationDegrees * kDegree) +
        std::cos(elevation * kDegree) * std::cos(p.elevationDegrees * kDegree) *
            std::cos((azimuth - p.azimuthDegrees) * kDegree);
    const double apart = std::acos(std::min(1.0, cosine)) / kDegree;
    worstDegrees = std::max(worstDegrees, apart);
    EXPECT_LT(apart, 0.01) << formatUtcTime(t) << " at " << lon << ", " << lat;
    ++rows;
  }
  EXPECT_EQ(rows, 400u);
  std::printf("worst of %zu against pvlib's SPA: %.2e degrees\n", rows, worstDegrees);
}

TEST(SolarPosition, SolsticesEquinoxesAndThePoles) {
  const struct {
    const char* time;  // of the solstice or equinox (USNO, to the minute)
    double declinationOverObliquity;
  } moments[] = {{"2024-03-20T03:06Z", 0},  {"2024-06-20T20:51Z", 1},
                 {"2024-09-22T12:44Z", 0},  {"2024-12-21T09:20Z", -1},
                 {"1950-06-21T17:36Z", 1},  {"2099-12-21T19:04Z", -1}};
  for (const auto& m : moments) {
    const double t = timeOf(m.time);
    const SolarPosition north = solarPosition(t, {0, 90, 0});
    const SolarPosition south = solarPosition(t, {123, -90, 0});
    const double declination = north.terms.declinationDegrees;
    // Within a minute of the moment: the declination moves 0.0066° a minute at an equinox.
    EXPECT_NEAR(declination, m.declinationOverObliquity * north.terms.obliquityDegrees, 0.007)
        << m.time;
    // At a pole the Sun's elevation is its declination (less 0.0024° of parallax at most).
    EXPECT_NEAR(north.elevationDegrees, declination, 0.003) << m.time;
    EXPECT_NEAR(south.elevationDegrees, -declination, 0.003) << m.time;
  }
}

TEST(SolarPosition, TheDateLineIsOneMeridian) {
  for (const char* time : {"2024-01-01T00:00Z", "2024-06-21T12:00Z", "1999-08-11T11:03Z"}) {
    const double t = timeOf(time);
    for (const double lat : {-60.0, -16.5, 0.0, 45.0, 89.0}) {
      const SolarPosition east = solarPosition(t, {180, lat, 0});
      const SolarPosition west = solarPosition(t, {-180, lat, 0});
      EXPECT_NEAR(east.elevationDegrees, west.elevationDegrees, 1e-9) << time << " " << lat;
      EXPECT_NEAR(std::remainder(east.azimuthDegrees - west.azimuthDegrees, 360), 0, 1e-9);
    }
  }
}

// The light's direction (one for the globe) against each observer's own elevation: they differ
// by the Sun's parallax only (≤ 0.0024°).
TEST(SolarPosition, TheGlobesLightAgreesWithEachObserver) {
  for (const char* time : {"2024-03-01T08:00Z", "2031-11-05T17:45Z", "1911-07-04T23:10Z"}) {
    const double t = timeOf(time);
    const glm::dvec3 sun = sunDirectionEcef(t);
    EXPECT_NEAR(glm::length(sun), 1.0, 1e-12);
    for (double lon = -180; lon < 180; lon += 37) {
      for (double lat = -85; lat <= 85; lat += 17) {
        // The geodetic up (WGS84's normal at lon, lat), the observer's horizon's.
        const glm::dvec3 up{std::cos(lat * kDegree) * std::cos(lon * kDegree),
                            std::cos(lat * kDegree) * std::sin(lon * kDegree),
                            std::sin(lat * kDegree)};
        const double fromLight = std::asin(glm::dot(up, sun)) / kDegree;
        EXPECT_NEAR(fromLight, solarPosition(t, {lon, lat, 0}).elevationDegrees, 0.003)
            << time << " at " << lon << ", " << lat;
      }
    }
  }
}

}  // namespace
}  // namespace globe::sun
