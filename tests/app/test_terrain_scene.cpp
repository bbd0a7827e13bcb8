// TerrainScene: the collision array always knows the ground under the camera, even when the
// camera looks at the horizon and its nadir is not drawn.
#include "app/terrain_scene.hpp"

#include <gtest/gtest.h>

#include "render/osmesa_context.hpp"
#include "tests/tools/tiler/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

TEST(TerrainScene, NadirTileJoinsTheCollisionArrayWhenNotDrawn) {
  auto context = render::OsMesaContext::create(320, 180);
  ASSERT_TRUE(context) << context.error();
  auto renderer = render::TerrainRenderer::create({});
  ASSERT_TRUE(renderer) << renderer.error();
  SceneOptions options;
  options.hysteresis = false;
  auto scene = TerrainScene::open(tiler::testing::bundledPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  // Level, looking north over Fuji's southern slope from 2,500 m: the ground below is out of view.
  const auto pose = camera::CameraPose::fromDegrees(138.60, 35.20, 2500, 0, 0, 0);
  auto frame = (*scene)->updateUntilComplete(pose, 320, 180, **renderer, std::chrono::seconds(60));
  ASSERT_TRUE(frame) << frame.error();
  const auto& array = (*scene)->renderingTileArray();
  const auto found =
      array.lookupIndexed(pose.position.longitudeRadians, pose.position.latitudeRadians);
  ASSERT_NE(found.tile, nullptr) << "collision must know the terrain under the camera";
  EXPECT_GE(found.tile->id.level, 10u);  // as fine as what is drawn around it
  bool drawn = false;
  for (const geo::TileId& tile : (*scene)->tiles()) drawn = drawn || tile == found.tile->id;
  EXPECT_FALSE(drawn) << "this view does not draw its nadir: the test needs that";
}

}  // namespace
}  // namespace globe::app
