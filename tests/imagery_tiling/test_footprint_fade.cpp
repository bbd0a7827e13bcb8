// Which footprint edges fade: a scene alone on all four sides, the members of a mosaic of like
// resolution nowhere, a whole-globe raster not at ±180° or the poles, pixel-is-area layers
// nowhere; and the fade itself, smoothstep over 4 pixels to the nearest fading edge.
#include "imagery_tiling/footprint_fade.hpp"

#include <gtest/gtest.h>

#include <vector>

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

}  // namespace
}  // namespace globe::imagery_tiling
