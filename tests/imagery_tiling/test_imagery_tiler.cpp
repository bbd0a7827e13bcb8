// globe-tiler imagery against its sources: finest-level pixels read back through GDAL at the
// same place, transparency from nodata and alpha only, stretches, TMS trees, compositing,
// resuming and determinism.
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <map>
#include <thread>

#include "core/crc32.hpp"
#include "formats/image_io.hpp"
#include "imagery_tiling/footprint_fade.hpp"
#include "imagery_tiling/imagery_encoding.hpp"
#include "imagery_tiling/imagery_reader.hpp"
#include "imagery_tiling/imagery_tiler.hpp"
#include "streaming/imagery_store.hpp"
#include "tests/imagery_tiling/imagery_test_support.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::imagery_tiling {
namespace {

namespace fs = std::filesystem;

std::string fixture(const std::string& name) {
  return std::string(GLOBE_SOURCE_DIR) + "/tests/data/imagery/" + name;
}

using testing::layerOf;
using testing::openStore;
using testing::tileLayer;
using testing::tilesOf;

// An independent reading of a source raster: OGR takes a lon/lat to the source CRS, the inverse
// geotransform to a pixel, GDAL reads the 2×2 neighbours and they are blended bilinearly.
class SourceProbe {
 public:
  explicit SourceProbe(const std::string& path) {
    GDALAllRegister();
    dataset_ = GDALOpen(path.c_str(), GA_ReadOnly);
    EXPECT_NE(dataset_, nullptr) << path;
    GDALGetGeoTransform(dataset_, geo_);
    OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(wgs84, 4326);
    OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReferenceH source = OSRClone(GDALGetSpatialRef(dataset_));
    OSRSetAxisMappingStrategy(source, OAMS_TRADITIONAL_GIS_ORDER);
    transform_ = OCTNewCoordinateTransformation(wgs84, source);
    OSRDestroySpatialReference(wgs84);
    OSRDestroySpatialReference(source);
    // Which pixels hold data (any of the first three bands not 0), for the collar's distance.
    const int columns = GDALGetRasterXSize(dataset_), rows = GDALGetRasterYSize(dataset_);
    valid_.assign(size_t(columns) * rows, 0);
    std::vector<uint8_t> band(valid_.size());
    for (int b = 1; b <= std::min(3, GDALGetRasterCount(dataset_)); ++b) {
      EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(dataset_, b), GF_Read, 0, 0, columns, rows,
                             band.data(), columns, rows, GDT_Byte, 0, 0),
                CE_None);
      for (size_t i = 0; i < band.size(); ++i) valid_[i] = valid_[i] != 0 || band[i] != 0 ? 1 : 0;
    }
  }
  ~SourceProbe() {
    OCTDestroyCoordinateTransformation(transform_);
    GDALClose(dataset_);
  }

  struct Sample {
    double rgb[3] = {0, 0, 0};
    int validNeighbours = 0;            // of the 4 (a neighbour is valid when any band is not 0)
    bool inside = false;                // the point lies inside the raster's area
    double edgeDistancePixels = 0;      // to the raster's nearest edge, in its pixels
    double collarDistancePixels = 1e9;  // to the nearest no-data pixel's centre (within 8)
  };

  Sample at(double lon, double lat, const std::vector<int>& bands = {1, 2, 3}) const {
    double x = lon, y = lat;
    Sample s;
    if (!OCTTransform(transform_, 1, &x, &y, nullptr)) return s;
    const double column = (x - geo_[0]) / geo_[1], row = (y - geo_[3]) / geo_[5];
    const int columns = GDALGetRasterXSize(dataset_), rows = GDALGetRasterYSize(dataset_);
    s.inside = column >= 0 && column < columns && row >= 0 && row < rows;
    s.edgeDistancePixels = std::min(std::min(column, columns - column), std::min(row, rows - row));
    if (!s.inside) return s;
    for (int cy = static_cast<int>(row) - 8; cy <= static_cast<int>(row) + 8; ++cy) {
      for (int cx = static_cast<int>(column) - 8; cx <= static_cast<int>(column) + 8; ++cx) {
        if (cx < 0 || cy < 0 || cx >= columns || cy >= rows) continue;
        if (valid_[size_t(cy) * columns + cx] != 0) continue;
        s.collarDistancePixels =
            std::min(s.collarDistancePixels, std::hypot(cx + 0.5 - column, cy + 0.5 - row));
      }
    }
    const double fx = column - 0.5, fy = row - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const double tx = fx - x0, ty = fy - y0;
    double weightSum = 0;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const int cx = std::clamp(x0 + dx, 0, columns - 1), cy = std::clamp(y0 + dy, 0, rows - 1);
        uint8_t value[3] = {0, 0, 0};
        for (size_t b = 0; b < 3; ++b) {
          EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(dataset_, bands[b]), GF_Read, cx, cy, 1, 1,
                                 &value[b], 1, 1, GDT_Byte, 0, 0),
                    CE_None);
        }
        if (value[0] == 0 && value[1] == 0 && value[2] == 0) continue;
        ++s.validNeighbours;
        const double w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty);
        weightSum += w;
        for (int b = 0; b < 3; ++b) s.rgb[b] += w * value[b];
      }
    }
    if (weightSum > 0) {
      for (double& v : s.rgb) v /= weightSum;
    }
    return s;
  }

 private:
  GDALDatasetH dataset_ = nullptr;
  std::vector<uint8_t> valid_;
  double geo_[6] = {};
  OGRCoordinateTransformationH transform_ = nullptr;
};

struct PixelCentre {
  double lon, lat;
};
// Where a pixel of a layer tile samples the ground: layers the tiler makes from rasters sample at
// the tiles' edges (formats::ImageryPixelGrid::Edges), 255 intervals across.
PixelCentre centreOf(const geo::TileId& tile, int row, int column) {
  const TileFrameDegrees f = tileFrameDegrees(tile);
  return {f.west + column * f.size / 255, f.north - row * f.size / 255};
}

bool fullyOpaqueImage(const formats::ImageRgba& image) {
  for (size_t i = 3; i < image.pixels.size(); i += 4) {
    if (image.pixels[i] != 255) return false;
  }
  return true;
}

const uint8_t* pixel(const formats::ImageRgba& image, int row, int column) {
  return &image.pixels[(size_t(row) * 256 + column) * 4];
}

TEST(ImageryTiler, ProjectedInputMatchesTheSourceThroughGdal) {
  const std::string input = fixture("rgb_byte_utm18_crop.tif");
  const fs::path layer = layerOf({input}, "utm");
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  const uint32_t finest = store->manifest().maxLevel();
  // 300 m pixels at 24.6° N: 0.00297° of longitude, 0.0027° of latitude; level 8's texel is
  // 0.00275°, level 7's 0.0055°.
  EXPECT_EQ(finest, 8u);
  ASSERT_EQ(store->manifest().sources.size(), 1u);
  EXPECT_EQ(store->manifest().sources[0].crs, "EPSG:32618");
  const SourceProbe probe(input);
  double errorSum = 0, worst = 0;
  int compared = 0, transparentNoData = 0, outsideTransparent = 0, faded = 0;
  for (const auto& [tile, image] : tilesOf(*store, finest)) {
    for (int row = 3; row < 256; row += 11) {
      for (int column = 5; column < 256; column += 11) {
        const PixelCentre c = centreOf(tile, row, column);
        const auto s = probe.at(c.lon, c.lat);
        const uint8_t* p = pixel(image, row, column);
        if (!s.inside) {
          EXPECT_EQ(p[3], 0) << "outside the raster";
          outsideTransparent += p[3] == 0;
          continue;
        }
        if (s.validNeighbours == 0) {
          EXPECT_EQ(p[3], 0) << "no data must be transparent";
          transparentNoData += p[3] == 0;
          continue;
        }
        if (s.validNeighbours < 4) continue;  // the edge of the scene: partly transparent
        // The collar fades over 4 source pixels (FootprintFade.AScenesNoDataCollarFades); the
        // chamfer distance the tiler uses is within 8 % of this one.
        if (s.collarDistancePixels < 1.1 * kFootprintFadePixels + 1) continue;
        if (s.edgeDistancePixels < kFootprintFadePixels) {
          // The footprint's edge fades over 4 source pixels (imagery_tiling/footprint_fade.hpp).
          const double t = s.edgeDistancePixels / kFootprintFadePixels;
          EXPECT_NEAR(p[3], 255.0 * t * t * (3 - 2 * t), 2.0);
          ++faded;
          continue;
        }
        EXPECT_EQ(p[3], 255);
        for (int b = 0; b < 3; ++b) {
          const double error = std::abs(p[b] - s.rgb[b]);
          errorSum += error;
          worst = std::max(worst, error);
        }
        ++compared;
      }
    }
  }
  ASSERT_GT(compared, 500);
  EXPECT_GT(transparentNoData, 50);
  EXPECT_GT(outsideTransparent, 50);
  EXPECT_GT(faded, 10);
  EXPECT_LT(errorSum / (3 * compared), 3.0);  // JPEG at quality 85
  EXPECT_LT(worst, 48.0);
}

TEST(ImageryTiler, FourthBandThatIsNotAlphaStaysOpaque) {
  const std::string input = fixture("naip_rgbn_utm14_crop.tif");
  const fs::path layer = layerOf({input}, "naip");
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  EXPECT_NE(store->manifest().sources[0].bands.find("bands 1,2,3 as RGB"), std::string::npos)
      << store->manifest().sources[0].bands;
  const SourceProbe probe(input);
  int opaque = 0, partial = 0, compared = 0;
  double errorSum = 0;
  for (const auto& [tile, image] : tilesOf(*store, store->manifest().maxLevel())) {
    for (int row = 0; row < 256; row += 3) {
      for (int column = 0; column < 256; column += 3) {
        const uint8_t* p = pixel(image, row, column);
        const PixelCentre c = centreOf(tile, row, column);
        const auto s = probe.at(c.lon, c.lat);
        if (s.edgeDistancePixels < kFootprintFadePixels) continue;  // the footprint's fade
        opaque += p[3] == 255;
        partial += p[3] > 0 && p[3] < 255;
        if (p[3] == 255 && s.validNeighbours == 4) {
          for (int b = 0; b < 3; ++b) errorSum += std::abs(p[b] - s.rgb[b]);
          ++compared;
        }
      }
    }
  }
  // Were the near-infrared band read as alpha, most pixels would be partly transparent.
  EXPECT_GT(opaque, 1000);
  EXPECT_LT(partial * 20, opaque);
  ASSERT_GT(compared, 500);
  EXPECT_LT(errorSum / (3 * compared), 6.0);
}

TEST(ImageryTiler, ImageWithoutGeoreferenceNeedsBounds) {
  const std::string input = fixture("no_georeference.png");
  const fs::path out = globe::testing::freshTempDir("imagery-nogeo") / "layer";
  auto refused = tileLayer({input}, out);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find(input), std::string::npos) << refused.error();
  EXPECT_NE(refused.error().find("no georeference"), std::string::npos) << refused.error();
  EXPECT_NE(refused.error().find("--bounds"), std::string::npos) << refused.error();
  EXPECT_FALSE(fs::exists(out / "layer.json"));

  ImageryTilerOptions options;
  options.input.bounds = formats::BoundsDegrees{10, 20, 16, 24.5};  // 64×48 px: 0.09375° each
  auto tiled = tileLayer({input}, out, options);
  ASSERT_TRUE(tiled) << tiled.error();
  auto store = openStore(out);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->manifest().maxLevel(), imageryFinestLevel(0.09375));
  EXPECT_EQ(store->manifest().sources[0].bounds, (formats::BoundsDegrees{10, 20, 16, 24.5}));
}

TEST(ImageryTiler, SixteenBitIsStretchedByAStatedRule) {
  // By default each band's 2-98 % percentiles (was: refused without --scale).
  const std::string input = fixture("zion_landsat_b4_uint16_crop.tif");
  auto defaultStore = openStore(layerOf({input}, "uint16-default"));
  ASSERT_TRUE(defaultStore);
  EXPECT_EQ(defaultStore->manifest().sources[0].stretch.rfind("2-98% per band: ", 0), 0u)
      << defaultStore->manifest().sources[0].stretch;

  ImageryTilerOptions linear;
  linear.input.scale = ImageryStretch{5678, 21574};  // the crop's range
  const fs::path layer = layerOf({input}, "uint16-linear", linear);
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->manifest().sources[0].bands.rfind("grey", 0), 0u);
  EXPECT_EQ(store->manifest().sources[0].stretch, "linear 5678..21574 to 0..255");
  // Grey: the three channels agree; the stretch spreads the values over most of 0..255.
  int darkest = 255, brightest = 0;
  for (const auto& [tile, image] : tilesOf(*store, store->manifest().maxLevel())) {
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      if (image.pixels[i + 3] != 255) continue;
      EXPECT_NEAR(image.pixels[i], image.pixels[i + 1], 2);
      darkest = std::min<int>(darkest, image.pixels[i]);
      brightest = std::max<int>(brightest, image.pixels[i]);
    }
  }
  EXPECT_LT(darkest, 40);
  EXPECT_GT(brightest, 150);

  ImageryTilerOptions automatic;
  automatic.input.scaleAuto = true;
  const fs::path autoLayer = layerOf({input}, "uint16-auto", automatic);
  auto autoStore = openStore(autoLayer);
  ASSERT_TRUE(autoStore);
  EXPECT_EQ(autoStore->manifest().sources[0].stretch.rfind("2-98% per band: ", 0), 0u)
      << autoStore->manifest().sources[0].stretch;
}

TEST(ImageryTiler, TmsTreeIsRepackedByteForByte) {
  const std::string tms = fixture("NaturalEarthII-tms-l0-1");
  const fs::path layer = layerOf({tms}, "tms");
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  ASSERT_EQ(store->manifest().maxLevel(), 1u);
  EXPECT_EQ(store->manifest().tileCount(), 2u + 8u);
  for (uint32_t level = 0; level <= 1; ++level) {
    for (uint32_t x = 0; x < (2u << level); ++x) {
      for (uint32_t y = 0; y < (1u << level); ++y) {
        const uint32_t tmsY = (1u << level) - 1 - y;  // TMS rows count from the south
        const fs::path file = fs::path(tms) / std::to_string(level) / std::to_string(x) /
                              (std::to_string(tmsY) + ".jpg");
        auto expected = transport::readWholeFile(file, 1 << 20);
        ASSERT_TRUE(expected) << expected.error();
        auto bytes = store->loadEncoded({level, x, y});
        ASSERT_TRUE(bytes && bytes->has_value()) << level << "/" << x << "/" << y;
        EXPECT_EQ(**bytes, *expected) << level << "/" << x << "/" << y;
      }
    }
  }
}

// Tiles sample the ground at their edges (formats::ImageryPixelGrid::Edges): two neighbours'
// facing edge columns are the same samples, at every level (the coarser ones filtered so that
// they stay shared) and across ±180° of a whole-globe image (the mean of its first and last
// columns on both sides), so the viewer's bilinear filter runs on from one tile into the next.
// JPEG would round them differently in each tile; the exact ring rides along in the JPEG
// (formats/tile_edges.hpp), so at the default quality they are identical, byte for byte, while
// the columns next to them differ as neighbouring columns do.
TEST(ImageryTiler, NeighboursShareTheirEdgeSamplesAtEveryLevel) {
  ImageryTilerOptions options;
  options.input.bounds = formats::BoundsDegrees{-180, -90, 180, 90};
  // The bundled 5400-wide Blue Marble: levels 0-4, 0-3 filtered from the level below.
  const fs::path layer = layerOf(
      {std::string(GLOBE_SOURCE_DIR) + "/data/imagery/world.topo.bathy.200412.3x5400x2700.jpg"},
      "edges", options);
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  ASSERT_EQ(store->manifest().maxLevel(), 4u);
  EXPECT_EQ(store->manifest().pixelGrid, formats::ImageryPixelGrid::Edges);
  for (uint32_t level = 0; level <= store->manifest().maxLevel(); ++level) {
    const auto tiles = tilesOf(*store, level);
    size_t differing = 0;
    double inside = 0;
    int pairs = 0;
    for (const auto& [tile, image] : tiles) {
      const uint32_t columns = 2u << level;
      const auto east = tiles.find({level, (tile.x + 1) % columns, tile.y});
      ASSERT_NE(east, tiles.end());
      const auto luma = [](const uint8_t* p) {
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      };
      for (int row = 0; row < 256; ++row) {
        const uint8_t* a = pixel(image, row, 255);
        const uint8_t* b = pixel(east->second, row, 0);
        differing += a[0] != b[0] || a[1] != b[1] || a[2] != b[2] ? 1 : 0;
        inside += std::abs(luma(pixel(image, row, 254)) - luma(pixel(east->second, row, 1)));
      }
      ++pairs;
    }
    ASSERT_GT(pairs, 0);
    EXPECT_EQ(differing, 0u) << "level " << level;
    EXPECT_GT(inside / (256.0 * pairs), 1.0) << "level " << level;
  }
  // A layer re-packing a TMS tree keeps its pixel-is-area tiles, as a version 1 layer.
  auto tms = openStore(layerOf({fixture("NaturalEarthII-tms-l0-1")}, "tms-area"));
  ASSERT_TRUE(tms);
  EXPECT_EQ(tms->manifest().pixelGrid, formats::ImageryPixelGrid::Area);
}

TEST(ImageryTiler, FinestInputWinsAndItsNoDataShowsTheCoarser) {
  const std::string world = fixture("bmng_world_512x256.jpg");
  const std::string scene = fixture("rgb_byte_utm18_crop.tif");
  ImageryTilerOptions options;
  options.input.bounds = formats::BoundsDegrees{-180, -90, 180, 90};  // the world JPEG has none
  const fs::path layer = layerOf({world, scene}, "two", options);
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  ASSERT_EQ(store->manifest().maxLevel(), 8u);
  EXPECT_EQ(store->manifest().sources[0].finestLevel, 0u);  // 0.703° pixels
  EXPECT_EQ(store->manifest().sources[1].finestLevel, 8u);
  const SourceProbe sceneProbe(scene);
  // The world image, read the same way in its own (assigned) frame: 0.703125° pixels.
  GDALDatasetH worldDataset = GDALOpen(world.c_str(), GA_ReadOnly);
  ASSERT_NE(worldDataset, nullptr);
  auto worldAt = [&](double lon, double lat, int band) {
    const double column = (lon + 180) / 0.703125, row = (90 - lat) / 0.703125;
    const int x0 = std::clamp(static_cast<int>(std::floor(column - 0.5)), 0, 511);
    const int y0 = std::clamp(static_cast<int>(std::floor(row - 0.5)), 0, 255);
    const double tx = column - 0.5 - x0, ty = row - 0.5 - y0;
    double sum = 0;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        uint8_t v = 0;
        EXPECT_EQ(
            GDALRasterIO(GDALGetRasterBand(worldDataset, band), GF_Read, std::min(x0 + dx, 511),
                         std::min(y0 + dy, 255), 1, 1, &v, 1, 1, GDT_Byte, 0, 0),
            CE_None);
        sum += (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * v;
      }
    }
    return sum;
  };
  int fromScene = 0, fromWorld = 0;
  double sceneError = 0, worldError = 0;
  for (const auto& [tile, image] : tilesOf(*store, 8)) {
    for (int row = 2; row < 256; row += 9) {
      for (int column = 2; column < 256; column += 9) {
        const uint8_t* p = pixel(image, row, column);
        EXPECT_EQ(p[3], 255) << "the world image is under every pixel";
        const PixelCentre c = centreOf(tile, row, column);
        const auto s = sceneProbe.at(c.lon, c.lat);
        if (s.inside && s.validNeighbours == 4) {
          for (int b = 0; b < 3; ++b) sceneError += std::abs(p[b] - s.rgb[b]);
          ++fromScene;
        } else if (!s.inside || s.validNeighbours == 0) {
          for (int b = 0; b < 3; ++b) worldError += std::abs(p[b] - worldAt(c.lon, c.lat, b + 1));
          ++fromWorld;
        }
      }
    }
  }
  GDALClose(worldDataset);
  ASSERT_GT(fromScene, 300);
  ASSERT_GT(fromWorld, 300);
  // Every tile here is JPEG at quality 85 with 4:2:0 chroma (0.6 at quality 100): the speckled
  // scene loses more than the smooth world.
  EXPECT_LT(sceneError / (3 * fromScene), 5.0);
  EXPECT_LT(worldError / (3 * fromWorld), 3.0);
  // Level 0 over the scene: both inputs, averaged from below; elsewhere the world alone.
  auto level0 = tilesOf(*store, 0);
  EXPECT_EQ(level0.size(), 2u);
}

TEST(ImageryTiler, FootprintAcrossTheAntimeridianWraps) {
  // The world image placed on 0..360°: the western hemisphere comes from its right half.
  GDALAllRegister();
  const fs::path vrt = globe::testing::freshTempDir("imagery-wrap") / "world-0-360.vrt";
  const char* translateArguments[] = {"-of", "VRT", "-a_srs", "EPSG:4326", "-a_ullr",
                                      "0",   "90",  "360",    "-90",       nullptr};
  GDALTranslateOptions* translateOptions =
      GDALTranslateOptionsNew(const_cast<char**>(translateArguments), nullptr);
  GDALDatasetH source = GDALOpen(fixture("bmng_world_512x256.jpg").c_str(), GA_ReadOnly);
  ASSERT_NE(source, nullptr);
  GDALClose(GDALTranslate(vrt.c_str(), source, translateOptions, nullptr));
  GDALTranslateOptionsFree(translateOptions);
  ImageryTilerOptions options;
  options.input.maxLevel = 1;
  const fs::path layer = layerOf({vrt.string()}, "wrap-layer", options);
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->manifest().tileCount(), 2u + 8u);
  double errorSum = 0;
  int compared = 0;
  for (const auto& [tile, image] : tilesOf(*store, 1)) {
    EXPECT_TRUE(fullyOpaqueImage(image)) << tile.x << "/" << tile.y;
    for (int row = 8; row < 256; row += 16) {
      for (int column = 8; column < 256; column += 16) {
        const PixelCentre c = centreOf(tile, row, column);
        const double sourceLon = c.lon < 0 ? c.lon + 360 : c.lon;
        // Level 1's texel (0.35°) is half the source pixel: compare with the nearest pixel's
        // 2×2 neighbourhood mean, loosely.
        const int x = std::clamp(static_cast<int>(sourceLon / 0.703125), 0, 511);
        const int y = std::clamp(static_cast<int>((90 - c.lat) / 0.703125), 0, 255);
        uint8_t value = 0;
        ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(source, 1), GF_Read, x, y, 1, 1, &value, 1, 1,
                               GDT_Byte, 0, 0),
                  CE_None);
        errorSum += std::abs(pixel(image, row, column)[0] - value);
        ++compared;
      }
    }
  }
  GDALClose(source);
  ASSERT_EQ(compared, 8 * 256);
  EXPECT_LT(errorSum / compared, 12.0);
}

// A 64×64 GeoTIFF over 10..11° E, 10..11° N made here: a palette (left half index 0 = red,
// right half index 1 = blue), or RGBA whose alpha band hides the northern half.
std::string syntheticRaster(const std::string& name, bool palette) {
  GDALAllRegister();
  const fs::path path = globe::testing::freshTempDir("imagery-synthetic-" + name) / (name + ".tif");
  const int bands = palette ? 1 : 4;
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 64, 64, bands, GDT_Byte, nullptr);
  double geo[6] = {10, 1.0 / 64, 0, 11, 0, -1.0 / 64};
  GDALSetGeoTransform(ds, geo);
  GDALSetProjection(ds, SRS_WKT_WGS84_LAT_LONG);
  std::vector<uint8_t> plane(64 * 64);
  if (palette) {
    GDALColorTableH table = GDALCreateColorTable(GPI_RGB);
    const GDALColorEntry red{255, 0, 0, 255}, blue{0, 0, 255, 255};
    GDALSetColorEntry(table, 0, &red);
    GDALSetColorEntry(table, 1, &blue);
    GDALSetRasterColorTable(GDALGetRasterBand(ds, 1), table);
    GDALDestroyColorTable(table);
    for (int i = 0; i < 64 * 64; ++i) plane[size_t(i)] = i % 64 < 32 ? 0 : 1;
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 64, 64, plane.data(), 64, 64,
                           GDT_Byte, 0, 0),
              CE_None);
  } else {
    const GDALColorInterp interps[4] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand, GCI_AlphaBand};
    for (int b = 0; b < 4; ++b) {
      for (int i = 0; i < 64 * 64; ++i) {
        plane[size_t(i)] = b == 3 ? (i / 64 < 32 ? 0 : 255) : static_cast<uint8_t>(60 * (b + 1));
      }
      GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
      GDALSetRasterColorInterpretation(band, interps[b]);
      EXPECT_EQ(GDALRasterIO(band, GF_Write, 0, 0, 64, 64, plane.data(), 64, 64, GDT_Byte, 0, 0),
                CE_None);
    }
  }
  GDALClose(ds);
  return path.string();
}

// The colour and alpha of the layer's finest pixel at a point.
std::array<int, 4> colourAt(streaming::ImageryStore& store, double lon, double lat) {
  const uint32_t level = store.manifest().maxLevel();
  const double size = std::ldexp(180.0, -static_cast<int>(level));
  const geo::TileId tile{level, static_cast<uint32_t>((lon + 180) / size),
                         static_cast<uint32_t>((90 - lat) / size)};
  const TileFrameDegrees f = tileFrameDegrees(tile);
  auto bytes = store.loadEncoded(tile);
  if (!bytes || !*bytes) return {-1, -1, -1, -1};
  auto image = formats::decodeImageRgba(**bytes, "tile");
  if (!image) return {-1, -1, -1, -1};
  const int column = static_cast<int>(std::lround((lon - f.west) / f.size * 255));
  const int row = static_cast<int>(std::lround((f.north - lat) / f.size * 255));
  const uint8_t* p = pixel(*image, row, column);
  return {p[0], p[1], p[2], p[3]};
}

TEST(ImageryTiler, PaletteIsExpanded) {
  const fs::path layer = layerOf({syntheticRaster("palette", true)}, "palette");
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->manifest().sources[0].bands, "palette");
  const auto left = colourAt(*store, 10.2, 10.5), right = colourAt(*store, 10.8, 10.5);
  const std::array<int, 4> red{255, 0, 0, 255}, blue{0, 0, 255, 255};
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(left[c], red[c], 3) << c;  // a flat JPEG area
    EXPECT_NEAR(right[c], blue[c], 3) << c;
  }
}

TEST(ImageryTiler, AlphaBandIsTransparency) {
  const fs::path layer = layerOf({syntheticRaster("rgba", false)}, "rgba");
  auto store = openStore(layer);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->manifest().sources[0].bands, "RGB + alpha (band 4)");
  EXPECT_EQ(colourAt(*store, 10.5, 10.8)[3], 0);  // northern half: alpha 0
  const auto south = colourAt(*store, 10.5, 10.2);
  EXPECT_EQ(south[3], 255);
  EXPECT_NEAR(south[0], 60, 1);
  EXPECT_NEAR(south[1], 120, 1);
  EXPECT_NEAR(south[2], 180, 1);
}

TEST(ImageryEncoding, FastEncodersDecodeBackThroughStb) {
  formats::ImageRgba image{256, 256, std::vector<uint8_t>(256 * 256 * 4)};
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    const size_t pixelIndex = i / 4;
    image.pixels[i] = static_cast<uint8_t>(pixelIndex % 256);
    image.pixels[i + 1] = static_cast<uint8_t>(pixelIndex / 256);
    image.pixels[i + 2] = static_cast<uint8_t>((pixelIndex % 256 + pixelIndex / 256) / 2);
    image.pixels[i + 3] = pixelIndex % 97 == 0 ? 0 : 255;
  }
  auto png = encodePngFast(image);
  ASSERT_TRUE(png) << png.error();
  auto back = formats::decodeImageRgba(*png, "png");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->pixels, image.pixels);  // lossless, alpha included

  for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
  auto jpeg = encodeJpegFast(image, 95);
  ASSERT_TRUE(jpeg) << jpeg.error();
  auto decoded = formats::decodeImageRgba(*jpeg, "jpeg");
  ASSERT_TRUE(decoded) << decoded.error();
  double error = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    error += std::abs(int(decoded->pixels[i]) - int(image.pixels[i]));
  }
  EXPECT_LT(error / double(image.pixels.size()), 4.0);
  EXPECT_FALSE(encodeJpegFast(image, 101));
}

TEST(ImageryTiler, SameBytesWithOneAndTwoThreads) {
  const std::vector<std::string> inputs = {fixture("rgb_byte_utm18_crop.tif"),
                                           fixture("naip_rgbn_utm14_crop.tif")};
  ImageryTilerOptions one;
  one.threads = 1;
  one.packTilesPerSide = 4;  // several packs per level
  ImageryTilerOptions two = one;
  two.threads = 2;
  const auto a = globe::testing::checksums(layerOf(inputs, "j1", one));
  const auto b = globe::testing::checksums(layerOf(inputs, "j2", two));
  EXPECT_GT(a.size(), 10u);
  EXPECT_EQ(a, b);
}

TEST(ImageryTiler, ResumesAfterLostPacksWithIdenticalBytes) {
  const std::vector<std::string> inputs = {fixture("rgb_byte_utm18_crop.tif")};
  ImageryTilerOptions options;
  options.packTilesPerSide = 4;
  const fs::path layer = layerOf(inputs, "resume", options);
  const auto complete = globe::testing::checksums(layer);
  // What a killed run leaves: no manifest, a temporary, packs of some levels missing.
  fs::remove(layer / "layer.json");
  fs::remove_all(layer / "L8");
  fs::remove_all(layer / "L3");
  auto bytes = transport::readWholeFile(layer / "L5" / "4_2.pack", 1 << 24);
  ASSERT_TRUE(bytes) << bytes.error();
  ASSERT_TRUE(transport::writeFileAtomically(layer / "L5" / "4_2.pack.tmp-1-0",
                                             std::span(*bytes).first(bytes->size() / 2)));
  auto resumed = tileLayer(inputs, layer, options);
  ASSERT_TRUE(resumed) << resumed.error();
  EXPECT_GT(resumed->packsReused, 0u);
  EXPECT_GT(resumed->packsBuilt, 0u);
  EXPECT_EQ(globe::testing::checksums(layer), complete);
  // Other options in the same directory are refused.
  options.jpegQuality = 50;
  auto refused = tileLayer(inputs, layer, options);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("other inputs or options"), std::string::npos);
}

TEST(ImageryTiler, ResumesAfterAKillWithIdenticalBytes) {
  const std::vector<std::string> arguments = {"imagery",
                                              "-q",
                                              "-j2",
                                              "--pack-tiles",
                                              "2",
                                              "--bounds",
                                              "-180,-90,180,90",
                                              "--max-level",
                                              "4",
                                              fixture("bmng_world_512x256.jpg")};
  auto run = [&](const fs::path& out, int killAfterMilliseconds) {
    const pid_t child = ::fork();
    if (child == 0) {
      std::vector<std::string> args = {GLOBE_TILER_EXE};
      args.insert(args.end(), arguments.begin(), arguments.end());
      args.push_back("-o");
      args.push_back(out.string());
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::freopen("/dev/null", "w", stdout);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    if (killAfterMilliseconds > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(killAfterMilliseconds));
      ::kill(child, SIGKILL);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return status;
  };
  const fs::path reference = globe::testing::freshTempDir("imagery-kill-ref") / "layer";
  ASSERT_EQ(run(reference, 0), 0);
  const fs::path killed = globe::testing::freshTempDir("imagery-kill") / "layer";
  run(killed, 150);
  EXPECT_EQ(run(killed, 0), 0);
  EXPECT_EQ(globe::testing::checksums(killed), globe::testing::checksums(reference));
}

}  // namespace
}  // namespace globe::imagery_tiling
