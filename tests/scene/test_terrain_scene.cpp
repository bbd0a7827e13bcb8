// TerrainScene: the collision array always knows the ground under the camera, even when the
// camera looks at the horizon and its nadir is not drawn; SceneOptions::sea picks the water
// surface or the sea floor as the ground; imagery layers keep the terrain refining only where
// that sharpens them.
#include "scene/terrain_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

// The tiles a scene draws for a pose once everything it wants is loaded (no GL), and where its
// layers kept the nominal refinement.
std::vector<geo::TileId> drawnTiles(const std::filesystem::path& pyramid,
                                    const std::vector<LayerOptions>& layers, bool measuredLod,
                                    const camera::CameraPose& pose,
                                    std::vector<terrain::NominalErrorRegion>* regions = nullptr) {
  globe::testing::BookkeepingGpu gpu;
  SceneOptions options;
  options.hysteresis = false;
  options.layers = layers;
  options.measuredLod = measuredLod;
  auto scene = TerrainScene::open(pyramid, options);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  auto frame = (*scene)->updateUntilComplete(pose, 640, 360, gpu, std::chrono::seconds(120));
  EXPECT_TRUE(frame) << frame.error();
  if (regions != nullptr) {
    regions->assign((*scene)->nominalErrorRegions().begin(), (*scene)->nominalErrorRegions().end());
  }
  return (*scene)->tiles();
}

// The tiles that refine by the nominal error under the regions (their ancestors do too).
std::vector<geo::TileId> underNominal(const std::vector<geo::TileId>& tiles,
                                      const std::vector<terrain::NominalErrorRegion>& regions) {
  std::vector<geo::TileId> kept;
  for (const geo::TileId& tile : tiles) {
    const geo::GlobeRectangle rectangle = geo::GeographicTilingScheme::tileRectangle(tile);
    for (const terrain::NominalErrorRegion& region : regions) {
      if (tile.level <= region.throughLevel && region.rectangle.intersects(rectangle)) {
        kept.push_back(tile);
        break;
      }
    }
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// Imagery takes its level from the terrain tile's (terrain/imagery_level.hpp), so under a layer
// the terrain refines by the nominal error as far as that sharpens the imagery, and by the
// tiler's measured error beyond. The 5400-wide Blue Marble has nothing finer than level 4
// (~5 km a texel): over Fuji it changes nothing, the terrain draws exactly what it draws without
// imagery (before, any layer meant the nominal error everywhere: many more tiles). The Landsat
// scene over Zion is 30 m: down to the level whose children still get finer imagery, the
// terrain refines as with the nominal error; beyond it, by the measured error again.
TEST(TerrainScene, ImageryKeepsTheTerrainRefiningOnlyWhereThatSharpensIt) {
  const auto fuji = camera::CameraPose::fromDegrees(138.60, 35.20, 6000, 30, -15, 0);
  const std::vector<LayerOptions> blueMarble{{globe::testing::blueMarbleLayer(), 1.0f}};
  const auto measured = drawnTiles(globe::testing::bundledPyramid(), {}, true, fuji);
  const auto nominal = drawnTiles(globe::testing::bundledPyramid(), {}, false, fuji);
  ASSERT_LT(measured.size() * 10, nominal.size() * 8) << "the view needs measured errors to matter";
  EXPECT_EQ(drawnTiles(globe::testing::bundledPyramid(), blueMarble, true, fuji), measured);

  const auto zion = camera::CameraPose::fromDegrees(-112.98, 37.25, 3500, 330, -20, 0);
  const std::vector<LayerOptions> landsat{{globe::testing::zionLayer(), 1.0f}};
  const auto zionMeasured = drawnTiles(globe::testing::zionPyramid(), {}, true, zion);
  const auto zionNominal = drawnTiles(globe::testing::zionPyramid(), {}, false, zion);
  ASSERT_NE(zionMeasured, zionNominal);
  std::vector<terrain::NominalErrorRegion> regions;
  const auto zionLandsat = drawnTiles(globe::testing::zionPyramid(), landsat, true, zion, &regions);
  ASSERT_EQ(regions.size(), 1u);
  const auto nominalPart = underNominal(zionLandsat, regions);
  EXPECT_GT(nominalPart.size(), 20u) << "the view needs the layer's region to matter";
  EXPECT_EQ(nominalPart, underNominal(zionNominal, regions));
  EXPECT_GT(zionLandsat.size(), zionMeasured.size()) << "sharper imagery wants finer terrain";
  // A layer drawn at opacity 0 shows nothing and refines nothing.
  const std::vector<LayerOptions> hidden{{globe::testing::zionLayer(), 0.0f}};
  EXPECT_EQ(drawnTiles(globe::testing::zionPyramid(), hidden, true, zion), zionMeasured);
}

TEST(TerrainScene, NadirTileJoinsTheCollisionArrayWhenNotDrawn) {
  globe::testing::BookkeepingGpu gpu;
  SceneOptions options;
  options.hysteresis = false;
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  // Level, looking north over Fuji's southern slope from 2,500 m: the ground below is out of view.
  const auto pose = camera::CameraPose::fromDegrees(138.60, 35.20, 2500, 0, 0, 0);
  auto frame = (*scene)->updateUntilComplete(pose, 320, 180, gpu, std::chrono::seconds(60));
  ASSERT_TRUE(frame) << frame.error();
  const auto& array = (*scene)->renderingTileArray();
  const auto found =
      array.lookupIndexed(pose.position.longitudeRadians, pose.position.latitudeRadians);
  ASSERT_NE(found.tile, nullptr) << "collision must know the terrain under the camera";
  EXPECT_GE(found.tile->id.level, 10u);  // as fine as what is drawn around it
  bool drawn = false;
  for (const geo::TileId& tile : (*scene)->tiles()) drawn = drawn || tile == found.tile->id;
  EXPECT_FALSE(drawn) << "this view does not draw its nadir: the test needs that";
  EXPECT_FALSE(found.tile->drawn) << "flagged as collision-only";
  for (const terrain::ArrayTile& tile : array.tiles()) {
    if (&tile != found.tile) {
      EXPECT_TRUE(tile.drawn);
    }
  }
}

// SceneOptions::sea reaches every block the scene reads: the height under the camera here (the
// near plane's), the drawn tiles and the collision array alike (they share the scene's store).
TEST(TerrainScene, TheSeaOptionChoosesTheGroundOverWater) {
  namespace sea = testing;
  const auto pyramid = globe::testing::freshTempDir("scene-sea") / "pyramid";
  ASSERT_TRUE(sea::writeSeaTestPyramid(pyramid));
  const auto open = sea::cellCentreDegrees(sea::kSeaTile, 7, 7);
  const auto below = sea::cellCentreDegrees(sea::kMixedTile, 6, 9);
  for (const terrain::SeaSurface surface :
       {terrain::SeaSurface::Water, terrain::SeaSurface::SeaFloor}) {
    SceneOptions options;
    options.sea = surface;
    auto scene = TerrainScene::open(pyramid, options);
    ASSERT_TRUE(scene) << scene.error();
    EXPECT_EQ((*scene)->store().sea(), surface);
    auto water = (*scene)->terrainHeightMeters(geo::degreesToRadians(open.longitude),
                                               geo::degreesToRadians(open.latitude));
    ASSERT_TRUE(water) << water.error();
    EXPECT_EQ(*water, surface == terrain::SeaSurface::Water ? 0.0 : sea::kSeaFloorMeters);
    auto land = (*scene)->terrainHeightMeters(geo::degreesToRadians(below.longitude),
                                              geo::degreesToRadians(below.latitude));
    ASSERT_TRUE(land) << land.error();
    EXPECT_EQ(*land, sea::kMixedLandBelowSeaLevelMeters);
  }
}

}  // namespace
}  // namespace globe::scene
