// Rendering speed, printed and not asserted: 300 real level-6 tiles at 1280×720 on llvmpipe.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <iostream>

#include "render/gl_loader.hpp"
#include "render/read_pixels.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

TEST(RenderSpeed, ThreeHundredTilesAt1280x720) {
  constexpr int kW = 1280, kH = 720;
  auto context = OsMesaContext::create(kW, kH);
  ASSERT_TRUE(context.ok()) << context.error();
  auto created = TerrainRenderer::create({});
  ASSERT_TRUE(created.ok()) << created.error();
  std::unique_ptr<TerrainRenderer> renderer = std::move(*created);
  // 20 × 15 level-6 tiles (2.8125° each) around Japan.
  const auto tiles = loadTiles(6, 110.0, 14.5, 165.0, 56.0);
  ASSERT_EQ(tiles.size(), 300u);
  for (const LoadedTile& tile : tiles) {
    const double skirt = terrain::recommendedSkirtDepthMeters(6, 17, kWgs84);
    ASSERT_TRUE(
        renderer->uploadTile(tile.id, terrain::buildTileMesh(tile.id, tile.block, kWgs84, skirt))
            .ok());
  }
  const LocalFrame frame = localFrame(138.0, 35.0);
  const terrain::RenderView view =
      lookDownView(138.0, 35.0, 5.0e6, 40.0, kW, kH, frame.up + frame.east);
  const std::vector<geo::TileId> ids = idsOf(tiles);

  using Clock = std::chrono::steady_clock;
  // Wall time, and CPU time of all threads (llvmpipe's included): the latter is steadier on a
  // machine shared with other work.
  auto cpuMilliseconds = [] {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    auto ms = [](const timeval& t) {
      return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_usec) / 1e3;
    };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
  };
  struct Timing {
    double wallMs, cpuMs;
    FrameStats stats;
  };
  auto timeFrames = [&](int frames) {
    const auto start = Clock::now();
    const double cpuStart = cpuMilliseconds();
    FrameStats stats;
    for (int k = 0; k < frames; ++k) {
      stats = renderer->draw(view, ids);
      finishGl();
    }
    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return Timing{wall / frames, (cpuMilliseconds() - cpuStart) / frames, stats};
  };
  const Timing first = timeFrames(1);
  const Timing steady = timeFrames(30);
  const FrameStats& stats = steady.stats;
  const Image image = readImage(kW, kH);
  savePng(image, "speed_japan_300_tiles_1280x720");
  EXPECT_GT(image.countNonBackground(), kW * kH / 2);
  EXPECT_EQ(stats.tilesDrawn, 300u);
  std::cout << "[render speed] " << currentGlInfo().renderer << ": " << stats.tilesDrawn
            << " tiles, " << stats.triangles << " triangles (skirts included), " << kW << "x" << kH
            << ": first frame " << first.wallMs << " ms, then " << steady.wallMs
            << " ms/frame wall (mean of 30), " << steady.cpuMs << " ms/frame CPU (all threads), "
            << stats.gpuBytesResident / 1024 << " KiB on the GPU\n";
}

}  // namespace
}  // namespace globe::render::test
