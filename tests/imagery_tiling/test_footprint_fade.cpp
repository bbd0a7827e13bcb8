// Which footprint edges fade: a scene alone on all four sides, the members of a mosaic of like
// resolution nowhere, a whole-globe raster not at ±180° or the poles, pixel-is-area layers
// nowhere; and the fade itself, smoothstep over 4 pixels to the nearest fading edge, and to the
// nearest no-data pixel of a scene's irregular collar.
#include "imagery_tiling/footprint_fade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/imagery_tiling/imagery_test_support.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::imagery_tiling {
namespace {

ImageryInput raster(formats::BoundsDegrees extent, double pixelDegrees) {
  ImageryInput input;
  input.kind = ImageryInput::Kind::Raster;
  input.pixelGrid = formats::ImageryPixelGrid::Edges;
  input.extent = extent;
  input.pixelDegrees = pixelDegrees;
  return input;
}

TEST(FootprintFade, OnlyTheLayersOuterEdgesFade) {
  const std::array<bool, 4> all{true, true, true, true}, none{};
  std::vector<ImageryInput> alone{raster({-113.2, 37.1, -112.8, 37.5}, 0.0003)};
  chooseFootprintFades(alone);
  EXPECT_EQ(alone[0].fadeEdges, all);

  // Two scenes of like resolution side by side (a mosaic): neither fades. A much coarser one
  // under them (the world) does not stop them fading.
  std::vector<ImageryInput> mosaic{raster({-100.0, 47.0, -99.5, 47.5}, 0.0001),
                                   raster({-99.5, 47.0, -99.0, 47.5}, 0.00012),
                                   raster({-101.0, 46.0, -98.0, 48.0}, 0.01)};
  chooseFootprintFades(mosaic);
  EXPECT_EQ(mosaic[0].fadeEdges, none);
  EXPECT_EQ(mosaic[1].fadeEdges, none);
  EXPECT_EQ(mosaic[2].fadeEdges, all);

  std::vector<ImageryInput> world{raster({-180, -90, 180, 90}, 0.0667)};
  chooseFootprintFades(world);
  EXPECT_EQ(world[0].fadeEdges, none);
  std::vector<ImageryInput> band{raster({-180, -60, 180, 60}, 0.0667)};
  chooseFootprintFades(band);
  EXPECT_EQ(band[0].fadeEdges, (std::array<bool, 4>{false, false, true, true}));

  std::vector<ImageryInput> area{raster({-113.2, 37.1, -112.8, 37.5}, 0.0003)};
  area[0].pixelGrid = formats::ImageryPixelGrid::Area;
  chooseFootprintFades(area);
  EXPECT_EQ(area[0].fadeEdges, none);
}

TEST(FootprintFade, SmoothstepOverFourPixelsToTheNearestFadingEdge) {
  ImageryInput input = raster({0, 0, 1, 1}, 0.01);
  input.fadeEdges = {true, false, false, false};  // only x = 0 fades
  EXPECT_DOUBLE_EQ(footprintFade(input, 0.0, 50, 100, 100), 0.0);
  EXPECT_DOUBLE_EQ(footprintFade(input, 2.0, 50, 100, 100), 0.5);
  EXPECT_DOUBLE_EQ(footprintFade(input, 4.0, 50, 100, 100), 1.0);
  EXPECT_DOUBLE_EQ(footprintFade(input, 99.5, 0.0, 100, 100), 1.0);  // those edges do not fade
  input.fadeEdges = {};
  EXPECT_DOUBLE_EQ(footprintFade(input, 0.0, 0.0, 100, 100), 1.0);
}

TEST(FootprintFade, DistanceToTheNearestTransparentPixel) {
  // 9×5 opaque with one transparent pixel at (2, 2).
  std::vector<uint8_t> rgba(9 * 5 * 4, 255);
  rgba[(2 * 9 + 2) * 4 + 3] = 0;
  std::vector<float> d;
  distanceToTransparent(rgba, 9, 5, d);
  EXPECT_FLOAT_EQ(d[2 * 9 + 2], 0.0f);
  EXPECT_FLOAT_EQ(d[2 * 9 + 3], 1.0f);
  EXPECT_FLOAT_EQ(d[2 * 9 + 6], 4.0f);
  EXPECT_NEAR(d[3 * 9 + 3], std::sqrt(2.0), 0.1);  // diagonal, chamfer 4/3
  EXPECT_NEAR(d[4 * 9 + 8], std::hypot(6.0, 2.0), 0.5);
  std::vector<uint8_t> opaque(4 * 4 * 4, 255);
  distanceToTransparent(opaque, 4, 4, d);
  EXPECT_GT(*std::min_element(d.begin(), d.end()), 1e4f);
}

// A UTM Landsat crop whose scene sits in a no-data collar: at the finest level the alpha rises
// from 0 to 255 over ~4 source pixels along the collar, not over the one pixel of the bilinear
// filter, and is 255 wherever the collar is farther than the fade.
TEST(FootprintFade, AScenesNoDataCollarFades) {
  const auto dir = globe::testing::layerOf(
      {std::string(GLOBE_SOURCE_DIR) + "/tests/data/imagery/rgb_byte_utm18_crop.tif"},
      "collar-fade");
  auto store = globe::testing::openStore(dir);
  ASSERT_TRUE(store);
  const uint32_t finest = store->manifest().maxLevel();
  std::vector<int> ramps;  // per row crossing the collar: pixels strictly between 0 and 255
  size_t opaque = 0;
  for (const auto& [tile, image] : globe::testing::tilesOf(*store, finest)) {
    for (int r = 0; r < image.heightPixels; ++r) {
      auto alpha = [&](int c) { return image.pixels[(size_t(r) * image.widthPixels + c) * 4 + 3]; };
      for (int c = 1; c < image.widthPixels; ++c) {
        if (alpha(c - 1) != 0 || alpha(c) == 0) continue;  // the collar ends here (west to east)
        int end = c;
        while (end < image.widthPixels && alpha(end) < 255) ++end;
        if (end < image.widthPixels) ramps.push_back(end - c);
      }
      for (int c = 0; c < image.widthPixels; ++c) opaque += alpha(c) == 255 ? 1 : 0;
    }
  }
  ASSERT_GT(ramps.size(), 20u);
  ASSERT_GT(opaque, 1000u);
  std::nth_element(ramps.begin(), ramps.begin() + long(ramps.size() / 2), ramps.end());
  const int median = ramps[ramps.size() / 2];
  EXPECT_GE(median, 3) << "the collar still cuts";
  EXPECT_LE(median, 12) << "the fade reaches too far";
}

}  // namespace
}  // namespace globe::imagery_tiling
