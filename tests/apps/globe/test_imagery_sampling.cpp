// Imagery magnified over a whole tile is drawn with the bilinear sampler (no per-fragment level
// of detail, render/terrain_renderer.hpp), which must draw the picture trilinear filtering draws:
// views rendered both ways in one context from one scene, over level ground (the same to the
// bit) and over Zion's cliffs (a few pixels differ).
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/globe/renderer_gpu.hpp"
#include "formats/image_io.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "tests/support/golden_compare.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

struct Difference {
  uint32_t drapes = 0, magnified = 0;
  // Of the bilinear picture against the trilinear one; differing: some channel off by > 2 levels.
  globe::testing::ImageDifference image;
};

// The view drawn with the bilinear sampler where magnified, and trilinear everywhere.
Difference compareSamplers(const char* name, const std::filesystem::path& pyramid,
                           const std::filesystem::path& layer, double lon, double lat,
                           double heightMeters, double headingDegrees, double pitchDegrees,
                           int width, int height) {
  Difference out;
  auto context = render::OsMesaContext::create(width, height);
  EXPECT_TRUE(context) << context.error();
  auto renderer = render::TerrainRenderer::create({});
  EXPECT_TRUE(renderer) << renderer.error();
  scene::SceneOptions options;
  options.hysteresis = false;
  options.layers = {{layer, 1.0f}};
  auto scene = scene::TerrainScene::open(pyramid, options);
  EXPECT_TRUE(scene) << scene.error();
  if (!context || !renderer || !scene) return out;
  RendererGpu gpu(**renderer, options);
  const auto pose =
      camera::CameraPose::fromDegrees(lon, lat, heightMeters, headingDegrees, pitchDegrees, 0);
  auto frame = (*scene)->updateUntilComplete(pose, width, height, gpu, std::chrono::seconds(120));
  EXPECT_TRUE(frame) << frame.error();
  if (!frame) return out;
  auto drawn = [&](bool bilinear) {
    render::TerrainStyle style = (*renderer)->style();
    style.bilinearWhereMagnified = bilinear;
    (*renderer)->setStyle(style);
    const render::FrameStats stats = gpu.draw(**scene);
    if (bilinear) {
      out.drapes = stats.drapesDrawn;
      out.magnified = stats.drapesMagnified;
    }
    return render::readPixelsRgba(width, height);
  };
  const formats::ImageRgba fast{width, height, drawn(true)}, exact{width, height, drawn(false)};
  out.image = globe::testing::compareImages(exact, fast, 2);
  if (const char* dir = std::getenv("GLOBE_TEST_IMAGE_DIR")) {  // to look at them
    const std::string base = std::string(dir) + "/" + name;
    (void)formats::writePngAtomically(base + "-bilinear.png", fast.pixels, width, height);
    (void)formats::writePngAtomically(base + "-trilinear.png", exact.pixels, width, height);
    (void)formats::writePngAtomically(base + "-diff.png", out.image.diffRgba, width, height);
  }
  std::printf(
      "%s: %u of %u drapes magnified; %.4f %% of the pixels differ by > 2 levels, largest %d, "
      "mean %.4f\n",
      name, out.magnified, out.drapes, 100.0 * out.image.differingFraction,
      out.image.largestChannelDifference, out.image.meanChannelDifference);
  return out;
}

// Zion's cliffs are steeper than the level ground the bound assumes: where they are seen edge-on
// trilinear filtering blends in coarser levels, the base level alone draws the face as a smooth
// stretch. Those pixels are few.
TEST(ImagerySampling, OnSteepTerrainOnlyCliffPixelsChange) {
  const auto& zion = globe::testing::zionLayer();
  // 9 km up looking down, and 4.5 km up looking north-west 20 deg down (the benchmark's views).
  for (const Difference& d : {compareSamplers("zion-nadir", globe::testing::zionPyramid(), zion,
                                              -112.98, 37.27, 9000, 0, -90, 1280, 720),
                              compareSamplers("zion-oblique", globe::testing::zionPyramid(), zion,
                                              -112.93, 37.16, 4500, 330, -20, 1280, 720)}) {
    EXPECT_GT(d.magnified, 0u) << "no drape took the bilinear sampler: the test shows nothing";
    EXPECT_LT(d.magnified, d.drapes) << "every drape magnified: trilinear was never needed";
    EXPECT_LE(d.image.differingFraction, 0.003);
    EXPECT_LT(d.image.meanChannelDifference, 0.05);
  }
}

// Level ground: 1,500 m everywhere over 3 x 3 degrees around Zion (a GeoTIFF made here with
// GDAL), over ETOPO20, tiled by the real tiler.
const std::filesystem::path& levelZionPyramid() {
  static const std::filesystem::path pyramid = [] {
    const auto dem = globe::testing::freshTempDir("level-dem") / "level-1500m.tif";
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    constexpr int kSize = 1080;  // 10 arc seconds
    GDALDataset* dataset = driver->Create(dem.c_str(), kSize, kSize, 1, GDT_Int16, nullptr);
    EXPECT_NE(dataset, nullptr);
    if (dataset == nullptr) return std::filesystem::path{};
    std::array<double, 6> transform{-114.5, 3.0 / kSize, 0.0, 38.8, 0.0, -3.0 / kSize};
    EXPECT_EQ(dataset->SetGeoTransform(transform.data()), CE_None);
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    EXPECT_EQ(dataset->SetSpatialRef(&wgs84), CE_None);
    std::vector<int16_t> heights(size_t{kSize} * kSize, 1500);
    EXPECT_EQ(dataset->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, kSize, kSize, heights.data(),
                                                  kSize, kSize, GDT_Int16, 0, 0),
              CE_None);
    GDALClose(dataset);
    return globe::testing::tilePyramid(
        "level-zion", {globe::testing::bundledData("data/dem/ETOPO20.DEM").string(), dem.string()});
  }();
  return pyramid;
}

// On level ground, where the bound says magnified, trilinear filtering samples the base level
// too: the pictures are the same to the bit. Looking 45 deg down from 2 km, the top of the view
// (~11 km away) is minified and keeps the trilinear sampler.
TEST(ImagerySampling, OnLevelGroundThePictureIsTheSame) {
  const auto& zion = globe::testing::zionLayer();
  const auto& level = levelZionPyramid();
  for (const Difference& d :
       {compareSamplers("level-nadir", level, zion, -112.98, 37.27, 5000, 0, -90, 1280, 720),
        compareSamplers("level-oblique", level, zion, -113.0, 37.2, 6000, 0, -25, 1280, 720)}) {
    EXPECT_GT(d.magnified, 0u);
    EXPECT_EQ(d.image.largestChannelDifference, 0);
  }
}

}  // namespace
}  // namespace globe::app
