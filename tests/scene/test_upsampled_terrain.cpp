// Terrain refined past the pyramid's data for imagery (SceneOptions::refineForImagery): over Zion
// the bundled pyramid has only the 20' world grid, the Landsat layer 30 m. The scene refines the
// terrain until each tile takes the imagery level its size calls for, and no further; collision
// reads the same surface as from the pyramid's own leaves; without the option the imagery stops
// at the leaves' level; where no layer is finer nothing is refined.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "scene/terrain_scene.hpp"
#include "streaming/tile_store.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

struct Drawn {
  std::vector<geo::TileId> tiles;
  std::vector<terrain::TileDrapes> drapes;
  uint32_t deepestLevel = 0;
};

// The deepest tile the pyramid holds at a place.
uint32_t pyramidLevelAt(streaming::TileStore& store, double lonDegrees, double latDegrees) {
  uint32_t deepest = 0;
  for (uint32_t level = 0; level <= store.manifest().maxLevel(); ++level) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(
        geo::degreesToRadians(lonDegrees), geo::degreesToRadians(latDegrees), level);
    auto entry = store.entry(*tile);
    if (entry && *entry) deepest = level;
  }
  return deepest;
}

const auto kZionLow = camera::CameraPose::fromDegrees(-112.98, 37.25, 4500, 330, -35, 0);

TEST(UpsampledTerrain, ImageryIsDrawnAtItsOwnResolutionOverTheWorldGrid) {
  const std::vector<LayerOptions> landsat{{globe::testing::zionLayer(), 1.0f}};
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const uint32_t leafLevel = pyramidLevelAt(**store, -112.98, 37.25);
  ASSERT_LE(leafLevel, 7u) << "the test needs a place with only the world grid";

  for (const bool refine : {true, false}) {
    globe::testing::BookkeepingGpu gpu;
    SceneOptions options;
    options.hysteresis = false;
    options.layers = landsat;
    options.refineForImagery = refine;
    auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
    ASSERT_TRUE(scene) << scene.error();
    auto frame = (*scene)->updateUntilComplete(kZionLow, 640, 360, gpu, std::chrono::seconds(60));
    ASSERT_TRUE(frame) << frame.error();
    uint32_t deepestTerrain = 0, deepestImagery = 0;
    const auto& tiles = (*scene)->tiles();
    const auto& drapes = (*scene)->drapes();
    ASSERT_EQ(tiles.size(), drapes.size());
    for (size_t i = 0; i < tiles.size(); ++i) {
      deepestTerrain = std::max(deepestTerrain, tiles[i].level);
      for (uint32_t k = 0; k < drapes[i].count; ++k) {
        deepestImagery = std::max(deepestImagery, drapes[i].layers[k].imageryTile.level);
        // A tile past the pyramid takes the imagery of the level its size calls for.
        if (tiles[i].level > leafLevel) {
          EXPECT_EQ(drapes[i].layers[k].imageryTile.level + 1, tiles[i].level);
        }
      }
    }
    if (refine) {
      EXPECT_GE(deepestTerrain, leafLevel + 5) << "30 m imagery over 20' terrain";
      EXPECT_GE(deepestImagery, leafLevel + 4);
      // Collision reads the surface the pyramid's leaves give, at points all over the view.
      std::vector<std::shared_ptr<const terrain::HeightBlock>> leaves;
      std::mt19937_64 random(7);
      double worst = 0;
      size_t checked = 0;
      for (size_t i = 0; i < tiles.size(); ++i) {
        if (tiles[i].level <= leafLevel) continue;
        const terrain::ArrayTile* drawn = nullptr;
        for (const terrain::ArrayTile& t : (*scene)->renderingTileArray().tiles()) {
          if (t.id == tiles[i]) drawn = &t;
        }
        ASSERT_NE(drawn, nullptr);
        geo::TileId leaf = tiles[i];
        while (leaf.level > leafLevel) leaf = leaf.parent();
        auto block = (*store)->loadBlock(leaf);
        ASSERT_TRUE(block) << block.error();
        const terrain::ArrayTile leafArray = terrain::makeArrayTile(leaf, *block);
        const auto rect = geo::GeographicTilingScheme::tileRectangle(tiles[i]);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int k = 0; k < 20; ++k) {
          const double lon = rect.westRadians + u(random) * rect.widthRadians();
          const double lat = rect.southRadians + u(random) * rect.heightRadians();
          const double a =
              collision::exactTileSurfaceHeight(leafArray, (*scene)->ellipsoid(), lon, lat)
                  .heightMeters;
          const double b =
              collision::exactTileSurfaceHeight(*drawn, (*scene)->ellipsoid(), lon, lat)
                  .heightMeters;
          worst = std::max(worst, std::abs(a - b));
          ++checked;
        }
      }
      EXPECT_GT(checked, 100u);
      EXPECT_LT(worst, 1.0) << "the upsampled tiles' surface is the leaves'";
    } else {
      EXPECT_LE(deepestTerrain, leafLevel);
      EXPECT_LT(deepestImagery, leafLevel);
    }
  }
}

// The Blue Marble is no finer than the world grid anywhere: nothing is refined past the pyramid.
TEST(UpsampledTerrain, NothingIsRefinedWhereNoLayerIsFiner) {
  globe::testing::BookkeepingGpu gpu;
  SceneOptions options;
  options.hysteresis = false;
  options.layers = {{globe::testing::blueMarbleLayer(), 1.0f}};
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  size_t upsampled = 0;
  for (;;) {
    const FrameInfo info = (*scene)->update(kZionLow, 640, 360, gpu);
    upsampled += info.upsampled;
    if (info.complete) break;
    (*scene)->waitForLoads(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(upsampled, 0u);
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(store);
  for (const geo::TileId& tile : (*scene)->tiles()) {
    auto entry = (*store)->entry(tile);
    ASSERT_TRUE(entry);
    EXPECT_TRUE(entry->has_value()) << geo::tileName(tile) << " is not the pyramid's";
  }
}

}  // namespace
}  // namespace globe::scene
