// TerrainScene over a real nginx on 127.0.0.1: the frame never waits on the server (pack indexes
// and blocks are read on the loader's threads), and the completed view is the local one.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>

#include "scene/terrain_scene.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/network_settings.hpp"

namespace globe::scene {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 640, kHeight = 360;

camera::CameraPose fujiOblique() {
  return camera::CameraPose::fromDegrees(138.60, 35.20, 6000, 30, -15, 0);
}

// A network with its disk cache in `dir`, for the scene's options.
std::shared_ptr<transport::Network> networkCachingIn(const fs::path& dir) {
  transport::NetworkSettings settings;
  settings.cacheDirectory = dir;
  settings.http.stallTimeoutMs = 2000;
  settings.remote.attempts = 1;
  return std::make_shared<transport::Network>(settings);
}

TEST(RemoteScene, TheSameTilesAsLocal) {
  const fs::path site = globe::testing::freshTempDir("remote-scene");
  fs::create_directories(site / "www");
  fs::create_symlink(globe::testing::bundledPyramid(), site / "www" / "pyramid");
  auto server = globe::testing::NginxServer::start({site / "www", ""});
  ASSERT_TRUE(server);
  SceneOptions options;
  options.hysteresis = false;
  options.network = networkCachingIn(site / "cache");
  auto local = TerrainScene::open(globe::testing::bundledPyramid(), options);
  auto remote = TerrainScene::open(server->url("/pyramid"), options);
  ASSERT_TRUE(local && remote);
  globe::testing::BookkeepingGpu a, b;
  auto x =
      (*local)->updateUntilComplete(fujiOblique(), kWidth, kHeight, a, std::chrono::seconds(60));
  auto y =
      (*remote)->updateUntilComplete(fujiOblique(), kWidth, kHeight, b, std::chrono::seconds(60));
  ASSERT_TRUE(x && y);
  EXPECT_GT((*local)->tiles().size(), 50u);
  EXPECT_EQ((*local)->tiles(), (*remote)->tiles());
  fs::remove_all(site);
}

// Every pack below level 2 stalls (1 byte/s): each frame still returns at once, drawing the
// coarse levels it has; nothing is complete while the packs are on their way.
TEST(RemoteScene, AFrameNeverWaitsOnAStalledServer) {
  const fs::path site = globe::testing::freshTempDir("remote-stall");
  fs::create_directories(site / "www");
  fs::create_symlink(globe::testing::bundledPyramid(), site / "www" / "pyramid");
  std::string stalls;
  for (int level = 2; level <= 14; ++level) {
    stalls += "location /pyramid/L" + std::to_string(level) + "/ { limit_rate 1; }\n";
  }
  auto server = globe::testing::NginxServer::start({site / "www", stalls});
  ASSERT_TRUE(server);
  SceneOptions options;
  options.network = networkCachingIn(site / "cache");
  auto scene = TerrainScene::open(server->url("/pyramid"), options);
  ASSERT_TRUE(scene) << scene.error();
  globe::testing::BookkeepingGpu gpu;
  double slowest = 0;
  const auto start = std::chrono::steady_clock::now();
  FrameInfo info;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1500)) {
    const auto t0 = std::chrono::steady_clock::now();
    info = (*scene)->update(fujiOblique(), kWidth, kHeight, gpu);
    slowest = std::max(
        slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    (*scene)->waitForLoads(std::chrono::milliseconds(20));
  }
  EXPECT_LT(slowest, 0.25);  // a blocking read would take the whole stall (> 1.5 s)
  EXPECT_FALSE(info.complete);
  EXPECT_FALSE((*scene)->tiles().empty());  // the levels that arrived are drawn
  for (const geo::TileId& tile : (*scene)->tiles()) EXPECT_LE(tile.level, 2u);
  scene->reset();
  fs::remove_all(site);
}

}  // namespace
}  // namespace globe::scene
