// Imagery layers through the whole viewer frame (tiler → layer packs → loader → textures →
// OSMesa): colours land where they belong, a UTM image and its EPSG:4326 warp give the same
// picture, no-data is transparent, a tile draws its ancestor's texture while its own loads, and
// imagery tile edges leave no seam.
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <vector>

#include "apps/globe/renderer_gpu.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "render/imagery_textures.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using globe::testing::bundledData;
using Rgb = std::array<double, 3>;

struct Rendered {
  formats::ImageRgba image;
  scene::FrameInfo frame;
  size_t tilesDrawn = 0;
  size_t tilesDraped = 0;  // drawn with at least one imagery texture
  size_t tilesMasked = 0;  // drawn with a water mask tile
  uint32_t deepestImageryLevel = 0;
};

// A straight-down, north-up view `heightAboveGroundMeters` over the point, every tile and
// imagery tile loaded. Odd sizes put the nadir on the centre pixel.
Rendered renderNadir(const fs::path& pyramid, const std::vector<scene::LayerOptions>& layers,
                     double longitudeDegrees, double latitudeDegrees,
                     double heightAboveGroundMeters, int sizePixels,
                     uint32_t maximumImageryLoadLevel = geo::kMaxLevel) {
  Rendered out;
  auto context = render::OsMesaContext::create(sizePixels, sizePixels);
  EXPECT_TRUE(context) << context.error();
  if (!context) return out;
  auto renderer = render::TerrainRenderer::create({});
  EXPECT_TRUE(renderer) << renderer.error();
  scene::SceneOptions options;
  options.hysteresis = false;
  options.layers = layers;
  options.maximumImageryLoadLevel = maximumImageryLoadLevel;
  // The source's colours as they are: these tests look at where the imagery lands, not its light.
  options.imageryLighting = terrain::ImageryLighting::Off;
  auto scene = scene::TerrainScene::open(pyramid, options);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene || !renderer) return out;
  RendererGpu gpu(**renderer, options);
  auto ground = (*scene)->terrainHeightMeters(geo::degreesToRadians(longitudeDegrees),
                                              geo::degreesToRadians(latitudeDegrees));
  EXPECT_TRUE(ground) << ground.error();
  const auto pose = camera::CameraPose::fromDegrees(longitudeDegrees, latitudeDegrees,
                                                    *ground + heightAboveGroundMeters, 0, -90, 0);
  auto frame =
      (*scene)->updateUntilComplete(pose, sizePixels, sizePixels, gpu, std::chrono::seconds(120));
  EXPECT_TRUE(frame) << frame.error();
  if (!frame) return out;
  out.frame = *frame;
  out.tilesDrawn = (*scene)->tiles().size();
  for (const terrain::TileDrapes& drapes : (*scene)->drapes()) {
    out.tilesDraped += drapes.count > 0 ? 1 : 0;
    out.tilesMasked += drapes.hasWaterMask ? 1 : 0;
    for (uint32_t k = 0; k < drapes.count; ++k) {
      out.deepestImageryLevel =
          std::max(out.deepestImageryLevel, drapes.layers[k].imageryTile.level);
    }
  }
  gpu.draw(**scene);
  out.image = {sizePixels, sizePixels, render::readPixelsRgba(sizePixels, sizePixels)};
  return out;
}

// The mean colour of a (2r+1)² window around a pixel.
Rgb meanAround(const formats::ImageRgba& image, int column, int row, int radius) {
  Rgb sum{0, 0, 0};
  int n = 0;
  for (int y = row - radius; y <= row + radius; ++y) {
    for (int x = column - radius; x <= column + radius; ++x) {
      const size_t p = (static_cast<size_t>(y) * image.widthPixels + x) * 4;
      for (int c = 0; c < 3; ++c) sum[c] += image.pixels[p + c];
      ++n;
    }
  }
  for (double& v : sum) v /= n;
  return sum;
}

double largestChannelDifference(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// The source image read through GDAL itself (not the tiler): the mean colour of the source
// pixels within `radiusMeters` of a ground point, found with OGR in the image's own CRS.
class SourceImage {
 public:
  explicit SourceImage(const fs::path& path) {
    GDALAllRegister();
    dataset_.reset(GDALDataset::Open(path.c_str(), GA_ReadOnly));
    EXPECT_NE(dataset_, nullptr) << path;
    if (!dataset_) return;
    EXPECT_EQ(dataset_->GetGeoTransform(transform_.data()), CE_None);
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference target(*dataset_->GetSpatialRef());
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    toImage_.reset(OGRCreateCoordinateTransformation(&wgs84, &target));
  }
  Rgb meanAround(double longitudeDegrees, double latitudeDegrees, double radiusMeters) const {
    double x = longitudeDegrees, y = latitudeDegrees;
    EXPECT_TRUE(toImage_->Transform(1, &x, &y));
    // Projected CRS in metres or geographic in degrees: the window in pixels either way.
    const double metresPerUnit = dataset_->GetSpatialRef()->IsGeographic() ? 111320.0 : 1.0;
    const double column = (x - transform_[0]) / transform_[1];
    const double row = (y - transform_[3]) / transform_[5];
    const int radius = std::max(
        0, static_cast<int>(std::lround(radiusMeters / (std::abs(transform_[1]) * metresPerUnit))));
    const int c0 = static_cast<int>(std::floor(column)) - radius;
    const int r0 = static_cast<int>(std::floor(row)) - radius;
    const int side = 2 * radius + 1;
    std::vector<uint8_t> pixels(static_cast<size_t>(side) * side * 3);
    EXPECT_EQ(dataset_->RasterIO(GF_Read, c0, r0, side, side, pixels.data(), side, side, GDT_Byte,
                                 3, nullptr, 3, side * 3, 1, nullptr),
              CE_None);
    Rgb sum{0, 0, 0};
    for (size_t p = 0; p < pixels.size(); p += 3) {
      for (int c = 0; c < 3; ++c) sum[c] += pixels[p + c];
    }
    for (double& v : sum) v /= static_cast<double>(side) * side;
    return sum;
  }

 private:
  struct Close {
    void operator()(GDALDataset* d) const { GDALClose(d); }
  };
  std::unique_ptr<GDALDataset, Close> dataset_;
  std::array<double, 6> transform_{};
  std::unique_ptr<OGRCoordinateTransformation> toImage_;
};

// Points inside the Landsat scene over Zion: canyon floors, rims, slickrock, forest.
constexpr std::array<std::array<double, 2>, 6> kZionPoints{{{-112.95, 37.27},
                                                            {-112.98, 37.21},
                                                            {-113.02, 37.35},
                                                            {-112.90, 37.30},
                                                            {-113.10, 37.42},
                                                            {-112.93, 37.44}}};

TEST(ImageryScene, ColoursLandWhereTheSourcePixelsAre) {
  const SourceImage source(bundledData("data/imagery/zion-landsat8-rgb.tif"));
  const std::vector<scene::LayerOptions> layers{{globe::testing::zionLayer(), 1.0f}};
  // 3 km up, 65 px over 45°: ~38 m per pixel, so the centre 5×5 pixels average ~190 m of ground.
  int farFromShifted = 0;
  for (const auto& [lon, lat] : kZionPoints) {
    const Rendered view = renderNadir(globe::testing::zionPyramid(), layers, lon, lat, 3000, 65);
    ASSERT_FALSE(view.image.pixels.empty());
    EXPECT_GT(view.frame.imagery.drapes, 0u);
    EXPECT_EQ(view.frame.imagery.fallbacks, 0u);
    const Rgb drawn = meanAround(view.image, 32, 32, 2);
    const Rgb truth = source.meanAround(lon, lat, 95);
    EXPECT_LE(largestChannelDifference(drawn, truth), 14.0)
        << lon << "," << lat << ": drawn " << drawn[0] << " " << drawn[1] << " " << drawn[2]
        << ", source " << truth[0] << " " << truth[1] << " " << truth[2];
    // The comparison can tell places apart: 1.5 km away the source is usually another colour.
    const Rgb shifted = source.meanAround(lon + 0.017, lat, 95);
    if (largestChannelDifference(drawn, shifted) > 14.0) ++farFromShifted;
  }
  EXPECT_GE(farFromShifted, 3) << "the points are too uniform to show a misplaced image";
}

TEST(ImageryScene, AUtmImageAndItsGeographicWarpGiveTheSamePicture) {
  // The same scene warped by GDAL to EPSG:4326 beforehand (bilinear, ~30 m): the tiler's own
  // warp of the UTM original must draw the same picture.
  const fs::path warped = globe::testing::freshTempDir("zion-4326") / "zion-4326.tif";
  {
    GDALAllRegister();
    GDALDatasetH source =
        GDALOpen(bundledData("data/imagery/zion-landsat8-rgb.tif").c_str(), GA_ReadOnly);
    ASSERT_NE(source, nullptr);
    const char* arguments[] = {"-t_srs", "EPSG:4326", "-r",     "bilinear",
                               "-tr",    "0.0003",    "0.0003", nullptr};
    GDALWarpAppOptions* options = GDALWarpAppOptionsNew(const_cast<char**>(arguments), nullptr);
    int failed = 0;
    GDALDatasetH out = GDALWarp(warped.c_str(), nullptr, 1, &source, options, &failed);
    GDALWarpAppOptionsFree(options);
    ASSERT_NE(out, nullptr);
    ASSERT_EQ(failed, 0);
    GDALClose(out);
    GDALClose(source);
  }
  const auto& geographic = globe::testing::imageryLayer("zion-4326", warped.string());
  const std::vector<scene::LayerOptions> utm{{globe::testing::zionLayer(), 1.0f}};
  const std::vector<scene::LayerOptions> wgs{{geographic, 1.0f}};
  const Rendered a = renderNadir(globe::testing::zionPyramid(), utm, -112.98, 37.28, 12000, 129);
  const Rendered b = renderNadir(globe::testing::zionPyramid(), wgs, -112.98, 37.28, 12000, 129);
  ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
  double sum = 0;
  size_t large = 0;
  for (size_t p = 0; p < a.image.pixels.size(); p += 4) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int{a.image.pixels[p + c]} - int{b.image.pixels[p + c]});
      sum += d;
      worst = std::max(worst, d);
    }
    large += worst > 40 ? 1 : 0;
  }
  const double pixels = static_cast<double>(a.image.pixels.size() / 4);
  EXPECT_LE(sum / (3 * pixels), 5.0);
  EXPECT_LE(static_cast<double>(large) / pixels, 0.01);
}

// The longitude/latitude of a pixel centre of a georeferenced image, through OGR.
std::array<double, 2> pixelCentreDegrees(const fs::path& path, double column, double row) {
  GDALAllRegister();
  GDALDataset* dataset = GDALDataset::Open(path.c_str(), GA_ReadOnly);
  EXPECT_NE(dataset, nullptr) << path;
  if (dataset == nullptr) return {0, 0};
  std::array<double, 6> t{};
  EXPECT_EQ(dataset->GetGeoTransform(t.data()), CE_None);
  double x = t[0] + (column + 0.5) * t[1] + (row + 0.5) * t[2];
  double y = t[3] + (column + 0.5) * t[4] + (row + 0.5) * t[5];
  OGRSpatialReference source(*dataset->GetSpatialRef()), wgs84;
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> toDegrees(
      OGRCreateCoordinateTransformation(&source, &wgs84));
  EXPECT_TRUE(toDegrees && toDegrees->Transform(1, &x, &y));
  GDALClose(dataset);
  return {x, y};
}

// RGB.byte.tif's no-data collar (value 0, outside the scene) lets the terrain's own colours show:
// the same pixel as with no layer at all; inside the scene the image is drawn.
TEST(ImageryScene, NoDataIsTransparent) {
  const fs::path crop = bundledData("tests/data/imagery/rgb_byte_utm18_crop.tif");
  const auto& layer = globe::testing::imageryLayer("rgb-byte", crop.string());
  const std::vector<scene::LayerOptions> with{{layer, 1.0f}};
  const auto& pyramid = globe::testing::bundledPyramid();
  const auto collar = pixelCentreDegrees(crop, 40, 180);  // 40 px inside the collar
  const auto scene = pixelCentreDegrees(crop, 300, 200);  // 200 px inside the scene
  const SourceImage source(crop);
  for (const auto& [point, inside] : {std::pair{collar, false}, std::pair{scene, true}}) {
    const Rendered a = renderNadir(pyramid, with, point[0], point[1], 15000, 33);
    const Rendered b = renderNadir(pyramid, {}, point[0], point[1], 15000, 33);
    const Rgb drawn = meanAround(a.image, 16, 16, 1), plain = meanAround(b.image, 16, 16, 1);
    if (inside) {
      const Rgb truth = source.meanAround(point[0], point[1], 450);
      EXPECT_LE(largestChannelDifference(drawn, truth), 14.0);
      EXPECT_GT(largestChannelDifference(drawn, plain), 20.0) << "the image is not drawn";
    } else {
      EXPECT_LE(largestChannelDifference(drawn, plain), 2.0) << "no-data is not transparent";
    }
  }
}

// A water mask decides land and sea where the terrain's colours show; under a layer that covers
// the whole globe opaquely (the Blue Marble) they never do, and the mask is neither loaded, nor
// drawn, nor refined for: the same tiles and the same picture as without it.
TEST(ImageryScene, AWaterMaskUnderAnOpaqueWorldLayerIsNeitherLoadedNorDrawn) {
  const auto& pyramid = globe::testing::bundledPyramid();
  const std::vector<scene::LayerOptions> mask{{globe::testing::coastMask(), 1.0f}};
  const std::vector<scene::LayerOptions> world{{globe::testing::blueMarbleLayer(), 1.0f}};
  const std::vector<scene::LayerOptions> both{world[0], mask[0]};
  // The Wash from 60 km: the mask's full-resolution box over the GTOPO30 crop and the grid.
  const Rendered alone = renderNadir(pyramid, mask, 0.3, 52.9, 60000, 65);
  const Rendered under = renderNadir(pyramid, both, 0.3, 52.9, 60000, 65);
  const Rendered plain = renderNadir(pyramid, world, 0.3, 52.9, 60000, 65);
  EXPECT_GT(alone.tilesMasked, 0u);
  EXPECT_EQ(under.tilesMasked, 0u);
  EXPECT_EQ(under.tilesDrawn, plain.tilesDrawn) << "refined for a mask that cannot show";
  EXPECT_EQ(under.image.pixels, plain.image.pixels);
  // At half opacity the world layer no longer hides the terrain's colours: the mask is back.
  const std::vector<scene::LayerOptions> halfWorld{{globe::testing::blueMarbleLayer(), 0.5f},
                                                   mask[0]};
  EXPECT_GT(renderNadir(pyramid, halfWorld, 0.3, 52.9, 60000, 65).tilesMasked, 0u);
}

// While a tile's own imagery is not loaded (here: never, imagery loads stop at level 3), every
// terrain tile is drawn with its nearest loaded ancestor's texture, scaled to fit: no tile is
// untextured, and the picture is a coarser version of the complete one.
TEST(ImageryScene, TilesDrawTheirNearestLoadedAncestorWhileTheirOwnLoads) {
  const std::vector<scene::LayerOptions> layers{{globe::testing::zionLayer(), 1.0f}};
  const Rendered coarse =
      renderNadir(globe::testing::zionPyramid(), layers, -112.95, 37.27, 6000, 129, 3);
  const Rendered full =
      renderNadir(globe::testing::zionPyramid(), layers, -112.95, 37.27, 6000, 129);
  ASSERT_GT(coarse.tilesDrawn, 0u);
  EXPECT_EQ(coarse.tilesDraped, coarse.tilesDrawn) << "an untextured tile while imagery loads";
  EXPECT_EQ(coarse.frame.imagery.fallbacks, coarse.tilesDrawn);
  EXPECT_LE(coarse.deepestImageryLevel, 3u);
  EXPECT_EQ(full.tilesDraped, full.tilesDrawn);
  EXPECT_EQ(full.frame.imagery.fallbacks, 0u);
  EXPECT_GE(full.deepestImageryLevel, 10u);
  // Same place, same colours on average (the coarse texture is the same scene, averaged).
  const Rgb a = meanAround(coarse.image, 64, 64, 40), b = meanAround(full.image, 64, 64, 40);
  EXPECT_LE(largestChannelDifference(a, b), 25.0);
}

// A long low flight over Zion with a small texture budget: after every frame the textures on the
// GPU stay within the budget, except for what that frame draws and the level-0 roots (the only
// textures never evicted), while the flight as a whole needs several times the budget.
TEST(ImageryScene, TextureMemoryStaysWithinTheBudgetOnALongFlight) {
  auto context = render::OsMesaContext::create(320, 180);
  ASSERT_TRUE(context) << context.error();
  auto renderer = render::TerrainRenderer::create({});
  ASSERT_TRUE(renderer) << renderer.error();
  scene::SceneOptions options;
  options.layers = {{globe::testing::blueMarbleLayer(), 1.0f}, {globe::testing::zionLayer(), 1.0f}};
  options.imageryBudget.textureBytes = 4u << 20;
  auto scene = scene::TerrainScene::open(globe::testing::zionPyramid(), options);
  ASSERT_TRUE(scene) << scene.error();
  RendererGpu gpu(**renderer, options);
  const uint64_t tileBytes = render::mipmappedTextureBytes(256, 256);
  std::set<std::pair<uint32_t, geo::TileId>> everUsed;
  uint64_t peak = 0;
  constexpr int kFrames = 48;
  for (int i = 0; i < kFrames; ++i) {
    const double t = i / (kFrames - 1.0);
    const auto pose =
        camera::CameraPose::fromDegrees(-113.10 + 0.2 * t, 37.15 + 0.3 * t, 3500, 20, -30, 0);
    auto frame = (*scene)->updateUntilComplete(pose, 320, 180, gpu, std::chrono::seconds(60));
    ASSERT_TRUE(frame) << frame.error();
    const render::FrameStats stats = gpu.draw(**scene);
    std::set<std::pair<uint32_t, geo::TileId>> used;
    for (const terrain::TileDrapes& drapes : (*scene)->drapes()) {
      for (uint32_t k = 0; k < drapes.count; ++k) {
        used.insert({drapes.layers[k].layer, drapes.layers[k].imageryTile});
      }
    }
    everUsed.insert(used.begin(), used.end());
    const uint64_t roots = 2 * 2;  // two level-0 tiles per layer at most
    EXPECT_LE(stats.imageryBytesResident, std::max<uint64_t>(options.imageryBudget.textureBytes,
                                                             (used.size() + roots) * tileBytes))
        << "frame " << i;
    EXPECT_EQ(stats.imageryBytesResident, (*renderer)->imageryBytesResident());
    peak = std::max(peak, stats.imageryBytesResident);
  }
  EXPECT_GT(everUsed.size() * tileBytes, 3 * options.imageryBudget.textureBytes)
      << "the flight does not need more than the budget: the test shows nothing";
  EXPECT_GT(peak, 0u);
  EXPECT_LT((*renderer)->imageryBytesResident(), everUsed.size() * tileBytes)
      << "nothing was evicted";
}

// A view centred on a corner of the imagery quadtree (four imagery tiles meet at the centre
// pixel): the brightness step across the centre column and row is no larger than the image's
// own steps around it (the seam score of a single column, as issue 13 defines it).
TEST(ImageryScene, ImageryTileEdgesLeaveNoSeam) {
  const std::vector<scene::LayerOptions> layers{{globe::testing::zionLayer(), 1.0f}};
  // A level-12 corner inside the scene; at 2.5 km up the drawn imagery is level 11 or 12, both
  // of which have an edge through this corner.
  const auto tile = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(-112.97),
                                                                geo::degreesToRadians(37.29), 12);
  ASSERT_TRUE(tile);
  const geo::TileId corner{12, tile->x & ~1u, tile->y & ~1u};  // a level-11 corner too
  const auto rect = geo::GeographicTilingScheme::tileRectangle(corner);
  const Rendered view =
      renderNadir(globe::testing::zionPyramid(), layers, geo::radiansToDegrees(rect.westRadians),
                  geo::radiansToDegrees(rect.northRadians), 2500, 129);
  ASSERT_FALSE(view.image.pixels.empty());
  const formats::ImageRgba& image = view.image;
  auto brightness = [&](int x, int y) {
    const size_t p = (static_cast<size_t>(y) * image.widthPixels + x) * 4;
    return (image.pixels[p] + image.pixels[p + 1] + image.pixels[p + 2]) / 3.0;
  };
  // Mean absolute step between column x and x+1 (or row y and y+1), over the middle half.
  auto columnStep = [&](int x) {
    double s = 0;
    for (int y = 32; y < 96; ++y) s += std::abs(brightness(x + 1, y) - brightness(x, y));
    return s / 64;
  };
  auto rowStep = [&](int y) {
    double s = 0;
    for (int x = 32; x < 96; ++x) s += std::abs(brightness(x, y + 1) - brightness(x, y));
    return s / 64;
  };
  for (auto step : {std::function<double(int)>(columnStep), std::function<double(int)>(rowStep)}) {
    std::vector<double> around;
    for (int k = 64 - 14; k <= 64 + 12; ++k) {
      if (k < 62 || k > 64) around.push_back(step(k));
    }
    std::nth_element(around.begin(), around.begin() + around.size() / 2, around.end());
    const double median = around[around.size() / 2];
    for (int k = 62; k <= 64; ++k) {
      EXPECT_LE(step(k), 2.0 * median + 1.0)
          << "a seam at " << k << " (median step " << median << ")";
    }
  }
}

}  // namespace
}  // namespace globe::app
