// Tests for collision/qotcd.hpp through ECEF cameras: the collision decision and clearance on
// both globe models, invalid cameras, no tile, the early-out, poles and the antimeridian.
#include "collision/qotcd.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using globe::test::kN;
using testing::gridLatitude;
using testing::gridLongitude;
using testing::makeBlock;
const TileId kTile{3, 5, 2};

using Detector = QotcdResult (*)(const RenderingTileArray&, const geo::Ellipsoid&,
                                 const glm::dvec3&, double);
const Detector kDetectors[] = {qotcdLinear, qotcdIndexed};

using testing::distinct;

void expectAllFinite(const QotcdResult& r) {
  EXPECT_TRUE(std::isfinite(r.terrainHeightMeters));
  EXPECT_TRUE(std::isfinite(r.cameraHeightMeters));
  EXPECT_TRUE(std::isfinite(r.longitudeRadians));
  EXPECT_TRUE(std::isfinite(r.latitudeRadians));
}

TEST(Qotcd, CollisionDecisionOnBothGlobeModels) {
  const terrain::HeightBlock block = makeBlock(kN, distinct);
  const RenderingTileArray array = testing::arrayOf({kTile}, block);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (Detector detect : kDetectors) {
      // Above vertex (7, 9): H = 709. The ECEF round trip moves lon/lat by ~1e-16: on the vertex.
      const double lon = gridLongitude(kTile, kN, 9), lat = gridLatitude(kTile, kN, 7);
      for (double d : {5000.0, 720.0, 709.5, 708.5, 100.0, -50.0}) {
        const glm::dvec3 camera = geo::cartographicToEcef(ellipsoid, {lon, lat, d});
        const QotcdResult r = detect(array, ellipsoid, camera, 10.0);
        ASSERT_TRUE(r.valid && r.found);
        EXPECT_EQ(r.tile, kTile);
        EXPECT_NEAR(r.cameraHeightMeters, d, 1e-6);
        EXPECT_EQ(r.collided, d <= 709.0 + 10.0) << d;
        EXPECT_NEAR(r.longitudeRadians, lon, 1e-15);
        EXPECT_NEAR(r.latitudeRadians, lat, 1e-15);
        if (d > 1616.0 + 10.0) {  // above the tile maximum + clearance: early-out
          EXPECT_TRUE(r.earlyOut);
          EXPECT_EQ(r.heightCase, HeightCase::TileMaximum);
          EXPECT_EQ(r.terrainHeightMeters, 1616.0);
        } else {
          EXPECT_FALSE(r.earlyOut);
          EXPECT_EQ(r.heightCase, HeightCase::Vertex);
          EXPECT_EQ(r.terrainHeightMeters, 709.0);
        }
      }
      // Inside quad (7, 9): H = max of 709, 710, 809, 810.
      const glm::dvec3 quad = geo::cartographicToEcef(
          ellipsoid, {gridLongitude(kTile, kN, 9.3), gridLatitude(kTile, kN, 7.6), 805.0});
      const QotcdResult r = detect(array, ellipsoid, quad, 0.0);
      EXPECT_EQ(r.terrainHeightMeters, 810.0);
      EXPECT_EQ(r.heightCase, HeightCase::Quad);
      EXPECT_TRUE(r.collided);
      // Non-finite clearance counts as 0.
      EXPECT_FALSE(detect(array, ellipsoid, geo::cartographicToEcef(ellipsoid, {lon, lat, 712.0}),
                          std::nan(""))
                       .collided);
    }
  }
}

TEST(Qotcd, InvalidCameraGivesAnInvalidResultWithoutNaN) {
  const terrain::HeightBlock block = makeBlock(kN, distinct);
  const RenderingTileArray array = testing::arrayOf({{0, 0, 0}, {0, 1, 0}}, block);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (Detector detect : kDetectors) {
      for (const glm::dvec3& camera :
           {glm::dvec3(0.0), glm::dvec3(1e-10, 0.0, 0.0), glm::dvec3(nan, 0.0, 0.0),
            glm::dvec3(0.0, 0.0, nan), glm::dvec3(inf, 0.0, 0.0), glm::dvec3(-inf, inf, 1.0)}) {
        const QotcdResult r = detect(array, ellipsoid, camera, 10.0);
        EXPECT_FALSE(r.valid);
        EXPECT_FALSE(r.found);
        EXPECT_FALSE(r.collided);
        EXPECT_FALSE(r.earlyOut);
        EXPECT_EQ(r.heightCase, HeightCase::None);
        EXPECT_EQ(r.terrainHeightMeters, 0.0);
        EXPECT_EQ(r.cameraHeightMeters, 0.0);
        expectAllFinite(r);
      }
      // Deep inside but away from the centre is valid: far below the terrain, a collision.
      const QotcdResult deep = detect(array, ellipsoid, glm::dvec3(1000.0, 0.0, 0.0), 0.0);
      EXPECT_TRUE(deep.valid && deep.found && deep.collided);
      expectAllFinite(deep);
    }
  }
  for (const geo::Cartographic& camera :
       {geo::Cartographic{nan, 0.0, 0.0}, geo::Cartographic{0.0, nan, 0.0},
        geo::Cartographic{0.0, 0.0, nan}, geo::Cartographic{0.0, 1.6, 0.0},
        geo::Cartographic{inf, 0.0, 0.0}}) {
    EXPECT_FALSE(qotcdLinear(array, camera, 0.0).valid);
    EXPECT_FALSE(qotcdIndexed(array, camera, 0.0).valid);
  }
}

TEST(Qotcd, NoTileMeansSeaLevel) {
  const terrain::HeightBlock block = makeBlock(kN, distinct);
  const RenderingTileArray empty;
  const RenderingTileArray elsewhere = testing::arrayOf({{3, 0, 0}}, block);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  for (const RenderingTileArray* array : {&empty, &elsewhere}) {
    for (Detector detect : kDetectors) {
      for (double d : {-5.0, 3.0, 50.0}) {
        const QotcdResult r =
            detect(*array, wgs84, geo::cartographicToEcef(wgs84, {0.2, 0.3, d}), 10.0);
        EXPECT_TRUE(r.valid);
        EXPECT_FALSE(r.found);
        EXPECT_EQ(r.terrainHeightMeters, 0.0);
        EXPECT_EQ(r.heightCase, HeightCase::None);
        EXPECT_EQ(r.collided, d <= 10.0);
      }
    }
  }
}

TEST(Qotcd, EarlyOutSkipsTheBlockRead) {
  const terrain::HeightBlock block =
      makeBlock(kN, [](uint32_t, uint32_t) { return int16_t{1000}; });
  // The tile claims a maximum of 100 m, below its real 1000 m: an early-out shows in the answer.
  ArrayTile lying = makeArrayTile(kTile, block);
  lying.maximumHeightMeters = 100;
  RenderingTileArray array;
  array.assign({lying});
  const geo::Ellipsoid sphere = geo::Ellipsoid::sphere();
  const double lon = gridLongitude(kTile, kN, 4.5), lat = gridLatitude(kTile, kN, 3.5);
  for (Detector detect : kDetectors) {
    QotcdCounters counters;
    // Far above (D > 100 + 20): never reads; the (wrong) block height of 1000 m is not seen.
    for (double d : {1e7, 1e5, 500.0, 121.0}) {
      const QotcdResult r =
          detect(array, sphere, geo::cartographicToEcef(sphere, {lon, lat, d}), 20.0);
      counters.add(r);
      EXPECT_TRUE(r.earlyOut);
      EXPECT_FALSE(r.collided);
      EXPECT_EQ(r.terrainHeightMeters, 100.0);
    }
    EXPECT_EQ(counters.earlyOuts, 4u);
    EXPECT_EQ(counters.blockReads, 0u);
    // At or below maximum + clearance: reads the block (H = 1000) and collides.
    for (double d : {119.0, 50.0}) {
      const QotcdResult r =
          detect(array, sphere, geo::cartographicToEcef(sphere, {lon, lat, d}), 20.0);
      counters.add(r);
      EXPECT_FALSE(r.earlyOut);
      EXPECT_TRUE(r.collided);
      EXPECT_EQ(r.terrainHeightMeters, 1000.0);
      EXPECT_EQ(r.heightCase, HeightCase::Quad);
    }
    EXPECT_EQ(counters.queries, 6u);
    EXPECT_EQ(counters.earlyOuts, 4u);
    EXPECT_EQ(counters.blockReads, 2u);
    EXPECT_EQ(counters.collisions, 2u);
  }
}

TEST(Qotcd, PolesFromEcef) {
  // Pole rows: north pole vertices 500 m (equal, as in a pyramid), south pole 2800 m.
  const terrain::HeightBlock north = makeBlock(
      kN, [](uint32_t i, uint32_t j) { return static_cast<int16_t>(i == 0 ? 500 : 10 * i + j); });
  const terrain::HeightBlock south = makeBlock(kN, [](uint32_t i, uint32_t j) {
    return static_cast<int16_t>(i == kN - 1 ? 2800 : 10 * i + j);
  });
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    const double b = ellipsoid.semiMinorAxisMeters;
    // Only tiles away from longitude 0 (the longitude ecefToCartographic gives on the axis).
    RenderingTileArray array;
    array.assign({makeArrayTile({4, 25, 0}, north), makeArrayTile({4, 3, 15}, south),
                  makeArrayTile({2, 7, 3}, south)});
    for (Detector detect : kDetectors) {
      const QotcdResult n = detect(array, ellipsoid, {0.0, 0.0, b + 400.0}, 0.0);
      EXPECT_TRUE(n.valid && n.found);
      EXPECT_EQ(n.latitudeRadians, std::numbers::pi / 2.0);
      EXPECT_EQ(n.tile, (TileId{4, 25, 0}));
      EXPECT_EQ(n.terrainHeightMeters, 500.0);
      EXPECT_EQ(n.heightCase, HeightCase::Vertex);
      EXPECT_TRUE(n.collided);
      EXPECT_NEAR(n.cameraHeightMeters, 400.0, 1e-6);
      const QotcdResult s = detect(array, ellipsoid, {0.0, 0.0, -b - 2820.0}, 50.0);
      EXPECT_EQ(s.tile, (TileId{4, 3, 15}));  // finer than (2,7,3)
      EXPECT_EQ(s.terrainHeightMeters, 2800.0);
      EXPECT_EQ(s.heightCase, HeightCase::Vertex);
      EXPECT_TRUE(s.collided);
      EXPECT_FALSE(detect(array, ellipsoid, {0.0, 0.0, -b - 2851.0}, 50.0).collided);
      // Close to the pole but not on it, above the pole row's vertices: same tile and height.
      const QotcdResult near = detect(
          array, ellipsoid,
          geo::cartographicToEcef(
              ellipsoid,
              {geo::GeographicTilingScheme::tileRectangle({4, 25, 0}).center().longitudeRadians,
               std::numbers::pi / 2.0 - 1e-15, 100.0}),
          0.0);
      EXPECT_EQ(near.tile, (TileId{4, 25, 0}));
      EXPECT_EQ(near.terrainHeightMeters, 500.0);
    }
  }
}

TEST(Qotcd, AntimeridianFromEcef) {
  const terrain::HeightBlock east = makeBlock(kN, [](uint32_t i, uint32_t j) {
    return static_cast<int16_t>(100 * i + j);  // column 16 lies on +180 deg
  });
  const terrain::HeightBlock west = makeBlock(kN, [](uint32_t i, uint32_t j) {
    return static_cast<int16_t>(5000 + 100 * i + j);  // column 0 lies on -180 deg
  });
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  // ECEF (x < 0, y = +-0, z): longitude +pi or -pi depending on the sign of zero.
  for (double y : {0.0, -0.0}) {
    const glm::dvec3 camera = geo::cartographicToEcef(wgs84, {std::numbers::pi, 0.6, 10.0});
    const glm::dvec3 onMeridian{camera.x, y, camera.z};
    ASSERT_EQ(std::abs(std::atan2(onMeridian.y, onMeridian.x)), std::numbers::pi);
    RenderingTileArray onlyEast;
    onlyEast.assign({makeArrayTile({3, 15, 2}, east)});
    RenderingTileArray onlyWest;
    onlyWest.assign({makeArrayTile({3, 0, 2}, west)});
    RenderingTileArray both;
    both.assign({makeArrayTile({3, 15, 2}, east), makeArrayTile({3, 0, 2}, west)});
    for (Detector detect : kDetectors) {
      const QotcdResult e = detect(onlyEast, wgs84, onMeridian, 0.0);
      const QotcdResult w = detect(onlyWest, wgs84, onMeridian, 0.0);
      const QotcdResult bw = detect(both, wgs84, onMeridian, 0.0);
      ASSERT_TRUE(e.found && w.found && bw.found);
      EXPECT_EQ(e.longitudeRadians, -std::numbers::pi);  // canonical form
      EXPECT_EQ(e.tile, (TileId{3, 15, 2}));
      EXPECT_EQ(w.tile, (TileId{3, 0, 2}));
      EXPECT_EQ(bw.tile, (TileId{3, 0, 2}));  // x = 0 owns the meridian
      // Both read their +-180 deg column: 16 east, 0 west; the same grid row.
      const double row =
          (geo::GeographicTilingScheme::tileRectangle({3, 0, 2}).northRadians - 0.6) /
          (std::numbers::pi / 8.0) * 16.0;
      const auto i = static_cast<uint32_t>(std::floor(row));
      EXPECT_EQ(e.heightCase, HeightCase::RowOrColumn);
      EXPECT_EQ(e.terrainHeightMeters, 100.0 * (i + 1) + 16);
      EXPECT_EQ(w.terrainHeightMeters, 5000.0 + 100.0 * (i + 1));
      EXPECT_EQ(bw.terrainHeightMeters, w.terrainHeightMeters);
    }
  }
}

}  // namespace
}  // namespace globe::collision
