// TerrainScene with a 3D Tiles tileset (no GL): the collision array's overlay is the surface of
// the contents the frame draws; --tileset-clamp sets a tileset made at height 0 on the terrain
// (a 30 m box on Fuji's slope: its roof 30 m above the ground there, not 30 m above the
// ellipsoid inside the mountain).
#include <gtest/gtest.h>

#include <filesystem>

#include "geo/cartographic.hpp"
#include "scene/terrain_scene.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tests/tiles3d/box_tileset.hpp"
#include "tiles3d/tileset.hpp"

namespace globe::scene::tileset_scene_test {
namespace {

namespace fs = std::filesystem;
constexpr double kLonDeg = 138.70, kLatDeg = 35.40;  // Fuji's south-west flank

std::shared_ptr<const tiles3d::Tileset> boxOnTheEllipsoid(const fs::path& dir) {
  tiles3d::testing::writeFile(dir / "box.glb", tiles3d::testing::boxGlb(20, 20, 30));
  tiles3d::testing::writeFile(
      dir / "tileset.json",
      R"({"asset":{"version":"1.1"},"root":{"geometricError":0,"boundingVolume":{"sphere":[0,0,15,40]},"transform":)" +
          tiles3d::testing::transformJson(tiles3d::testing::eastNorthUp(kLonDeg, kLatDeg, 0)) +
          R"(,"content":{"uri":"box.glb"}}})");
  auto tileset = tiles3d::readTileset(dir);
  EXPECT_TRUE(tileset) << tileset.error();
  return std::make_shared<const tiles3d::Tileset>(std::move(*tileset));
}

// The roof collision reads under the box's centre, from a camera 200 m above the ground there
// looking straight down, once the view is complete.
std::optional<double> roofSeen(bool clamp, double* groundMeters) {
  const fs::path dir = globe::testing::freshTempDir("tileset-scene");
  SceneOptions options;
  options.tilesets = {boxOnTheEllipsoid(dir)};
  options.clampTilesets = clamp;
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return std::nullopt;
  const double lon = geo::degreesToRadians(kLonDeg), lat = geo::degreesToRadians(kLatDeg);
  auto ground = (*scene)->terrainHeightMeters(lon, lat);
  EXPECT_TRUE(ground) << ground.error();
  *groundMeters = ground ? *ground : 0;
  globe::testing::BookkeepingGpu gpu;
  camera::CameraPose pose;
  pose.position = {lon, lat, *groundMeters + 200};
  pose.pitchRadians = geo::degreesToRadians(-90);
  auto frame = (*scene)->updateUntilComplete(pose, 640, 360, gpu, std::chrono::seconds(60));
  EXPECT_TRUE(frame) << frame.error();
  if (frame) {
    EXPECT_EQ(frame->modelsDrawn, 1u);
  }
  const terrain::SurfaceOverlay* overlay = (*scene)->renderingTileArray().overlay();
  EXPECT_NE(overlay, nullptr);
  auto roof = overlay != nullptr ? overlay->heightAt(lon, lat) : std::nullopt;
  fs::remove_all(dir);
  return roof;
}

TEST(TilesetScene, ClampSetsABoxMadeAtHeightZeroOnTheTerrain) {
  double ground = 0;
  const auto above = roofSeen(false, &ground);
  ASSERT_TRUE(above.has_value());
  EXPECT_NEAR(*above, 30.0, 0.5);  // above the ellipsoid, as 3D Tiles says: inside the mountain
  ASSERT_GT(ground, 1000.0);
  const auto clamped = roofSeen(true, &ground);
  ASSERT_TRUE(clamped.has_value());
  EXPECT_NEAR(*clamped, ground + 30.0, 0.5);
}

}  // namespace
}  // namespace globe::scene::tileset_scene_test
