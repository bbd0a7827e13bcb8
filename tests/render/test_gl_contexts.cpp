// Contexts: OSMesa gives a 3.3+ core context that renders, resizes and rejects bad sizes; a GLFW
// window does the same under a display (skipped without $DISPLAY, e.g. run under xvfb-run).
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "render/gl_loader.hpp"
#include "render/glfw_window_context.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "render/terrain_renderer.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

TEST(OsMesaContext, GivesACoreContextOfAtLeast33) {
  auto context = OsMesaContext::create(64, 48);
  ASSERT_TRUE(context.ok()) << context.error();
  const GlInfo info = currentGlInfo();
  EXPECT_TRUE(info.major > 3 || (info.major == 3 && info.minor >= 3)) << info.version;
  EXPECT_FALSE(info.renderer.empty());
  std::cout << "GL_VERSION " << info.version << ", GL_RENDERER " << info.renderer << "\n";
  EXPECT_EQ((*context)->widthPixels(), 64);
  EXPECT_EQ((*context)->heightPixels(), 48);
}

TEST(OsMesaContext, RejectsBadSizes) {
  for (const auto& [w, h] : {std::pair{0, 10}, std::pair{10, -1}, std::pair{100000, 10}}) {
    auto context = OsMesaContext::create(w, h);
    ASSERT_FALSE(context.ok());
    EXPECT_NE(context.error().find("out of range"), std::string::npos) << context.error();
  }
}

TEST(OsMesaContext, ResizeKeepsObjectsAndRendersAtTheNewSize) {
  auto context = OsMesaContext::create(32, 32);
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = TerrainRenderer::create({});
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  const auto tiles = loadTiles(1, -180, -90, 180, 90);
  ASSERT_EQ(tiles.size(), 8u);
  for (const LoadedTile& tile : tiles) {
    auto mesh = terrain::buildTileMesh(tile.id, tile.block, kWgs84, 0.0);
    ASSERT_FALSE((*renderer)->uploadTile(tile.id, mesh).ok());  // skirts expected
    mesh = terrain::buildTileMesh(tile.id, tile.block, kWgs84, 50000.0);
    ASSERT_TRUE((*renderer)->uploadTile(tile.id, mesh).ok());
  }
  ASSERT_TRUE((*context)->resize(200, 100).ok());
  EXPECT_EQ((*context)->widthPixels(), 200);
  EXPECT_FALSE((*context)->resize(0, 100).ok());
  const glm::dvec3 eye(3.0 * kWgs84.semiMajorAxisMeters, 0.0, 0.0);
  const terrain::RenderView view = terrain::makeLookAtView(
      eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1), geo::degreesToRadians(45.0), 200, 100, eye);
  const FrameStats stats = (*renderer)->draw(view, idsOf(tiles));
  EXPECT_EQ(stats.tilesDrawn, 8u);
  const std::vector<uint8_t> pixels = readPixelsRgba(200, 100);
  ASSERT_EQ(pixels.size(), 200u * 100u * 4u);
  const Image image{200, 100, pixels};
  // The globe is centred: the middle pixel is drawn, the corners are space.
  EXPECT_FALSE(image.isBackground(100, 50));
  EXPECT_TRUE(image.isBackground(0, 0));
  EXPECT_TRUE(image.isBackground(199, 99));
  (*renderer).reset();
}

// Under a display (DISPLAY set, e.g. `xvfb-run -a`), a real window renders the globe too.
TEST(GlfwWindowContext, RendersTheGlobeInAWindow) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || display[0] == '\0') GTEST_SKIP() << "no DISPLAY (try xvfb-run -a)";
  GlfwWindowOptions options;
  options.widthPixels = 320;
  options.heightPixels = 240;
  options.title = "globe render test";
  options.vsync = false;
  auto window = GlfwWindowContext::create(options);
  ASSERT_TRUE(window.ok()) << window.error();
  const GlInfo info = currentGlInfo();
  EXPECT_TRUE(info.major > 3 || (info.major == 3 && info.minor >= 3)) << info.version;
  auto renderer = TerrainRenderer::create({});
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  const auto tiles = loadTiles(2, -180, -90, 180, 90);
  for (const LoadedTile& tile : tiles) {
    const double skirt = terrain::recommendedSkirtDepthMeters(2, 17, kWgs84);
    ASSERT_TRUE(
        (*renderer)
            ->uploadTile(tile.id, terrain::buildTileMesh(tile.id, tile.block, kWgs84, skirt))
            .ok());
  }
  const int width = (*window)->framebufferWidthPixels();
  const int height = (*window)->framebufferHeightPixels();
  ASSERT_GT(width, 0);
  const glm::dvec3 eye(0.0, 3.0 * kWgs84.semiMajorAxisMeters, 0.0);
  const terrain::RenderView view = terrain::makeLookAtView(
      eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1), geo::degreesToRadians(45.0), width, height, eye);
  (*renderer)->draw(view, idsOf(tiles));
  const Image image = readImage(width, height);
  savePng(image, "glfw_window_globe");
  EXPECT_FALSE(image.isBackground(width / 2, height / 2));
  EXPECT_TRUE(image.isBackground(0, 0));
  (*window)->swapBuffers();
  (*window)->pollEvents();
  EXPECT_FALSE((*window)->shouldClose());
  (*window)->requestClose();
  EXPECT_TRUE((*window)->shouldClose());
  (*renderer).reset();
}

}  // namespace
}  // namespace globe::render::test
