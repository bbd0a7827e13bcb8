// Tests for terrain/screen_space_error.hpp: the geometric error model, the screen-space error
// formula and the distance lower bound (checked against dense sampling of real regions).
#include "terrain/screen_space_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/terrain/selection_test_support.hpp"

namespace globe::terrain {
namespace {

TEST(GeometricError, IsAQuarterOfTheEquatorialVertexSpacing) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  // 0.25 x 6378137 m x (pi / 16) at level 0 with 17 vertices per side.
  EXPECT_NEAR(geometricErrorMeters(0, 17, wgs84), 313086.0, 0.5);
  EXPECT_NEAR(geometricErrorMeters(14, 17, wgs84), 19.109, 1e-3);
  for (uint32_t level = 0; level < 30; ++level) {
    EXPECT_DOUBLE_EQ(geometricErrorMeters(level + 1, 17, wgs84),
                     geometricErrorMeters(level, 17, wgs84) / 2.0);
  }
  EXPECT_DOUBLE_EQ(geometricErrorMeters(3, 65, wgs84), geometricErrorMeters(3, 17, wgs84) / 4.0);
  EXPECT_DOUBLE_EQ(geometricErrorMeters(0, 17, geo::Ellipsoid::sphere()),
                   0.25 * 6371000.0 * std::numbers::pi / 16.0);
  // Degenerate block sizes do not divide by zero.
  EXPECT_TRUE(std::isfinite(geometricErrorMeters(0, 1, wgs84)));
  EXPECT_TRUE(std::isfinite(geometricErrorMeters(0, 0, wgs84)));
}

TEST(GeometricError, AMeasuredErrorLowersItOnlyAsFarAsTheViewingAngleAllows) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const double nominal = geometricErrorMeters(7, 17, wgs84);  // ~2.4 km
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double unknown : {nan, -1.0, inf}) {
    EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, unknown, 0.0), nominal) << unknown;
  }
  // Seen from straight above (or not said): the nominal, whatever was measured.
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 0.0, 1.0), nominal);
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 0.0), nominal);
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 0.0, nan), nominal);
  // Edge-on: the measured error plus the chord's sag below the curved surface (spacing ~9.8 km:
  // ~1.9 m), down to the floor.
  const double spacing = nominal / kTerrainQuality;
  const double sag = spacing * spacing / (8 * wgs84.semiMajorAxisMeters);
  EXPECT_NEAR(sag, 1.9, 0.1);
  EXPECT_NEAR(tileGeometricErrorMeters(7, 17, wgs84, 1500.0, 0.0), 1500.0 + sag, 1e-9);
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 0.0, 0.0), kMeasuredErrorFloor * nominal);
  // In between: the nominal times the cosine, or the measured error if larger.
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 0.0, 0.5), 0.5 * nominal);
  EXPECT_NEAR(tileGeometricErrorMeters(7, 17, wgs84, 1500.0, 0.5), 1500.0 + sag, 1e-9);
  // Coarse levels keep the nominal.
  EXPECT_EQ(tileGeometricErrorMeters(5, 17, wgs84, 0.0, 0.0), geometricErrorMeters(5, 17, wgs84));
  // Rougher than the nominal: the nominal stays (never refines more than before).
  EXPECT_EQ(tileGeometricErrorMeters(7, 17, wgs84, 5000.0, 0.0), nominal);
}

TEST(GeometricError, FaceOnIsTheLargestCosineToTheCamera) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const glm::dvec3 ground =
      geo::cartographicToEcef(wgs84, geo::Cartographic::fromDegrees(10, 45, 0));
  const glm::dvec3 up = geo::geodeticSurfaceNormal(wgs84, ground);
  EXPECT_NEAR(faceOnFraction(ground + 1000.0 * up, {ground}, wgs84), 1.0, 1e-12);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
  const glm::dvec3 grazing = ground + 1000.0 * east + 100.0 * up;  // ~5.7° above the horizon
  EXPECT_NEAR(faceOnFraction(grazing, {ground}, wgs84), 100.0 / std::hypot(1000.0, 100.0), 1e-9);
  EXPECT_EQ(faceOnFraction(ground - 1000.0 * up, {ground}, wgs84), 0.0);  // from below: 0
  EXPECT_EQ(faceOnFraction(ground, {ground}, wgs84), 1.0);                // on it: as if above
  EXPECT_NEAR(faceOnFraction(grazing, {ground, grazing - 50.0 * up}, wgs84), 1.0, 1e-6);
}

TEST(ScreenSpaceError, ProjectsTheErrorOntoTheViewport) {
  SelectionView view;
  view.viewportHeightPixels = 1080.0;
  view.fovYRadians = std::numbers::pi / 3.0;
  // 100 m at 1 km with a 60 degree fov over 1080 px: 100 x 1080 / (2 x 1000 x tan 30).
  EXPECT_NEAR(screenSpaceErrorPixels(100.0, 1000.0, view), 93.5307, 1e-4);
  EXPECT_DOUBLE_EQ(screenSpaceErrorPixels(100.0, 2000.0, view),
                   screenSpaceErrorPixels(100.0, 1000.0, view) / 2.0);
  view.viewportHeightPixels = 540.0;
  EXPECT_NEAR(screenSpaceErrorPixels(100.0, 1000.0, view), 93.5307 / 2.0, 1e-4);
  // Inside or touching a region: clamped to the minimum distance, never infinite or NaN.
  const double atMinimum = screenSpaceErrorPixels(100.0, kMinimumDistanceMeters, view);
  EXPECT_DOUBLE_EQ(screenSpaceErrorPixels(100.0, 0.0, view), atMinimum);
  EXPECT_DOUBLE_EQ(screenSpaceErrorPixels(100.0, -5.0, view), atMinimum);
  EXPECT_DOUBLE_EQ(screenSpaceErrorPixels(100.0, std::numeric_limits<double>::quiet_NaN(), view),
                   atMinimum);
  EXPECT_TRUE(std::isfinite(atMinimum));
  EXPECT_EQ(screenSpaceErrorPixels(0.0, 0.0, view), 0.0);
}

// A camera straight above a flat tile at height H sees it at distance H - (tile height).
TEST(DistanceLowerBound, IsTheHeightAboveATileBelow) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const geo::TileId tile{12, 6400, 1300};
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const geo::RegionVolume volume = geo::RegionVolume::fromRegion({rect, 100.0, 250.0}, wgs84);
  const geo::Cartographic centre = rect.center();
  for (const double height : {300.0, 1000.0, 5000.0}) {
    const glm::dvec3 camera =
        geo::cartographicToEcef(wgs84, {centre.longitudeRadians, centre.latitudeRadians, height});
    EXPECT_NEAR(distanceLowerBoundMeters(camera, height, volume), height - 250.0, 1e-6);
  }
  // Inside the region: 0.
  const glm::dvec3 inside =
      geo::cartographicToEcef(wgs84, {centre.longitudeRadians, centre.latitudeRadians, 200.0});
  EXPECT_EQ(distanceLowerBoundMeters(inside, 200.0, volume), 0.0);
  // An unbounded (invalid) region may be anywhere.
  const geo::RegionVolume invalid = geo::RegionVolume::fromRegion({rect, 10.0, -10.0}, wgs84);
  EXPECT_EQ(distanceLowerBoundMeters(inside * 2.0, 1e7, invalid), 0.0);
}

// Never more than the true distance (approached from above by dense samples), and close to it
// for a tile small against its distance.
TEST(DistanceLowerBound, NeverExceedsTheSampledDistanceAndIsTightFarAway) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  std::mt19937_64 rng(20240611);
  std::uniform_int_distribution<uint32_t> levels(0, 16);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tightChecks = 0;
  double worstTightness = 1.0;
  for (int i = 0; i < 3000; ++i) {
    const uint32_t level = levels(rng);
    const geo::TileId tile{
        level, static_cast<uint32_t>(unit(rng) * geo::GeographicTilingScheme::tilesX(level)),
        static_cast<uint32_t>(unit(rng) * geo::GeographicTilingScheme::tilesY(level))};
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const auto low = static_cast<int16_t>(-8000 + unit(rng) * 12000);
    const auto high = static_cast<int16_t>(low + (unit(rng) < 0.2 ? 0.0 : unit(rng) * 5000));
    const HeightRange range{low, high};
    const geo::RegionVolume volume = geo::RegionVolume::fromRegion(
        {rect, static_cast<double>(low), static_cast<double>(high)}, wgs84);
    // Cameras near the tile (within a few tile sizes) or anywhere, low or high.
    const double spread = unit(rng) < 0.5 ? 4.0 : 1e3;
    const double lon =
        std::clamp(rect.westRadians + (unit(rng) * 2 - 0.5) * spread * rect.widthRadians(),
                   -std::numbers::pi, std::numbers::pi);
    const double lat =
        std::clamp(rect.southRadians + (unit(rng) * 2 - 0.5) * spread * rect.heightRadians(),
                   -std::numbers::pi / 2, std::numbers::pi / 2);
    const double height = std::pow(10.0, unit(rng) * 7.5) - 100.0;
    const glm::dvec3 camera = geo::cartographicToEcef(wgs84, {lon, lat, height});
    const double bound = distanceLowerBoundMeters(camera, height, volume);
    const double sampled = testing::sampledDistanceMeters(camera, tile, range, wgs84);
    ASSERT_LE(bound, sampled * (1 + 1e-12) + 1e-6)
        << "tile " << level << "/" << tile.x << "/" << tile.y << " camera height " << height;
    ASSERT_GE(bound, 0.0);
    const double size =
        glm::length(volume.pointsEcefMeters.front() - volume.pointsEcefMeters.back());
    if (level >= 6 && sampled > 8.0 * size) {
      ++tightChecks;
      worstTightness = std::min(worstTightness, bound / sampled);
      EXPECT_GT(bound, 0.8 * sampled) << "tile " << level << "/" << tile.x << "/" << tile.y;
    }
  }
  EXPECT_GT(tightChecks, 300);
  std::printf("distance bound: worst bound/sampled %.3f over %d far small tiles\n", worstTightness,
              tightChecks);
}

}  // namespace
}  // namespace globe::terrain
