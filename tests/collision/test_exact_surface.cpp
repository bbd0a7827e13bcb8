// Tests for collision/exact_surface.hpp on synthetic tiles: vertices, the diagonal rule, the
// chord sag, pole quads, agreement with brute-force ray casting, and exactSurfaceTest.
#include "collision/exact_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "collision/grid_location.hpp"
#include "collision/qotcd_height.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/collision/mesh_ray_cast.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using globe::test::kN;
using testing::gridLatitude;
using testing::gridLongitude;
using testing::makeBlock;

int16_t hilly(uint32_t i, uint32_t j) {
  return static_cast<int16_t>(static_cast<int>((i * 7919 + j * 104729) % 4001) - 200);
}

TEST(ExactSurface, VerticesGiveTheirHeight) {
  const terrain::HeightBlock block = makeBlock(kN, hilly);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (const TileId& id :
         {TileId{0, 1, 0}, TileId{3, 5, 2}, TileId{9, 700, 100}, TileId{14, 25000, 5000}}) {
      const ArrayTile tile = makeArrayTile(id, block);
      for (uint32_t i = 1; i + 1 < kN; ++i) {  // pole rows (level 0) are tested separately
        for (uint32_t j = 0; j < kN; ++j) {
          const SurfaceSample s =
              exactTileSurfaceHeight(tile, ellipsoid, testing::meshVertexLongitude(id, kN, j),
                                     testing::meshVertexLatitude(id, kN, i));
          EXPECT_NEAR(s.heightMeters, block.surfaceHeightMetersAt(i, j), 1e-6) << i << " " << j;
        }
      }
    }
  }
}

TEST(ExactSurface, DiagonalRuleAndBruteForceRayCast) {
  // Random points on random tiles of several levels: away from the diagonal and the quad edges
  // the triangle is the one of the DIAGONAL RULE; everywhere, the height is the brute force's.
  const terrain::HeightBlock block = makeBlock(kN, hilly);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (uint32_t level : {2u, 5u, 8u, 12u}) {
      const TileId id{
          level, static_cast<uint32_t>(rng() % geo::GeographicTilingScheme::tilesX(level)),
          1 + static_cast<uint32_t>(rng() % (geo::GeographicTilingScheme::tilesY(level) - 2))};
      const ArrayTile tile = makeArrayTile(id, block);
      for (int k = 0; k < 200; ++k) {
        const double column = 16.0 * unit(rng), row = 16.0 * unit(rng);
        const double lon = gridLongitude(id, kN, column), lat = gridLatitude(id, kN, row);
        const SurfaceSample s = exactTileSurfaceHeight(tile, ellipsoid, lon, lat);
        const auto hit = testing::castOntoTileMesh(tile, ellipsoid, lon, lat);
        const double fu = column - std::floor(column), fv = row - std::floor(row);
        // Away from the diagonal and the quad edges: the grid-space choice (DIAGONAL RULE).
        const double margin = level <= 2 ? 0.05 : 0.01;
        if (std::abs(fu - fv) > margin && fu > margin && fv > margin && fu < 1 - margin &&
            fv < 1 - margin) {
          EXPECT_EQ(s.triangle, fv >= fu ? SurfaceTriangle::SouthWest : SurfaceTriangle::NorthEast);
          EXPECT_EQ(s.quadRow, static_cast<uint32_t>(row));
          EXPECT_EQ(s.quadColumn, static_cast<uint32_t>(column));
        }
        // Everywhere the ray hits this tile's mesh: the same height as the brute force.
        if (hit) {
          EXPECT_NEAR(s.heightMeters, hit->heightMeters, 1e-6)
              << level << " " << row << " " << column;
        }
        // Conservative: never above QOTCD's H.
        EXPECT_LE(s.heightMeters, qotcdTileHeight(tile, lon, lat).heightMeters + 1e-6);
      }
    }
  }
}

TEST(ExactSurface, FlatTerrainSagsBetweenVerticesLikeAChord) {
  // A flat block at 1000 m: the triangle planes are chords, below the curved surface.
  const terrain::HeightBlock flat = makeBlock(kN, [](uint32_t, uint32_t) { return int16_t{1000}; });
  const geo::Ellipsoid sphere = geo::Ellipsoid::sphere();
  const double r = sphere.semiMajorAxisMeters + 1000.0;
  for (uint32_t level : {1u, 4u, 8u, 12u}) {
    // The tile just south-east of (0, 0): its north edge is the equator.
    const TileId id{level, geo::GeographicTilingScheme::tilesX(level) / 2,
                    geo::GeographicTilingScheme::tilesY(level) / 2};
    const ArrayTile tile = makeArrayTile(id, flat);
    // Mid-point of the north-west edge of quad (0, 0) along the row at the equator: a chord of
    // angle c sags r (1 - cos(c/2)) below the arc; on the sphere the ray is radial.
    const double cell = std::numbers::pi / (geo::GeographicTilingScheme::tilesY(level) * 16.0);
    const SurfaceSample mid =
        exactTileSurfaceHeight(tile, sphere, gridLongitude(id, kN, 0.5), gridLatitude(id, kN, 0));
    const double chordSag = r * (1.0 - std::cos(cell / 2.0));
    EXPECT_NEAR(mid.heightMeters, 1000.0 - chordSag, 1e-6 + 1e-9 * chordSag) << level;
    const SurfaceSample centre =
        exactTileSurfaceHeight(tile, sphere, gridLongitude(id, kN, 8.5), gridLatitude(id, kN, 8.3));
    EXPECT_LT(centre.heightMeters, 1000.0);
  }
}

TEST(ExactSurface, PoleQuadsAndPolePoint) {
  // Level-2 tile touching the north pole; pole row equal (500 m) as in a pyramid.
  const TileId id{2, 3, 0};
  const terrain::HeightBlock block = makeBlock(kN, [](uint32_t i, uint32_t j) {
    return static_cast<int16_t>(i == 0 ? 500 : 300 + 10 * i + j);
  });
  const ArrayTile tile = makeArrayTile(id, block);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    // The pole itself, at any longitude (even outside the tile): the pole row's height.
    for (double lon : {0.0, -std::numbers::pi, 2.0}) {
      const SurfaceSample pole =
          exactTileSurfaceHeight(tile, ellipsoid, lon, std::numbers::pi / 2.0);
      EXPECT_EQ(pole.triangle, SurfaceTriangle::Pole);
      EXPECT_EQ(pole.heightMeters, 500.0);
    }
    // In the north-east half of a pole quad, collapsed to a segment: the south-west half's plane.
    const double lon = gridLongitude(id, kN, 5.7), lat = gridLatitude(id, kN, 0.2);
    const SurfaceSample s = exactTileSurfaceHeight(tile, ellipsoid, lon, lat);
    EXPECT_EQ(s.triangle, SurfaceTriangle::SouthWest);
    EXPECT_TRUE(std::isfinite(s.heightMeters));
    const auto hit = testing::castOntoTileMesh(tile, ellipsoid, lon, lat);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->quadRow, 0u);
    EXPECT_EQ(hit->quadColumn, 5u);
    EXPECT_NEAR(s.heightMeters, hit->heightMeters, 1e-6);
    EXPECT_LE(s.heightMeters, qotcdTileHeight(tile, lon, lat).heightMeters);
  }
  // Unequal pole rows (not from a pyramid): the highest pole vertex, for both H and E.
  const terrain::HeightBlock uneven = makeBlock(
      kN, [](uint32_t i, uint32_t j) { return static_cast<int16_t>(i == 0 ? 100 + j : 50); });
  const ArrayTile unevenTile = makeArrayTile(id, uneven);
  EXPECT_EQ(exactTileSurfaceHeight(unevenTile, geo::Ellipsoid::wgs84(), 1.0, std::numbers::pi / 2.0)
                .heightMeters,
            116.0);
  const TileHeight h = qotcdTileHeight(unevenTile, 1.0, std::numbers::pi / 2.0);
  EXPECT_EQ(h.heightMeters, 116.0);
  EXPECT_EQ(h.heightCase, HeightCase::Vertex);
}

// exactSurfaceTest keeps the last quad's corners per thread: a query over the same quad after
// the heights changed (a block rewritten in place, another ellipsoid, another tile id at the same
// address) must see the new surface, never the remembered one.
TEST(ExactSurface, RememberedQuadFollowsHeightsEllipsoidAndTile) {
  terrain::HeightBlock block = makeBlock(kN, hilly);
  const TileId id{8, 300, 90};
  RenderingTileArray array;
  array.assign({makeArrayTile(id, block)});
  const double lon = gridLongitude(id, kN, 6.4), lat = gridLatitude(id, kN, 9.1);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    const glm::dvec3 camera = geo::cartographicToEcef(ellipsoid, {lon, lat, 5000.0});
    const double before = exactSurfaceTest(array, ellipsoid, camera, 0.0).surfaceHeightMeters;
    EXPECT_NEAR(before, exactSurfaceHeight(array, ellipsoid, lon, lat)->heightMeters, 1e-6);
    for (int16_t& h : block.heights) h = static_cast<int16_t>(h + 300);
    const double after = exactSurfaceTest(array, ellipsoid, camera, 0.0).surfaceHeightMeters;
    // Raised vertices also spread apart a little: +300 m to ~1e-5 m, the uncached path exactly.
    EXPECT_NEAR(after, before + 300.0, 1e-4);
    EXPECT_NEAR(after, exactSurfaceHeight(array, ellipsoid, lon, lat)->heightMeters, 1e-6);
    for (int16_t& h : block.heights) h = static_cast<int16_t>(h - 300);
  }
  // The same block under a neighbouring id: the same grid position is another place.
  const TileId east{8, 301, 90};
  RenderingTileArray moved;
  moved.assign({makeArrayTile(east, block)});
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const double eastLon = gridLongitude(east, kN, 6.4);
  const glm::dvec3 camera = geo::cartographicToEcef(wgs84, {eastLon, lat, 5000.0});
  ASSERT_TRUE(
      exactSurfaceTest(array, wgs84, geo::cartographicToEcef(wgs84, {lon, lat, 5000.0}), 0.0)
          .found);
  const ExactSurfaceResult r = exactSurfaceTest(moved, wgs84, camera, 0.0);
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.surfaceHeightMeters, exactSurfaceHeight(moved, wgs84, eastLon, lat)->heightMeters,
              1e-6);
}

TEST(ExactSurface, SurfaceTestAndInvalidCameras) {
  const terrain::HeightBlock block = makeBlock(kN, hilly);
  const TileId id{8, 300, 90};
  RenderingTileArray array;
  array.assign({makeArrayTile(id, block)});
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const double lon = gridLongitude(id, kN, 6.4), lat = gridLatitude(id, kN, 9.1);
  const auto surface = exactSurfaceHeight(array, wgs84, lon, lat);
  ASSERT_TRUE(surface);
  EXPECT_EQ(surface->tile, id);
  for (double above : {-3.0, 4.0, 25.0}) {
    const glm::dvec3 camera =
        geo::cartographicToEcef(wgs84, {lon, lat, surface->heightMeters + above});
    const ExactSurfaceResult r = exactSurfaceTest(array, wgs84, camera, 5.0);
    EXPECT_TRUE(r.valid && r.found);
    EXPECT_NEAR(r.surfaceHeightMeters, surface->heightMeters, 1e-6);
    EXPECT_EQ(r.collided, above <= 5.0);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const glm::dvec3& camera : {glm::dvec3(0.0), glm::dvec3(nan, 1.0, 1.0)}) {
    const ExactSurfaceResult r = exactSurfaceTest(array, wgs84, camera, 5.0);
    EXPECT_FALSE(r.valid || r.found || r.collided);
    EXPECT_EQ(r.surfaceHeightMeters, 0.0);
    EXPECT_EQ(r.cameraHeightMeters, 0.0);
  }
  // No tile under the camera: sea level.
  const ExactSurfaceResult sea =
      exactSurfaceTest(array, wgs84, geo::cartographicToEcef(wgs84, {0.0, 0.0, 3.0}), 5.0);
  EXPECT_TRUE(sea.valid);
  EXPECT_FALSE(sea.found);
  EXPECT_TRUE(sea.collided);
  EXPECT_FALSE(exactSurfaceHeight(array, wgs84, 0.0, 0.0));
  EXPECT_FALSE(exactSurfaceHeight(array, wgs84, nan, 0.0));
}

}  // namespace
}  // namespace globe::collision
