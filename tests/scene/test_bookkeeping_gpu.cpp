// The scene's GPU bookkeeping with no GL: every drawn tile is prepared on the TileGpu, tiles not
// drawn for a while are released once over the budget, and BookkeepingGpu counts bytes exactly.
#include "tests/support/bookkeeping_gpu.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "scene/terrain_scene.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

TEST(BookkeepingGpu, CountsMeshAndTextureBytesThroughReplaceAndRelease) {
  globe::testing::BookkeepingGpu gpu;
  terrain::TileMesh mesh;
  mesh.vertices.assign(1000, 0.0f);
  const geo::TileId a{3, 1, 2}, b{3, 2, 2};
  ASSERT_TRUE(gpu.prepareTile(a, mesh));
  ASSERT_TRUE(gpu.prepareTile(b, mesh));
  mesh.vertices.assign(10, 0.0f);
  ASSERT_TRUE(gpu.prepareTile(a, mesh));  // replaced, not added
  EXPECT_EQ(gpu.tilesResident(), 2u);
  EXPECT_EQ(gpu.bytesResident(), (1000u + 10u) * sizeof(float));
  EXPECT_TRUE(gpu.releaseTile(b));
  EXPECT_FALSE(gpu.releaseTile(b));
  EXPECT_FALSE(gpu.hasTile(b));
  EXPECT_FALSE(gpu.prepareTile(b, terrain::TileMesh{}));  // nothing to upload is refused

  const std::vector<uint8_t> rgba(4 * 4 * 4, 255);
  ASSERT_TRUE(gpu.prepareImageryTile(0, a, rgba, 4, 4));
  ASSERT_TRUE(gpu.prepareImageryTile(1, a, rgba, 4, 4));  // another layer: another texture
  EXPECT_EQ(gpu.imageryTilesResident(), 2u);
  EXPECT_EQ(gpu.imageryBytesResident(), 2u * 64u * 4u / 3u);
  EXPECT_FALSE(gpu.prepareImageryTile(0, b, rgba, 4, 5));  // wrong size
  EXPECT_TRUE(gpu.releaseImageryTile(0, a));
  EXPECT_TRUE(gpu.hasImageryTile(1, a));
  EXPECT_EQ(gpu.imageryBytesResident(), 64u * 4u / 3u);
}

// A flight over the bundled pyramid with a small GPU budget: what a frame draws is always on the
// GPU, and the GPU never holds more than the budget beyond that frame's own tiles.
TEST(BookkeepingGpu, TheSceneKeepsDrawnTilesResidentAndReleasesOldOnesOverTheBudget) {
  globe::testing::BookkeepingGpu gpu;
  SceneOptions options;
  options.hysteresis = false;
  options.gpuTileBudget = 60;
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  size_t largestFrame = 0;
  for (int step = 0; step < 8; ++step) {
    const auto pose =
        camera::CameraPose::fromDegrees(138.3 + 0.1 * step, 35.0 + 0.05 * step, 8000, 45, -30, 0);
    auto frame = (*scene)->updateUntilComplete(pose, 320, 180, gpu, std::chrono::seconds(60));
    ASSERT_TRUE(frame) << frame.error();
    const auto& tiles = (*scene)->tiles();
    ASSERT_FALSE(tiles.empty());
    largestFrame = std::max(largestFrame, tiles.size());
    for (const geo::TileId& tile : tiles) EXPECT_TRUE(gpu.hasTile(tile)) << step;
    EXPECT_LE(gpu.tilesResident(), std::max<size_t>(options.gpuTileBudget, tiles.size())) << step;
  }
  // The flight moved far enough to need more distinct tiles than the budget: some were released
  // and the later frames prepared others.
  EXPECT_GT(gpu.tilesPrepared(), options.gpuTileBudget);
  EXPECT_LT(largestFrame, gpu.tilesPrepared());
}

}  // namespace
}  // namespace globe::scene
