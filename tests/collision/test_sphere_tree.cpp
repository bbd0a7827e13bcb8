// Tests for collision/sphere_tree.hpp: the point-triangle distance, spheres that bound their
// sub-blocks, agreement with brute force over every triangle on real tiles, and the early exit.
#include "collision/sphere_tree.hpp"
#include "collision/sphere_tree_bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "collision/exact_surface.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/collision/collision_test_support.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using Scheme = geo::GeographicTilingScheme;
using testing::RealPyramid;
// An independent reference: the face when the projection falls inside, else the nearest edge.
double referenceSquaredDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                const glm::dvec3& c) {
  auto segment = [&p](const glm::dvec3& s, const glm::dvec3& e) {
    const glm::dvec3 d = e - s;
    const double length = glm::dot(d, d);
    double t = length > 0 ? glm::dot(p - s, d) / length : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const glm::dvec3 q = s + t * d - p;
    return glm::dot(q, q);
  };
  double best = std::min({segment(a, b), segment(b, c), segment(c, a)});
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double nn = glm::dot(n, n);
  if (nn > 0) {
    const double signedDistance = glm::dot(p - a, n) / std::sqrt(nn);
    const glm::dvec3 q = p - signedDistance * n / std::sqrt(nn);
    const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                        glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                        glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (inside) best = std::min(best, signedDistance * signedDistance);
  }
  return best;
}

TEST(SphereTree, PointTriangleDistanceMatchesAReference) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  auto point = [&] { return glm::dvec3{coordinate(rng), coordinate(rng), coordinate(rng)}; };
  for (int k = 0; k < 200000; ++k) {
    const glm::dvec3 p = point();
    glm::dvec3 a = point(), b = point(), c = point();
    const auto shape = k % 8;
    if (shape == 0) b = a;                           // collapsed edge (a pole quad's half)
    if (shape == 1) b = c = a;                       // a point
    if (shape == 2) c = a + 0.37 * (b - a);          // collinear
    if (shape == 3) b = a + glm::dvec3{1e-9, 0, 0};  // a sliver
    const double expected = referenceSquaredDistance(p, a, b, c);
    const double actual = squaredDistanceToTriangle(p, a, b, c);
    ASSERT_TRUE(std::isfinite(actual));
    ASSERT_NEAR(actual, expected, 1e-9 * (1.0 + expected)) << k;
  }
  // Exactly on the surface and on the edges.
  const glm::dvec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_EQ(squaredDistanceToTriangle({0.25, 0.25, 0}, a, b, c), 0.0);
  EXPECT_EQ(squaredDistanceToTriangle({0.5, 0.0, 0}, a, b, c), 0.0);
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle({0.25, 0.25, 2}, a, b, c), 4.0);
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle({-1, -1, 0}, a, b, c), 2.0);
}

// Fuji level 14 around the summit, eastern England level 11, the polar rows of level 2 (whose
// pole quads collapse) and two level-0 tiles' worth of level 1.
std::vector<TileId> realTiles(RealPyramid& pyramid) {
  std::vector<TileId> tiles = testing::tilesOfLevel(pyramid, 14, 138.70, 35.33, 138.75, 35.38);
  const auto england = testing::tilesOfLevel(pyramid, 11, -1.1, 52.9, -0.95, 53.05);
  tiles.insert(tiles.end(), england.begin(), england.end());
  for (uint32_t x = 0; x < Scheme::tilesX(2); x += 3) {
    tiles.push_back({2, x, 0});
    tiles.push_back({2, x, Scheme::tilesY(2) - 1});
  }
  tiles.push_back({1, 1, 1});
  return tiles;
}

TEST(SphereTree, SpheresBoundTheirSubBlocksAndTriangles) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const RenderingTileArray array = pyramid.array(realTiles(pyramid));
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  SphereTreeSet trees;
  trees.build(array, wgs84);
  ASSERT_EQ(trees.tileCount(), array.tiles().size());
  for (uint32_t t = 0; t < trees.tileCount(); ++t) {
    const ArrayTile& tile = array.tiles()[t];
    const uint32_t n = trees.verticesPerSide(t);
    ASSERT_EQ(trees.depth(t), 4u);  // 17 x 17: 16 -> 8 -> 4 -> 2 -> 1 quads
    // The vertices are the mesh's.
    const terrain::BlockGrid grid{tile.id, n};
    for (uint32_t i = 0; i < n; i += 5) {
      for (uint32_t j = 0; j < n; j += 3) {
        EXPECT_EQ(trees.vertex(t, i, j),
                  terrain::tileVertexEcefMeters(wgs84, grid, i, j,
                                                tile.block->surfaceHeightMetersAt(i, j)));
      }
    }
    for (uint32_t level = 0; level <= trees.depth(t); ++level) {
      std::vector<int> covered((n - 1) * (n - 1), 0);
      for (uint32_t index = 0; index < (1u << (2 * level)); ++index) {
        const SphereTreeSet::Block block = trees.nodeBlock(t, level, index);
        ASSERT_EQ(block.quadsPerSide, 16u >> level);
        const BoundingSphere sphere = trees.node(t, level, index);
        for (uint32_t i = block.firstRow; i <= block.firstRow + block.quadsPerSide; ++i) {
          for (uint32_t j = block.firstColumn; j <= block.firstColumn + block.quadsPerSide; ++j) {
            if (i < block.firstRow + block.quadsPerSide &&
                j < block.firstColumn + block.quadsPerSide) {
              ++covered[i * (n - 1) + j];
            }
            // Every vertex inside: the triangles (their convex hulls) are inside too.
            ASSERT_LE(glm::distance(trees.vertex(t, i, j), sphere.centerEcefMeters),
                      sphere.radiusMeters);
          }
        }
        if (level < trees.depth(t)) {
          // The children split the block into its four quadrants, NW, NE, SW, SE.
          const uint32_t half = block.quadsPerSide / 2;
          for (uint32_t child = 0; child < 4; ++child) {
            const SphereTreeSet::Block sub = trees.nodeBlock(t, level + 1, 4 * index + child);
            EXPECT_EQ(sub.firstRow, block.firstRow + (child / 2) * half);
            EXPECT_EQ(sub.firstColumn, block.firstColumn + (child % 2) * half);
          }
        }
      }
      // Each level partitions the tile's quads.
      EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
    }
  }
  EXPECT_GT(trees.memoryBytes(), trees.tileCount() * (341 * sizeof(BoundingSphere)));
}

// Every triangle of every tile within the radius, by brute force.
std::vector<TriangleRef> bruteForce(const SphereTreeSet& trees, const glm::dvec3& center,
                                    double radius) {
  std::vector<TriangleRef> found;
  for (uint32_t t = 0; t < trees.tileCount(); ++t) {
    const uint32_t cells = trees.verticesPerSide(t) - 1;
    for (uint32_t i = 0; i < cells; ++i) {
      for (uint32_t j = 0; j < cells; ++j) {
        const glm::dvec3 a = trees.vertex(t, i, j), b = trees.vertex(t, i + 1, j),
                         c = trees.vertex(t, i + 1, j + 1), d = trees.vertex(t, i, j + 1);
        if (squaredDistanceToTriangle(center, a, b, c) <= radius * radius) {
          found.push_back({t, i, j, true});
        }
        if (squaredDistanceToTriangle(center, a, c, d) <= radius * radius) {
          found.push_back({t, i, j, false});
        }
      }
    }
  }
  return found;
}

TEST(SphereTree, FindsEveryTriangleThatBruteForceFinds) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const std::vector<TileId> ids = realTiles(pyramid);
  const RenderingTileArray array = pyramid.array(ids);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  SphereTreeSet trees;
  trees.build(array, wgs84);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> offset(-150.0, 150.0);
  int colliding = 0, manyHits = 0;
  constexpr int kQueries = 2000;
  for (int q = 0; q < kQueries; ++q) {
    const testing::LonLat point = testing::randomQueryPoint(rng, ids, 14, 17);
    const auto surface =
        exactSurfaceHeight(array, wgs84, point.longitudeRadians, point.latitudeRadians);
    const double height = (surface ? surface->heightMeters : 0.0) + offset(rng);
    const glm::dvec3 camera =
        geo::cartographicToEcef(wgs84, {point.longitudeRadians, point.latitudeRadians, height});
    const double radius = std::array{50.0, 50.0, 50.0, 10.0, 400.0}[rng() % 5];
    std::vector<TriangleRef> expected = bruteForce(trees, camera, radius);
    std::vector<TriangleRef> found = trees.trianglesWithin(camera, radius);
    std::sort(expected.begin(), expected.end());
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << q;
    const SphereTreeResult result = trees.intersect(camera, radius);
    ASSERT_EQ(result.collided, !expected.empty()) << q;
    if (result.collided) {
      ++colliding;
      manyHits += expected.size() > 1;
      EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), result.hit));
      EXPECT_GE(result.triangleTests, 1u);
    } else {
      EXPECT_GE(result.sphereTests, trees.tileCount());  // every root was tested
    }
    const uint32_t tile = static_cast<uint32_t>(rng() % trees.tileCount());
    const bool inTile = std::any_of(expected.begin(), expected.end(),
                                    [tile](const TriangleRef& r) { return r.tile == tile; });
    EXPECT_EQ(trees.intersectTile(tile, camera, radius).collided, inTile);
  }
  // The queries exercise both outcomes.
  EXPECT_GT(colliding, kQueries / 5);
  EXPECT_LT(colliding, kQueries * 4 / 5);
  EXPECT_GT(manyHits, kQueries / 10);
}

// The hierarchy over the roots answers as the scan does (its speed is globe-bench's
// BM_SphereTreeBvh: over these few mixed-level tiles, some a continent wide, it saves nothing).
TEST(SphereTree, TheBvhAgreesWithTheScan) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const std::vector<TileId> ids = realTiles(pyramid);
  const RenderingTileArray array = pyramid.array(ids);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  SphereTreeSet trees;
  trees.build(array, wgs84);
  const SphereTreeBvh bvh(trees);
  EXPECT_GT(bvh.nodeCount(), trees.tileCount() / 4);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> offset(-150.0, 150.0);
  int colliding = 0;
  uint64_t scanTests = 0, bvhTests = 0;
  constexpr int kQueries = 4000;
  for (int q = 0; q < kQueries; ++q) {
    const testing::LonLat point = testing::randomQueryPoint(rng, ids, 14, 17);
    const auto surface =
        exactSurfaceHeight(array, wgs84, point.longitudeRadians, point.latitudeRadians);
    const double height = (surface ? surface->heightMeters : 0.0) + offset(rng);
    const glm::dvec3 camera =
        geo::cartographicToEcef(wgs84, {point.longitudeRadians, point.latitudeRadians, height});
    const double radius = std::array{50.0, 10.0, 400.0}[rng() % 3];
    const SphereTreeResult scan = trees.intersect(camera, radius);
    const SphereTreeResult fast = bvh.intersect(camera, radius);
    ASSERT_EQ(fast.collided, scan.collided) << q;
    if (fast.collided) {
      ++colliding;
      const std::vector<TriangleRef> within = trees.trianglesWithin(camera, radius);
      EXPECT_TRUE(std::find(within.begin(), within.end(), fast.hit) != within.end()) << q;
    }
    scanTests += scan.sphereTests;
    bvhTests += fast.sphereTests;
  }
  EXPECT_GT(colliding, kQueries / 5);
  EXPECT_LT(colliding, kQueries * 4 / 5);
  std::printf("%zu tiles: sphere tests per query %.1f scanning, %.1f through the BVH\n",
              trees.tileCount(), static_cast<double>(scanTests) / kQueries,
              static_cast<double>(bvhTests) / kQueries);
  EXPECT_FALSE(bvh.intersect({std::nan(""), 0, 0}, 50.0).collided);
  SphereTreeSet empty;
  empty.build(RenderingTileArray{}, wgs84);
  EXPECT_FALSE(SphereTreeBvh(empty).intersect(glm::dvec3(6.4e6, 0, 0), 50.0).collided);
}

TEST(SphereTree, StopsAtTheFirstHit) {
  // Flat tiles at 100 m: a camera 1 m above the north-west vertex of the first tile, with a
  // sphere reaching hundreds of triangles, is settled by the first triangle tested.
  const terrain::HeightBlock flat =
      testing::makeBlock(17, [](uint32_t, uint32_t) { return int16_t{100}; });
  const RenderingTileArray array =
      testing::arrayOf({{14, 29000, 4500}, {14, 29001, 4500}, {14, 29000, 4501}}, flat);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  SphereTreeSet trees;
  trees.build(array, wgs84);
  const uint32_t first = 0;
  const glm::dvec3 camera = geo::cartographicToEcef(
      wgs84, {array.tiles()[first].westRadians, array.tiles()[first].northRadians, 101.0});
  const double radius = 600.0;
  ASSERT_GT(trees.trianglesWithin(camera, radius).size(), 100u);
  const SphereTreeResult result = trees.intersect(camera, radius);
  ASSERT_TRUE(result.collided);
  EXPECT_EQ(result.triangleTests, 1u);
  EXPECT_EQ(result.sphereTests, 1u + trees.depth(first));  // the root, then one node per level
  EXPECT_EQ(result.hit, (TriangleRef{first, 0, 0, true}));

  // Far above: only the roots are tested.
  const glm::dvec3 high = geo::cartographicToEcef(
      wgs84, {array.tiles()[first].westRadians, array.tiles()[first].northRadians, 5000.0});
  const SphereTreeResult miss = trees.intersect(high, 50.0);
  EXPECT_FALSE(miss.collided);
  EXPECT_EQ(miss.sphereTests, 3u);
  EXPECT_EQ(miss.triangleTests, 0u);
}

TEST(SphereTree, SemanticsAreDistanceToTheDrawnSurface) {
  // Within the radius above or below the surface: a collision; deeper than the radius below it
  // (the camera inside the terrain): none, unlike QOTCD and the exact surface test.
  const terrain::HeightBlock flat =
      testing::makeBlock(17, [](uint32_t, uint32_t) { return int16_t{500}; });
  const RenderingTileArray array = testing::arrayOf({{12, 7000, 1000}}, flat);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  SphereTreeSet trees;
  trees.build(array, wgs84);
  const geo::GlobeRectangle r = Scheme::tileRectangle({12, 7000, 1000});
  const double lon = r.westRadians + 0.3 * r.widthRadians();
  const double lat = r.southRadians + 0.6 * r.heightRadians();
  const auto surface = exactSurfaceHeight(array, wgs84, lon, lat);
  ASSERT_TRUE(surface);
  auto at = [&](double aboveSurface) {
    return geo::cartographicToEcef(wgs84, {lon, lat, surface->heightMeters + aboveSurface});
  };
  EXPECT_TRUE(trees.intersect(at(49.9), kCameraSphereRadiusMeters).collided);
  EXPECT_FALSE(trees.intersect(at(50.1), kCameraSphereRadiusMeters).collided);
  EXPECT_TRUE(trees.intersect(at(-49.9), kCameraSphereRadiusMeters).collided);
  EXPECT_FALSE(trees.intersect(at(-50.1), kCameraSphereRadiusMeters).collided);
  // Non-finite cameras find nothing.
  EXPECT_FALSE(trees.intersect({std::nan(""), 0, 0}, 50.0).collided);
  // An empty set.
  SphereTreeSet empty;
  empty.build(RenderingTileArray{}, wgs84);
  EXPECT_FALSE(empty.intersect(at(0.0), 50.0).collided);
  EXPECT_EQ(empty.memoryBytes(), 0u);
}

}  // namespace
}  // namespace globe::collision
