// QOTCD on the real bundled pyramid (ETOPO20 + W002N52 + Fuji): the linear scan and the indexed
// lookup agree on 10^6 queries over real arrays; QOTCD's H is not below the exact rendered
// surface on 10^6 points of all levels and both globe models, except within the derived row-sliver
// bound (see rowSliverAllowanceMeters); the exact surface matches brute-force ray casting; real
// poles and Mount Fuji.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "collision/exact_surface.hpp"
#include "collision/grid_location.hpp"
#include "collision/height_service.hpp"
#include "collision/qotcd.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/collision/mesh_ray_cast.hpp"
#include "tests/collision/surface_bounds.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using testing::rowSliverAllowanceMeters;  // the derivation is in surface_bounds.hpp
using Scheme = geo::GeographicTilingScheme;
using testing::RealPyramid;

uint64_t tileHash(const TileId& id, uint64_t salt) { return std::hash<TileId>{}(id) ^ salt; }

bool intersectsDegrees(const TileId& id, double west, double south, double east, double north) {
  return Scheme::tileRectangle(id).intersects(
      geo::GlobeRectangle::fromDegrees(west, south, east, north));
}

// A selection-like cut: coarse everywhere, some random refinement, full depth over small areas
// of Fuji and eastern England.
std::vector<TileId> selectionLikeCut(RealPyramid& pyramid) {
  return testing::quadtreeCut(pyramid, [](const TileId& id) {
    if (id.level < 2) return true;
    if (id.level < 5 && tileHash(id, 1) % 100 < 35) return true;
    return intersectsDegrees(id, 138.70, 35.33, 138.76, 35.39) ||
           intersectsDegrees(id, -1.05, 52.95, -0.95, 53.05);
  });
}

struct NamedArray {
  std::string name;
  std::vector<TileId> tiles;
  bool coversGlobe;
};

std::vector<NamedArray> realArrays(RealPyramid& pyramid) {
  std::vector<NamedArray> arrays;
  arrays.push_back({"all of level 2", testing::tilesOfLevel(pyramid, 2, -180, -90, 180, 90), true});
  const std::vector<TileId> cut = selectionLikeCut(pyramid);
  arrays.push_back({"quadtree cut", cut, true});
  // Overlapping levels: every tile of levels 0..3 plus the cut (the finest wins).
  NamedArray overlap{"levels 0-3 + cut", {}, true};
  for (uint32_t level = 0; level <= 3; ++level) {
    const auto all = testing::tilesOfLevel(pyramid, level, -180, -90, 180, 90);
    overlap.tiles.insert(overlap.tiles.end(), all.begin(), all.end());
  }
  for (const TileId& id : cut) {
    if (id.level > 3) overlap.tiles.push_back(id);
  }
  arrays.push_back(overlap);
  // Holes: a quarter of the cut removed, so owners are often missing and neighbours answer.
  NamedArray holes{"cut with holes", {}, false};
  for (const TileId& id : cut) {
    if (tileHash(id, 7) % 4 != 0) holes.tiles.push_back(id);
  }
  arrays.push_back(holes);
  // Regional: level 10 over Fuji, the polar rows of level 4, the +-180 deg columns of level 5.
  NamedArray regional{"Fuji L10 + polar rows + antimeridian", {}, false};
  regional.tiles = testing::tilesOfLevel(pyramid, 10, 138.0, 35.0, 139.0, 36.0);
  for (uint32_t x = 0; x < Scheme::tilesX(4); ++x) {
    regional.tiles.push_back({4, x, 0});
    regional.tiles.push_back({4, x, Scheme::tilesY(4) - 1});
  }
  for (uint32_t y = 0; y < Scheme::tilesY(5); ++y) {
    regional.tiles.push_back({5, 0, y});
    regional.tiles.push_back({5, Scheme::tilesX(5) - 1, y});
  }
  arrays.push_back(regional);
  return arrays;
}

TEST(RealPyramid, LinearAndIndexedQotcdAgreeOnAMillionQueries) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const uint32_t maxLevel = pyramid.maxLevel();
  ASSERT_GE(maxLevel, 12u);
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> heightMeters(-600.0, 4500.0);
  constexpr int kQueriesPerArray = 200000;
  uint64_t total = 0;
  std::printf("%-40s %6s %8s %8s %9s %8s %9s %9s\n", "array", "tiles", "found", "edgeNbr",
              "earlyOut", "collided", "lin ns/q", "idx ns/q");
  for (const NamedArray& named : realArrays(pyramid)) {
    const RenderingTileArray array = pyramid.array(named.tiles);
    ASSERT_EQ(array.tiles().size(), named.tiles.size()) << named.name;
    uint64_t found = 0, neighbour = 0, earlyOuts = 0, collided = 0;
    double linearSeconds = 0, indexedSeconds = 0;
    for (int q = 0; q < kQueriesPerArray; ++q) {
      const auto point = testing::randomQueryPoint(rng, named.tiles, maxLevel, 17);
      const double d = rng() % 16 == 0 ? 1e6 : heightMeters(rng);
      const double clearance = static_cast<double>(rng() % 3) * 50.0;
      const geo::Cartographic camera{point.longitudeRadians, point.latitudeRadians, d};
      const auto t0 = std::chrono::steady_clock::now();
      const QotcdResult linear = qotcdLinear(array, camera, clearance);
      const auto t1 = std::chrono::steady_clock::now();
      const QotcdResult indexed = qotcdIndexed(array, camera, clearance);
      const auto t2 = std::chrono::steady_clock::now();
      linearSeconds += std::chrono::duration<double>(t1 - t0).count();
      indexedSeconds += std::chrono::duration<double>(t2 - t1).count();
      ++total;
      ASSERT_TRUE(linear.valid && indexed.valid);
      ASSERT_EQ(linear.found, indexed.found)
          << named.name << " lon " << point.longitudeRadians << " lat " << point.latitudeRadians;
      if (named.coversGlobe) {
        ASSERT_TRUE(linear.found) << named.name << " lon " << point.longitudeRadians << " lat "
                                  << point.latitudeRadians;
      }
      ASSERT_EQ(linear.tile, indexed.tile)
          << named.name << " lon " << point.longitudeRadians << " lat " << point.latitudeRadians;
      ASSERT_EQ(linear.terrainHeightMeters, indexed.terrainHeightMeters);
      ASSERT_EQ(linear.heightCase, indexed.heightCase);
      ASSERT_EQ(linear.collided, indexed.collided);
      ASSERT_EQ(linear.earlyOut, indexed.earlyOut);
      if (!linear.found) continue;
      ++found;
      earlyOuts += linear.earlyOut;
      collided += linear.collided;
      const auto owner = Scheme::positionToTile(linear.longitudeRadians, linear.latitudeRadians,
                                                linear.tile.level);
      if (owner && *owner != linear.tile) ++neighbour;
    }
    std::printf(
        "%-40s %6zu %8llu %8llu %9llu %8llu %9.1f %9.1f\n", named.name.c_str(), named.tiles.size(),
        static_cast<unsigned long long>(found), static_cast<unsigned long long>(neighbour),
        static_cast<unsigned long long>(earlyOuts), static_cast<unsigned long long>(collided),
        1e9 * linearSeconds / kQueriesPerArray, 1e9 * indexedSeconds / kQueriesPerArray);
    if (named.name != "all of level 2") {
      EXPECT_GT(neighbour, 100u) << named.name << ": edge neighbours must be exercised";
    }
  }
  EXPECT_GE(total, 1000000u);
}

// A random point of the tile: mostly inside quads, else on row/column lines, vertices, diagonals.
std::pair<double, double> randomPointInTile(std::mt19937_64& rng, const TileId& id) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double column = 16.0 * unit(rng), row = 16.0 * unit(rng);
  switch (rng() % 20) {
    case 0:
    case 1:
    case 2:
      row = std::floor(17.0 * unit(rng));
      break;
    case 3:
    case 4:
    case 5:
      column = std::floor(17.0 * unit(rng));
      break;
    case 6:
      row = std::floor(17.0 * unit(rng)), column = std::floor(17.0 * unit(rng));
      break;
    case 7:
      row = std::floor(row) + (column - std::floor(column));
      break;
    default:
      break;
  }
  return {testing::gridLongitude(id, 17, column), testing::gridLatitude(id, 17, row)};
}

TEST(RealPyramid, QotcdHeightIsAtLeastTheExactSurface) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const uint32_t maxLevel = pyramid.maxLevel();
  std::mt19937_64 rng(77);
  constexpr int kTilesPerLevel = 24;
  constexpr int kPointsPerTile = 1400;
  uint64_t points = 0, sliverPoints = 0;
  double worstUnderestimate = 0.0;  // min(H - E)
  double worstRatio = 0.0;          // of an underestimate to its allowance
  std::printf("%-7s %5s %9s %12s %12s %12s\n", "model", "level", "points", "max H-E m",
              "mean H-E m", "min H-E m");
  for (const geo::GlobeModel model : {geo::GlobeModel::Wgs84, geo::GlobeModel::Sphere}) {
    const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(model);
    for (uint32_t level = 0; level <= maxLevel; ++level) {
      std::vector<TileId> tiles;
      for (int k = 0; k < kTilesPerLevel; ++k) tiles.push_back(pyramid.randomTile(rng, level));
      if (level <= 5) {  // polar rows and the antimeridian, where ETOPO20 covers them
        tiles.push_back({level, static_cast<uint32_t>(rng() % Scheme::tilesX(level)), 0});
        tiles.push_back({level, static_cast<uint32_t>(rng() % Scheme::tilesX(level)),
                         Scheme::tilesY(level) - 1});
        tiles.push_back({level, Scheme::tilesX(level) - 1, 0});
      }
      double maxOver = 0.0, sumOver = 0.0, minOver = std::numeric_limits<double>::infinity();
      uint64_t count = 0;
      for (const TileId& id : tiles) {
        ASSERT_TRUE(pyramid.has(id));
        const ArrayTile tile = pyramid.arrayTile(id);
        for (int k = 0; k < kPointsPerTile; ++k) {
          const auto [lon, lat] = randomPointInTile(rng, id);
          const double h = qotcdTileHeight(tile, lon, lat).heightMeters;
          const double e = exactTileSurfaceHeight(tile, ellipsoid, lon, lat).heightMeters;
          ASSERT_TRUE(std::isfinite(e));
          const double over = h - e;
          if (over < -1e-6) {
            const double allowance = rowSliverAllowanceMeters(tile, lat, ellipsoid);
            ASSERT_GE(over, -allowance)
                << "tile " << id.level << "/" << id.x << "/" << id.y << " lon " << lon << " lat "
                << lat << " H " << h << " E " << e;
            ++sliverPoints;
            worstRatio = std::max(worstRatio, -over / allowance);
          }
          maxOver = std::max(maxOver, over);
          minOver = std::min(minOver, over);
          sumOver += over;
          ++count;
        }
      }
      points += count;
      worstUnderestimate = std::min(worstUnderestimate, minOver);
      std::printf("%-7s %5u %9llu %12.3f %12.3f %12.2e\n", std::string(toString(model)).c_str(),
                  level, static_cast<unsigned long long>(count), maxOver,
                  sumOver / static_cast<double>(count), minOver);
    }
  }
  std::printf(
      "points %llu, worst H - E %.3e m; %llu points below -1e-6 m, all within the row "
      "sliver allowance (at most %.2f of it)\n",
      static_cast<unsigned long long>(points), worstUnderestimate,
      static_cast<unsigned long long>(sliverPoints), worstRatio);
  EXPECT_GE(points, 1000000u);
}

TEST(RealPyramid, ExactSurfaceMatchesRayCastingTheMesh) {
  RealPyramid& pyramid = RealPyramid::bundled();
  std::mt19937_64 rng(5);
  uint64_t sameTriangle = 0, otherTriangle = 0, missed = 0;
  double worst = 0.0;
  for (const geo::GlobeModel model : {geo::GlobeModel::Wgs84, geo::GlobeModel::Sphere}) {
    const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(model);
    for (uint32_t level : {0u, 2u, 5u, 8u, 11u, pyramid.maxLevel()}) {
      for (int k = 0; k < 3; ++k) {
        const TileId id = pyramid.randomTile(rng, level);
        const ArrayTile tile = pyramid.arrayTile(id);
        for (int p = 0; p < 250; ++p) {
          const auto [lon, lat] = randomPointInTile(rng, id);
          const SurfaceSample exact = exactTileSurfaceHeight(tile, ellipsoid, lon, lat);
          const auto hit = testing::castOntoTileMesh(tile, ellipsoid, lon, lat);
          if (exact.triangle == SurfaceTriangle::Pole) continue;
          if (!hit) {
            ++missed;
            continue;
          }
          const double diff = std::abs(exact.heightMeters - hit->heightMeters);
          worst = std::max(worst, diff);
          if (hit->quadRow == exact.quadRow && hit->quadColumn == exact.quadColumn &&
              hit->southWest == (exact.triangle == SurfaceTriangle::SouthWest)) {
            ++sameTriangle;
          } else {
            ++otherTriangle;  // on a shared edge: both triangles hold the point
          }
          EXPECT_LE(diff, 1e-6) << "tile " << id.level << "/" << id.x << "/" << id.y << " lon "
                                << lon << " lat " << lat;
        }
      }
    }
  }
  std::printf(
      "ray cast vs exact surface: %llu points, %llu same triangle, %llu a neighbour "
      "sharing the edge, max diff %.2e m; %llu rays between tiles (miss this tile)\n",
      static_cast<unsigned long long>(sameTriangle + otherTriangle),
      static_cast<unsigned long long>(sameTriangle), static_cast<unsigned long long>(otherTriangle),
      worst, static_cast<unsigned long long>(missed));
  EXPECT_GT(sameTriangle, 4 * otherTriangle);
  EXPECT_LT(missed, (sameTriangle + otherTriangle) / 50);
}

TEST(RealPyramid, PolesAreOneHeightAndFoundFromAnyLongitude) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const RenderingTileArray array = pyramid.array(selectionLikeCut(pyramid));
  for (const bool north : {true, false}) {
    // Every pole vertex of every level the pyramid has there is the same height.
    const TileId root{0, 0, 0};
    const uint32_t poleRow = north ? 0 : 16;
    const double pole = pyramid.block(root).surfaceHeightMetersAt(poleRow, 0);
    for (uint32_t level = 0; level <= 5; ++level) {
      for (uint32_t x = 0; x < Scheme::tilesX(level); x += 1 + level) {
        const TileId id{level, x, north ? 0 : Scheme::tilesY(level) - 1};
        if (!pyramid.has(id)) continue;
        for (uint32_t j = 0; j < 17; ++j) {
          ASSERT_EQ(pyramid.block(id).surfaceHeightMetersAt(poleRow, j), pole);
        }
      }
    }
    for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
      const double z = (north ? 1.0 : -1.0) * (ellipsoid.semiMinorAxisMeters + pole + 30.0);
      using PoleDetector = QotcdResult (*)(const RenderingTileArray&, const geo::Ellipsoid&,
                                           const glm::dvec3&, double);
      for (const PoleDetector detect : {PoleDetector{qotcdLinear}, PoleDetector{qotcdIndexed}}) {
        const QotcdResult r = detect(array, ellipsoid, glm::dvec3(0.0, 0.0, z), 0.0);
        ASSERT_TRUE(r.found);
        if (!r.earlyOut) {
          EXPECT_EQ(r.terrainHeightMeters, pole);
        }
        EXPECT_GE(r.terrainHeightMeters, pole);
        EXPECT_FALSE(r.collided);
        EXPECT_TRUE(detect(array, ellipsoid, glm::dvec3(0.0, 0.0, z), 31.0).collided);
      }
      for (double lon : {-std::numbers::pi, -2.0, 0.5, std::numbers::pi}) {
        const auto sample =
            sampleHeight(array, ellipsoid, lon,
                         north ? std::numbers::pi / 2 : -std::numbers::pi / 2, HeightMode::Exact);
        ASSERT_TRUE(sample);
        EXPECT_EQ(sample->heightMeters, pole);
      }
    }
    std::printf("%s pole height %.0f m\n", north ? "north" : "south", pole);
  }
}

TEST(RealPyramid, MountFujiSummit) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const RenderingTileArray array = pyramid.array(selectionLikeCut(pyramid));
  const double lon = geo::degreesToRadians(138.7275), lat = geo::degreesToRadians(35.3606);
  const auto qotcd = sampleHeight(array, geo::Ellipsoid::wgs84(), lon, lat, HeightMode::Qotcd);
  const auto exact = sampleHeight(array, geo::Ellipsoid::wgs84(), lon, lat, HeightMode::Exact);
  ASSERT_TRUE(qotcd && exact);
  EXPECT_EQ(qotcd->level, pyramid.maxLevel());
  EXPECT_EQ(exact->tile, qotcd->tile);
  EXPECT_GE(qotcd->heightMeters, exact->heightMeters);
  EXPECT_GT(exact->heightMeters, 3600.0);
  EXPECT_LT(qotcd->heightMeters, 3800.0);
  std::printf("Fuji summit: level %u, QOTCD %.1f m, exact %.3f m\n", qotcd->level,
              qotcd->heightMeters, exact->heightMeters);
  // A camera 10 m above the exact surface collides by QOTCD with 50 m clearance, not without.
  const glm::dvec3 camera =
      geo::cartographicToEcef(geo::Ellipsoid::wgs84(), {lon, lat, exact->heightMeters + 10.0});
  EXPECT_TRUE(qotcdIndexed(array, geo::Ellipsoid::wgs84(), camera, 50.0).collided);
  EXPECT_FALSE(exactSurfaceTest(array, geo::Ellipsoid::wgs84(), camera, 0.0).collided);
  EXPECT_TRUE(exactSurfaceTest(array, geo::Ellipsoid::wgs84(), camera, 10.5).collided);
}

}  // namespace
}  // namespace globe::collision
