// A short soak of scripted playback (the globe-soak tool's loop): the bundled Fuji flight looped
// ~40 times through `globe play`'s per-frame step with a block budget and a GPU tile budget far
// below what one loop touches, so blocks and meshes are evicted and loaded again every loop.
#include "tools/soak/playback_soak.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
constexpr int64_t kFrames = 705;  // 5 loops: ASan's slower and keeps freed memory quarantined
#else
constexpr bool kSanitized = false;
constexpr int64_t kFrames = 5640;  // 40 loops, ~3.5 s
#endif

TEST(PlaybackSoak, LoopsWithoutDriftWithinTheBudgetsAndWithFlatMemory) {
  soak::SoakOptions options;
  options.pyramid = globe::testing::bundledPyramid();
  options.pathFile = std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-demo.json";
  options.frames = kFrames;
  options.framesPerSecond = 5;  // the 28 s flight in 141 frames
  options.widthPixels = 320;
  options.heightPixels = 180;
  options.scene.cacheBudgetBytes = 350 << 10;  // one loop touches ~560 blocks (~0.45 MiB)
  options.scene.gpuTileBudget = 300;           // and ~545 meshes
  options.memorySampleFrames = 50;
  options.checkpoints = {141, 282};
  const auto report = soak::runSoak(options);
  ASSERT_TRUE(report) << report.error();
  EXPECT_EQ(report->framesPerLoop, 141);
  ASSERT_EQ(report->checkpoints.size(), 3u);
  const soak::SoakCheckpoint& firstLoop = report->checkpoints[0];
  const soak::SoakCheckpoint& secondLoop = report->checkpoints[1];
  const soak::SoakCheckpoint& last = report->checkpoints.back();
  EXPECT_EQ(last.frames, kFrames);

  // Frame k + 141 shows exactly frame k's pose, every loop: no drift at all.
  EXPECT_EQ(last.framesDrifted, 0);
  EXPECT_EQ(last.maximumDriftMeters, 0.0);
  EXPECT_EQ(last.maximumDriftRadians, 0.0);
  // The flight dives into Fuji: the controller lifts the camera (the glide, and the response
  // where it collides), and as often in every loop.
  EXPECT_GT(firstLoop.responseFrames, 0);
  EXPECT_EQ(secondLoop.responseFrames, 2 * firstLoop.responseFrames);
  EXPECT_EQ(last.responseFrames, kFrames / 141 * firstLoop.responseFrames);
  EXPECT_EQ(secondLoop.collisionFrames, 2 * firstLoop.collisionFrames);
  EXPECT_EQ(last.collisionFrames, kFrames / 141 * firstLoop.collisionFrames);
  EXPECT_GE(last.minimumClearanceMeters, 2.0 - 1e-6);  // the floor: the eye clearance

  // The budgets hold while blocks and meshes are evicted and loaded again every loop.
  EXPECT_GT(last.cache.evictions, kFrames / 141 * 50);
  EXPECT_GT(last.loader.completed, secondLoop.loader.completed);
  EXPECT_LE(last.cache.peakResidentBytes,
            std::max(last.cacheBudgetBytes, last.cache.peakPinnedBytes));
  EXPECT_LE(last.cache.peakPinnedBytes, last.cacheBudgetBytes);  // so within the budget
  EXPECT_LE(last.gpuTiles, 300u + 300u);  // evicted down to the budget, or the tiles drawn now

  // Memory after the first loop stays flat: no leak per frame or per reload. (Not under ASan:
  // its quarantine holds freed memory back on purpose.)
  ASSERT_GT(last.residentAfterFirstLoopBytes, 0u);
  if (!kSanitized) {
    EXPECT_LE(last.maximumResidentAfterFirstLoopBytes,
              last.residentAfterFirstLoopBytes + (4u << 20))
        << "VmRSS grew from " << last.residentAfterFirstLoopBytes << " B after the first loop";
  }
}

TEST(PlaybackSoak, RefusesBadOptionsAndPaths) {
  soak::SoakOptions options;
  options.pyramid = "/nonexistent-pyramid";
  options.pathFile = std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-demo.json";
  options.framesPerSecond = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(soak::runSoak(options));
  options.framesPerSecond = 30;
  options.frames = 0;
  EXPECT_FALSE(soak::runSoak(options));
  options.frames = 10;
  options.pathFile = std::string(GLOBE_SOURCE_DIR) + "/data/paths/none.json";
  const auto missing = soak::runSoak(options);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("none.json"), std::string::npos) << missing.error();
  options.pathFile = std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-demo.json";
  const auto noPyramid = soak::runSoak(options);
  ASSERT_FALSE(noPyramid);
  EXPECT_NE(noPyramid.error().find("nonexistent-pyramid"), std::string::npos) << noPyramid.error();
}

}  // namespace
}  // namespace globe::app
