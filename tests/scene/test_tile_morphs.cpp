// A finer tile that arrives late under the camera: with morphs (SceneOptions::morphFrames) the
// ground rises out of the coarser surface over a few frames and the controller lifts the camera
// a fraction of the difference per frame; without, the camera pops up by all of it in one frame.
// Real blocks of real DEMs (Fuji in the bundled pyramid, Zion's 1" DEM), the real controller.
#include "scene/tile_morphs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "camera/camera_controller.hpp"
#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "scene/terrain_scene.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/morphed_block.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "terrain/upsampled_block.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

using Block = std::shared_ptr<const terrain::HeightBlock>;
const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();

Block load(streaming::TileStore& store, const geo::TileId& tile) {
  auto block = store.loadBlock(tile);
  EXPECT_TRUE(block) << block.error();
  return block ? std::make_shared<const terrain::HeightBlock>(std::move(*block)) : nullptr;
}

// A parent tile and its four children, as a pyramid holds them.
struct Family {
  geo::TileId parent;
  Block parentBlock;
  std::array<geo::TileId, 4> children;
  std::array<Block, 4> childBlocks;
};

Family familyAt(streaming::TileStore& store, double lonDegrees, double latDegrees,
                uint32_t parentLevel) {
  Family f;
  f.parent = *geo::GeographicTilingScheme::positionToTile(
      lonDegrees * std::numbers::pi / 180, latDegrees * std::numbers::pi / 180, parentLevel);
  f.parentBlock = load(store, f.parent);
  f.children = f.parent.children();
  for (size_t i = 0; i < 4; ++i) f.childBlocks[i] = load(store, f.children[i]);
  return f;
}

// Where in the child tiles the finer ground stands highest above the parent's surface: a vertex
// of a child (on the parent's grid or between), with that rise.
struct Site {
  double longitudeRadians = 0, latitudeRadians = 0, riseMeters = 0;
};

Site highestRise(const Family& f) {
  Site best;
  for (size_t i = 0; i < 4; ++i) {
    const terrain::HeightBlock from =
        terrain::upsampleBlock(*f.parentBlock, f.children[i], kWgs84);
    const terrain::HeightBlock& to = *f.childBlocks[i];
    const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(f.children[i]);
    const uint32_t n = to.verticesPerSide;
    for (uint32_t row = 1; row + 1 < n; ++row) {  // inside: one tile holds the point
      for (uint32_t column = 1; column + 1 < n; ++column) {
        const double rise = to.surfaceHeightMetersAt(row, column) -
                            from.surfaceHeightMetersAt(row, column);
        if (rise <= best.riseMeters) continue;
        best = {r.westRadians + (r.eastRadians - r.westRadians) * column / (n - 1),
                r.northRadians - (r.northRadians - r.southRadians) * row / (n - 1), rise};
      }
    }
  }
  return best;
}

TEST(MorphBlock, BlendsTheSurfaceAndKeepsTheSamples) {
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const Family f = familyAt(**store, 138.7275, 35.3606, 9);  // Fuji's summit
  ASSERT_TRUE(f.parentBlock && f.childBlocks[0]);
  const terrain::HeightBlock from = terrain::upsampleBlock(*f.parentBlock, f.children[0], kWgs84);
  const terrain::HeightBlock& to = *f.childBlocks[0];
  ASSERT_TRUE(to.hasApron());
  const uint32_t n = to.verticesPerSide;
  for (double fraction : {0.0, 0.25, 1.0}) {
    const terrain::HeightBlock m = terrain::morphBlock(from, to, fraction);
    EXPECT_EQ(m.heights, to.heights) << "the samples (water flags) are the arriving block's";
    EXPECT_EQ(m.apron, to.apron);
    EXPECT_TRUE(m.shadingNormals.empty()) << "the mesh shades the blended surface";
    double largestGap = 0;
    for (uint32_t row = 0; row < n; ++row) {
      for (uint32_t column = 0; column < n; ++column) {
        const double a = from.surfaceHeightMetersAt(row, column);
        const double b = to.surfaceHeightMetersAt(row, column);
        EXPECT_NEAR(m.surfaceHeightMetersAt(row, column), a + fraction * (b - a), 1e-9);
        largestGap = std::max(largestGap, std::abs(b - a));
      }
    }
    EXPECT_GT(largestGap, 5.0) << "Fuji's summit: the finer tile differs from its parent";
    // The apron blends too, so the morphing tile's edge normals follow its own surface.
    const double a = from.surfaceHeightMetersWithApron(-1, -2);
    const double b = to.surfaceHeightMetersWithApron(-1, -2);
    EXPECT_NEAR(m.surfaceHeightMetersWithApron(-1, -2), a + fraction * (b - a), 1e-9);
  }
  // NaN counts as arrived; out of range is clamped.
  const terrain::HeightBlock nan = terrain::morphBlock(from, to, std::nan(""));
  const terrain::HeightBlock over = terrain::morphBlock(from, to, 7.0);
  EXPECT_EQ(nan.surfaceHeightMetersAt(3, 5), to.surfaceHeightMetersAt(3, 5));
  EXPECT_EQ(over.surfaceHeightMetersAt(3, 5), to.surfaceHeightMetersAt(3, 5));
  // Blocks of different sizes cannot blend: the arriving block as it is.
  terrain::HeightBlock small;
  small.verticesPerSide = 3;
  small.heights.assign(9, 100);
  EXPECT_EQ(terrain::morphBlock(small, to, 0.5).surfaceHeightMetersAt(4, 4),
            to.surfaceHeightMetersAt(4, 4));
}

// How the camera fares standing on the parent's surface where the finer ground rises most, when
// the children arrive: each frame the array holds the blocks TileMorphs hands out, and the
// controller (dt 0: the floor only, as after a view update) runs against it.
struct Landing {
  double riseMeters = 0;          // the finer ground above the parent's at the site
  double totalLiftMeters = 0;     // how far the camera went up in all
  double largestStepMeters = 0;   // in one frame
  int framesLifting = 0;          // frames that lifted it
  double lowestClearanceMeters = 1e9;  // eye above the array's surface, every frame
};

Landing landOnArrivingTiles(const Family& f, uint32_t morphFrames) {
  Landing out;
  const Site site = highestRise(f);
  out.riseMeters = site.riseMeters;
  TileMorphs morphs(morphFrames, kWgs84);
  terrain::RenderingTileArray array;
  // Frame 0: the parent drawn; the camera settles 2 m above it.
  (void)morphs.blockFor(f.parent, f.parentBlock, true);
  (void)morphs.endFrame();
  array.assign({terrain::makeArrayTile(f.parent, *f.parentBlock)});
  const auto parentSurface =
      collision::exactSurfaceHeight(array, kWgs84, site.longitudeRadians, site.latitudeRadians);
  camera::CameraPose pose;
  pose.position = {site.longitudeRadians, site.latitudeRadians, parentSurface->heightMeters + 2.0};
  pose.pitchRadians = -0.3;
  camera::CameraController controller(pose);
  controller.update(0.0, array, kWgs84);
  const double start = controller.pose().position.heightMeters;
  // The children arrive; the frames go on until the morphs are done.
  std::vector<Block> held;  // the array's blocks live as long as the array
  for (uint32_t frame = 0; frame < morphFrames + 2; ++frame) {
    std::vector<terrain::ArrayTile> tiles;
    held.clear();
    for (size_t i = 0; i < 4; ++i) {
      held.push_back(morphs.blockFor(f.children[i], f.childBlocks[i], true).block);
      tiles.push_back(terrain::makeArrayTile(f.children[i], *held.back()));
    }
    (void)morphs.endFrame();
    array.assign(std::move(tiles));
    const double before = controller.pose().position.heightMeters;
    controller.update(0.0, array, kWgs84);
    const double after = controller.pose().position.heightMeters;
    out.largestStepMeters = std::max(out.largestStepMeters, after - before);
    out.framesLifting += after - before > 1e-6 ? 1 : 0;
    const auto surface =
        collision::exactSurfaceHeight(array, kWgs84, site.longitudeRadians, site.latitudeRadians);
    out.lowestClearanceMeters = std::min(out.lowestClearanceMeters, after - surface->heightMeters);
  }
  out.totalLiftMeters = controller.pose().position.heightMeters - start;
  return out;
}

void expectLiftedOverFrames(const Family& f, const char* where) {
  SCOPED_TRACE(where);
  const Landing pop = landOnArrivingTiles(f, 0);
  ASSERT_GT(pop.riseMeters, 20.0) << "the site must rise enough to show a pop";
  // Without morphs: the whole rise in one frame (the failure this reproduces).
  EXPECT_EQ(pop.framesLifting, 1);
  EXPECT_NEAR(pop.largestStepMeters, pop.riseMeters, 0.05 * pop.riseMeters);

  constexpr uint32_t kFrames = 8;
  const Landing glide = landOnArrivingTiles(f, kFrames);
  EXPECT_NEAR(glide.totalLiftMeters, pop.totalLiftMeters, 0.01) << "the same ground in the end";
  EXPECT_GE(glide.framesLifting, static_cast<int>(kFrames) - 1);
  EXPECT_LE(glide.largestStepMeters, glide.totalLiftMeters / kFrames * 1.05 + 0.01);
  // The floor holds every frame: the camera is never under the surface it is drawn over.
  EXPECT_GE(glide.lowestClearanceMeters, 2.0 - 1e-6);
  EXPECT_GE(pop.lowestClearanceMeters, 2.0 - 1e-6);
}

TEST(TileMorphs, ACameraOnLateFinerGroundIsLiftedOverFramesNotPopped) {
  auto fuji = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(fuji) << fuji.error();
  expectLiftedOverFrames(familyAt(**fuji, 138.7275, 35.3606, 9), "Fuji, level 9 to 10");
  auto zion = streaming::TileStore::open(globe::testing::zionPyramid());
  ASSERT_TRUE(zion) << zion.error();
  expectLiftedOverFrames(familyAt(**zion, -112.95, 37.27, 11), "Zion Canyon, level 11 to 12");
}

TEST(TileMorphs, OnlyNewTilesNearTheCameraUnderADrawnAncestorMorph) {
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const Family f = familyAt(**store, 138.7275, 35.3606, 9);
  TileMorphs morphs(4, kWgs84);
  // Nothing drawn before: no surface to rise from.
  EXPECT_FALSE(morphs.blockFor(f.children[0], f.childBlocks[0], true).upload);
  (void)morphs.endFrame();
  (void)morphs.blockFor(f.parent, f.parentBlock, true);
  (void)morphs.endFrame();
  // Far from the camera: drawn as loaded. Near: the morph, uploaded every frame, then the block.
  const auto far = morphs.blockFor(f.children[1], f.childBlocks[1], false);
  EXPECT_EQ(far.block, f.childBlocks[1]);
  std::vector<bool> uploads;
  for (int frame = 0; frame < 5; ++frame) {
    if (frame > 0) (void)morphs.blockFor(f.children[1], f.childBlocks[1], false);
    const auto near = morphs.blockFor(f.children[2], f.childBlocks[2], true);
    uploads.push_back(near.upload);
    EXPECT_EQ(near.block == f.childBlocks[2], frame >= 3) << frame;
    EXPECT_EQ(morphs.active(), frame < 3 ? 1u : 0u) << frame;
    EXPECT_TRUE(morphs.endFrame().empty());
  }
  EXPECT_EQ(uploads, (std::vector<bool>{true, true, true, true, false}));
  // A tile that leaves the array half way and comes back goes on from where it was (a tile that
  // flickers near the camera must not pop); one that stays away `frames` frames is dropped and
  // named, its morph mesh to be released.
  (void)morphs.blockFor(f.parent, f.parentBlock, true);
  (void)morphs.endFrame();
  const auto first = morphs.blockFor(f.children[3], f.childBlocks[3], true);
  EXPECT_TRUE(first.upload);
  EXPECT_TRUE(morphs.endFrame().empty());
  EXPECT_TRUE(morphs.endFrame().empty());  // a frame without it
  const auto resumed = morphs.blockFor(f.children[3], f.childBlocks[3], true);
  const double a = first.block->surfaceHeightMetersAt(5, 5);
  const double b = f.childBlocks[3]->surfaceHeightMetersAt(5, 5);
  EXPECT_NEAR(resumed.block->surfaceHeightMetersAt(5, 5), a + (b - a) / 3, 1e-9)
      << "step 2 of 4 after step 1";
  EXPECT_TRUE(morphs.endFrame().empty());
  std::vector<geo::TileId> released;
  for (int frame = 0; frame < 4 && released.empty(); ++frame) released = morphs.endFrame();
  EXPECT_EQ(released, std::vector<geo::TileId>{f.children[3]});
  EXPECT_EQ(morphs.active(), 0u);
  // A tile only collided with (not drawn) morphs too, and never asks for an upload; a tile drawn
  // after it had been drawn as a morph gets its own mesh back.
  (void)morphs.blockFor(f.parent, f.parentBlock, true);
  (void)morphs.endFrame();
  const auto collided = morphs.blockFor(f.children[0], f.childBlocks[0], true, false);
  EXPECT_FALSE(collided.upload);
  EXPECT_NE(collided.block, f.childBlocks[0]);
  EXPECT_TRUE(morphs.endFrame().empty());
}

TEST(TileMorphs, NearMeansWithinTheRadiusOfTheNadir) {
  const geo::TileId tile{10, 1500, 300};
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
  const double midLatitude = 0.5 * (r.northRadians + r.southRadians);
  EXPECT_TRUE(TileMorphs::isNear(tile, r.westRadians + 1e-6, midLatitude, 0.0));
  // 1 km west of the west edge.
  const double kmInRadians = 1000.0 / 6371008.8 / std::cos(midLatitude);
  EXPECT_TRUE(TileMorphs::isNear(tile, r.westRadians - kmInRadians, midLatitude, 1100.0));
  EXPECT_FALSE(TileMorphs::isNear(tile, r.westRadians - kmInRadians, midLatitude, 900.0));
  // Across the antimeridian: the short way round.
  const geo::TileId east{3, 15, 3};
  const geo::GlobeRectangle e = geo::GeographicTilingScheme::tileRectangle(east);
  EXPECT_NEAR(e.eastRadians, std::numbers::pi, 1e-12);
  EXPECT_TRUE(TileMorphs::isNear(east, -std::numbers::pi + 1e-5, e.southRadians + 0.01, 100.0));
}

// The scene end to end (no GL): after a jump down to Fuji's flank the tiles under the camera are
// asked for first, finer tiles near the camera arrive as morphs, and the view is complete only
// when they are done, with the loaded blocks drawn.
TEST(TileMorphs, TheSceneLoadsTheNadirFirstAndMorphsWhatArrivesNearIt) {
  SceneOptions options;
  options.hysteresis = false;
  options.loaderThreads = 1;
  options.morphFrames = 6;
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  globe::testing::BookkeepingGpu gpu;
  const auto high = camera::CameraPose::fromDegrees(138.70, 35.30, 60000, 0, -89, 0);
  ASSERT_TRUE((*scene)->updateUntilComplete(high, 640, 360, gpu, std::chrono::seconds(60)));
  // Low over the flank, looking at the horizon: the nadir is not even drawn.
  const auto low = camera::CameraPose::fromDegrees(138.745, 35.345, 3200, 0, -50, 0);
  // The first frame at the new pose: the tiles under the camera below the finest one loaded
  // there, a few levels deep (a descent needs them next), are on their way at once, at the
  // highest priority, before the view's refinement has reached them.
  const streaming::TileLoader& loader = (*scene)->loader();
  uint32_t loadedLevel = 0;
  for (uint32_t level = 0; level <= (*scene)->store().manifest().maxLevel(); ++level) {
    if (loader.isResident(*geo::GeographicTilingScheme::positionToTile(
            low.position.longitudeRadians, low.position.latitudeRadians, level))) {
      loadedLevel = level;
    }
  }
  (void)(*scene)->update(low, 640, 360, gpu);
  for (uint32_t level = loadedLevel + 1; level <= loadedLevel + 3; ++level) {
    const auto tile = *geo::GeographicTilingScheme::positionToTile(
        low.position.longitudeRadians, low.position.latitudeRadians, level);
    EXPECT_TRUE(loader.state(tile) == streaming::TileState::Loading ||
                loader.state(tile) == streaming::TileState::Resident)
        << geo::tileName(tile);
  }
  size_t mostMorphing = 0;
  for (int frame = 0; frame < 2000; ++frame) {
    const FrameInfo info = (*scene)->update(low, 640, 360, gpu);
    mostMorphing = std::max(mostMorphing, info.morphing);
    if (info.complete) break;
    if (info.morphing == 0) (*scene)->waitForLoads(std::chrono::milliseconds(50));
  }
  EXPECT_GT(mostMorphing, 0u) << "finer tiles arrived near the camera as morphs";
  // Complete: every drawn tile is the block the pyramid holds (no morph left half way).
  const terrain::RenderingTileArray& array = (*scene)->renderingTileArray();
  ASSERT_FALSE(array.tiles().empty());
  for (const terrain::ArrayTile& tile : array.tiles()) {
    auto loaded = (*scene)->store().loadBlock(tile.id);
    ASSERT_TRUE(loaded) << loaded.error();
    EXPECT_TRUE(tile.block->exactSurfaceMeters.empty()) << geo::tileName(tile.id);
    EXPECT_EQ(tile.block->heights, loaded->heights) << geo::tileName(tile.id);
  }
}

}  // namespace
}  // namespace globe::scene
