// The eye's distance to the nearest drawn triangle on real canyon walls (Zion, SRTM 3"), against
// a brute force over every triangle of the tiles around it with a separately written point-to-
// triangle distance (plane projection, else the nearest edge); and the push that clears the ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <glm/geometric.hpp>

#include "collision/exact_surface.hpp"
#include "collision/lateral_clearance.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using globe::test::kWgs84;

double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::distance(p, a + t * ab);
}

double triangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                        const glm::dvec3& c) {
  const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
  const double height = glm::dot(p - a, n);
  const glm::dvec3 q = p - height * n;  // in the plane
  const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                      glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                      glm::dot(glm::cross(a - c, q - c), n) >= 0;
  if (inside) return std::abs(height);
  return std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
}

// Every triangle of every tile holding a point within 200 m of the eye's footprint.
double bruteForceDistance(const RenderingTileArray& array, const glm::dvec3& eye) {
  const auto at = geo::ecefToCartographic(kWgs84, eye);
  std::vector<const ArrayTile*> tiles;
  for (int a = -1; a <= 1; ++a) {
    for (int b = -1; b <= 1; ++b) {
      const ArrayTile* tile =
          array.findIndexed(at->longitudeRadians + b * 3e-5, at->latitudeRadians + a * 3e-5);
      if (tile && std::find(tiles.begin(), tiles.end(), tile) == tiles.end()) tiles.push_back(tile);
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (const ArrayTile* tile : tiles) {
    const terrain::BlockGrid grid{tile->id, tile->block->verticesPerSide};
    const auto v = [&](uint32_t r, uint32_t c) {
      return terrain::tileVertexEcefMeters(kWgs84, grid, r, c,
                                           tile->block->surfaceHeightMetersAt(r, c));
    };
    for (uint32_t i = 0; i + 1 < grid.verticesPerSide; ++i) {
      for (uint32_t j = 0; j + 1 < grid.verticesPerSide; ++j) {
        best = std::min({best, triangleDistance(eye, v(i, j), v(i + 1, j), v(i + 1, j + 1)),
                         triangleDistance(eye, v(i, j), v(i + 1, j + 1), v(i, j + 1))});
      }
    }
  }
  return best;
}

const RenderingTileArray& canyon() {
  static const RenderingTileArray array = [] {
    testing::RealPyramid& pyramid = testing::RealPyramid::zion();
    const uint32_t finest = pyramid.maxLevel();
    return pyramid.array(testing::quadtreeCut(pyramid, [&](const geo::TileId& id) {
      const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(id);
      return id.level < 2 ||
             (id.level < finest && r.westRadians <= geo::degreesToRadians(-112.93) &&
              r.eastRadians >= geo::degreesToRadians(-112.96) &&
              r.southRadians <= geo::degreesToRadians(37.29) &&
              r.northRadians >= geo::degreesToRadians(37.27));
    }));
  }();
  return array;
}

TEST(LateralClearance, NearestTriangleMatchesABruteForceOnCanyonWalls) {
  const RenderingTileArray& array = canyon();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> lon(-112.9445, -112.9405), lat(37.275, 37.285),
      above(0.05, 3.0);
  int near = 0;
  for (int k = 0; k < 300; ++k) {
    const double lonRadians = geo::degreesToRadians(lon(rng));
    const double latRadians = geo::degreesToRadians(lat(rng));
    const auto ground = exactSurfaceHeight(array, kWgs84, lonRadians, latRadians);
    ASSERT_TRUE(ground);
    const glm::dvec3 eye = geo::cartographicToEcef(
        kWgs84, {lonRadians, latRadians, ground->heightMeters + above(rng)});
    const double expected = bruteForceDistance(array, eye);
    const auto found = nearestDrawnTriangle(array, kWgs84, eye, 5.0);
    if (expected >= 5.0 - 1e-6) {
      EXPECT_FALSE(found && found->distanceMeters < 5.0 - 1e-6) << k;
      continue;
    }
    ++near;
    ASSERT_TRUE(found) << k << " expected " << expected;
    EXPECT_NEAR(found->distanceMeters, expected, 1e-6) << k;
    EXPECT_NEAR(glm::length(found->awayEcef), 1.0, 1e-9);
    // Stepping back along `away` by the distance reaches the surface's nearest point.
    EXPECT_NEAR(bruteForceDistance(array, eye - found->distanceMeters * found->awayEcef), 0.0, 1e-6)
        << k;
  }
  EXPECT_GT(near, 200);  // on the walls, most eyes within 3 m vertically are nearer than 5 m
}

TEST(LateralClearance, ThePushClearsTheBallAndLeavesAFreeEyeAlone) {
  const RenderingTileArray& array = canyon();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> lon(-112.9445, -112.9405), lat(37.275, 37.285),
      above(0.05, 1.0);
  for (int k = 0; k < 100; ++k) {
    const double lonRadians = geo::degreesToRadians(lon(rng));
    const double latRadians = geo::degreesToRadians(lat(rng));
    const double ground = exactSurfaceHeight(array, kWgs84, lonRadians, latRadians)->heightMeters;
    const glm::dvec3 eye =
        geo::cartographicToEcef(kWgs84, {lonRadians, latRadians, ground + above(rng)});
    const LateralPush push = pushAwayFromTerrain(array, kWgs84, eye, 0.75);
    ASSERT_TRUE(push.valid);
    EXPECT_GE(bruteForceDistance(array, push.eyeEcefMeters), 0.75) << k;
    EXPECT_LT(push.pushMeters, 0.76) << k;  // never more than the ball's radius
  }
  // 100 m above the canyon floor: nothing within the ball, nothing moves.
  const glm::dvec3 high =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(-112.9470, 37.2797, 1500.0));
  const LateralPush free = pushAwayFromTerrain(array, kWgs84, high, 0.75);
  EXPECT_TRUE(free.valid);
  EXPECT_EQ(free.pushMeters, 0.0);
  EXPECT_FALSE(pushAwayFromTerrain(array, kWgs84, glm::dvec3(NAN), 0.75).valid);
  EXPECT_FALSE(pushAwayFromTerrain(array, kWgs84, high, NAN).valid);
}

}  // namespace
}  // namespace globe::collision
